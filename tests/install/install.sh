#!/bin/sh
# The README's install steps, run by the suite (run.cmake) in a scratch directory where kane/ is this
# repository, app/ a copy of tests/install/consumer and HOME the scratch directory; CXX and
# CMAKE_GENERATOR come from the environment.
set -e
cmake -S kane -B kane-build -DKANE_BUILD_TESTS=OFF -DKANE_BUILD_EXAMPLES=OFF -DCMAKE_INSTALL_PREFIX=$HOME/.local
cmake --install kane-build
cmake -S app -B app-build -DCMAKE_PREFIX_PATH=$HOME/.local
cmake --build app-build
./app-build/consumer
