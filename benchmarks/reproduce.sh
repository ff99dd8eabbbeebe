#!/usr/bin/env bash
# The performance tables, regenerated on this machine: what the benchmarks need, then all of them.
set -euo pipefail
cd "$(dirname "$0")/.."
apt-get install -y libbenchmark-dev liborocos-kdl-dev && benchmarks/table.sh
