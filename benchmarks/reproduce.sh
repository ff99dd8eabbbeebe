#!/usr/bin/env bash
# The performance page, regenerated on this machine: what the benchmarks need, then every table.
set -euo pipefail
cd "$(dirname "$0")/.."
apt-get install -y libbenchmark-dev liborocos-kdl-dev && benchmarks/performance_page.sh
