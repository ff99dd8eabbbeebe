#!/usr/bin/env bash
# Compile time and peak memory of kane's translation units (the 6- and 20-joint
# chains, the rolling disc, the 6-revolute arm) beside one that only includes
# Eigen, at -O2 and at -O0 -g; compared with the committed
# baseline (benchmarks/compile_baseline.txt). Exit 1 if a time or memory
# exceeds its baseline by more than 30%. Usage: benchmarks/compile_cost.sh [--update]
# benchmarks/compile_cost.sh chain_dynamics [n ...]: the n-link chain's dynamics
# instead, one unit per n (chain_compile_cost.sh).
set -euo pipefail
if [ "${1:-}" = chain_dynamics ]; then
  shift
  exec "$(dirname "$0")/chain_compile_cost.sh" "$@"
fi
here=$(cd "$(dirname "$0")" && pwd)
top=$(dirname "$here")
cxx=${CXX:-g++}
flags=(-std=c++20 -I"$top/include" -isystem /usr/include/eigen3 -c -o /dev/null)
baseline="$here/compile_baseline.txt"
results=$(mktemp)

measure() {  # name, opt, source, extra flags...
  local name=$1 opt=$2 src=$3
  shift 3
  local out
  out=$( { /usr/bin/time -f "%e %M" "$cxx" "${flags[@]}" $opt "$@" "$src" >/dev/null; } 2>&1 | tail -1)
  echo "$name|$opt $out" >>"$results"
}

for opt in "-O2" "-O0 -g"; do
  measure eigen_only "$opt" "$here/eigen_only.cpp"
  measure chain6 "$opt" "$here/chain_kane.cpp" -DKANE_CHAIN_ONLY=6
  measure chain20 "$opt" "$here/chain_kane.cpp" -DKANE_CHAIN_ONLY=20
  measure disc "$opt" "$here/disc_kane.cpp"
  measure arm6 "$opt" "$here/arm6_kane.cpp"
done

printf '%-11s %-7s %9s %9s %12s %12s\n' unit flags seconds MB over_eigen baseline_s
status=0
while IFS='|' read -r name rest; do
  opt=${rest% * *}
  read -r secs kb <<<"${rest#"$opt" }"
  ref=$(grep "^eigen_only|$opt " "$results" | awk '{print $(NF-1)}')
  over=$(awk -v a="$secs" -v b="$ref" 'BEGIN{printf "%+.2f", a-b}')
  base=$(grep -F "$name|$opt " "$baseline" 2>/dev/null | awk '{print $(NF-1)}' || true)
  base_kb=$(grep -F "$name|$opt " "$baseline" 2>/dev/null | awk '{print $NF}' || true)
  printf '%-11s %-7s %9s %9d %12s %12s\n' "$name" "$opt" "$secs" $((kb / 1024)) "$over" "${base:--}"
  if [ -n "$base" ] && awk -v a="$secs" -v b="$base" -v m="$kb" -v bm="$base_kb" 'BEGIN{exit !(a > 1.3*b || m > 1.3*bm)}'; then
    echo "  regression: $name $opt beyond 1.3x of its baseline" && status=1
  fi
done <"$results"

if [ "${1:-}" = "--update" ]; then
  { echo "# name|flags seconds peak_KB  ($($cxx --version | head -1), $(nproc) cores)"; cat "$results"; } >"$baseline"
  echo "baseline written to $baseline"
fi
rm -f "$results"
exit $status
