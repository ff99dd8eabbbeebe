#!/bin/sh
# Doxygen input filter: kane's plain // comments before an entity read as Doxygen's ///.
exec sed -e 's,^\([[:space:]]*\)//,\1///,' "$1"
