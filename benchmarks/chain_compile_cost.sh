#!/usr/bin/env bash
# Compile cost of kane's n-link chain dynamics (chain_dynamics_kane.cpp), one
# translation unit per n, g++ -O2: wall and CPU user seconds, peak MB, and the
# growth exponent p (cost ~ n^p) between the first and the last n.
# Usage: benchmarks/chain_compile_cost.sh [n ...]   (default 6 12 24 48;
# also benchmarks/compile_cost.sh chain_dynamics [n ...]). CXX picks the compiler,
# KANE_INCLUDE kane's include folder (default: this tree's).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
top=$(dirname "$here")
cxx=${CXX:-g++}
include=${KANE_INCLUDE:-$top/include}
ns=("$@")
[ ${#ns[@]} -gt 0 ] || ns=(6 12 24 48)
timing=$(mktemp)
trap 'rm -f "$timing"' EXIT

printf '%4s %9s %9s %9s\n' n wall_s user_s peak_MB
rows=()
for n in "${ns[@]}"; do
  /usr/bin/time -o "$timing" -f "%e %U %M" "$cxx" -O2 -std=c++20 -I"$include" -isystem /usr/include/eigen3 \
    -DKANE_CHAIN_N="$n" -c -o /dev/null "$here/chain_dynamics_kane.cpp"
  read -r wall user kb < <(tail -1 "$timing")
  printf '%4s %9s %9s %9d\n' "$n" "$wall" "$user" $((kb / 1024))
  rows+=("$n $wall $user $kb")
done
if [ ${#rows[@]} -ge 2 ]; then
  awk -v a="${rows[0]}" -v b="${rows[${#rows[@]} - 1]}" 'BEGIN {
    split(a, x, " "); split(b, y, " "); r = log(y[1] / x[1])
    printf "growth n^p from n = %d to %d: wall p = %.2f, user p = %.2f, peak p = %.2f\n",
      x[1], y[1], log(y[2] / x[2]) / r, log(y[3] / x[3]) / r, log(y[4] / x[4]) / r }'
fi
