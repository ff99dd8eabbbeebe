#!/usr/bin/env bash
# The README's performance table: builds the bench presets (-O2, -O3,
# -O3 -march=native), runs every benchmark binary (5 repetitions) and prints
# the median CPU ns of the hand-written pass and of kane, and their ratio;
# then the peer (Orocos KDL) at -O3. Needs libbenchmark-dev liborocos-kdl-dev.
set -euo pipefail
cd "$(dirname "$0")/.."
presets=(bench-o2 bench bench-native)
csv=$(mktemp)
for p in "${presets[@]}"; do
  cmake --preset "$p" >/dev/null
  cmake --build --preset "$p" >/dev/null
  for b in arm6 chain disc; do
    "./build/$p/benchmarks/bench_$b" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
      --benchmark_format=csv 2>/dev/null | grep '_median"' | sed "s/^/$p,/"
  done
done >"$csv"
awk -F, '
  { split($2, n, "/"); impl = n[length(n)]; sub(/_median"$/, "", impl)
    prob = $2; sub(/\/[a-z]+_median"$/, "", prob); gsub(/"/, "", prob)
    t[$1, prob, impl] = $5
    if (!(prob in seen)) { seen[prob] = 1; order[++np] = prob } }
  END {
    print "| problem | -O2: hand, kane (ratio) | -O3: hand, kane (ratio) | -O3 -march=native: hand, kane (ratio) |"
    print "|---|---|---|---|"
    split("bench-o2 bench bench-native", ps, " ")
    for (i = 1; i <= np; ++i) {
      line = "| " order[i]
      for (j = 1; j <= 3; ++j) {
        h = t[ps[j], order[i], "hand"]; k = t[ps[j], order[i], "kane"]
        line = line sprintf(" | %.0f, %.0f (%.2f)", h, k, k / h)
      }
      print line " |"
    }
    printf "\nOrocos KDL at -O3 (ns):"
    for (i = 1; i <= np; ++i) if (t["bench", order[i], "kdl"] != "") printf " %s %.0f;", order[i], t["bench", order[i], "kdl"]
    print ""
  }' "$csv"
rm -f "$csv"
