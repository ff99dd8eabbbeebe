#!/usr/bin/env bash
# The README's performance table: builds the bench presets (-O2, -O3,
# -O3 -march=native), runs every benchmark binary (5 repetitions) and prints,
# per problem and preset, the median CPU ns of the hand-written pass and of
# kane with the range [min-max] of the 5 repetitions, and the ratio of the
# medians; for the disc also SymPy's generated code (disc_sympy.cpp), for the bicycle
# (bench_bicycle: no hand column) kane and SymPy's code (bicycle_sympy.cpp); then the
# peer (Orocos KDL) at -O3 (bench_disc_dynamics also times kane_reduced, which the
# table leaves out). Needs libbenchmark-dev liborocos-kdl-dev.
set -euo pipefail
cd "$(dirname "$0")/.."
presets=(bench-o2 bench bench-native)
reps=5
csv=$(mktemp)
for p in "${presets[@]}"; do
  cmake --preset "$p" >/dev/null
  cmake --build --preset "$p" >/dev/null
  for b in arm6 chain disc fourbar quaternion dynamics6 disc_dynamics bicycle chain_dynamics; do
    "./build/$p/benchmarks/bench_$b" --benchmark_repetitions=$reps --benchmark_format=csv 2>/dev/null |
      grep '^"' | grep -Ev '_(mean|median|stddev|cv)"' | sed "s/^/$p,/"
  done
done >"$csv"
awk -F, -v reps=$reps '
  { gsub(/"/, "", $2); n = split($2, part, "/"); impl = part[n]; prob = substr($2, 1, length($2) - length(impl) - 1)
    key = $1 SUBSEP prob SUBSEP impl
    runs[key, ++count[key]] = $5 + 0
    if (!(prob in seen)) { seen[prob] = 1; order[++np] = prob } }
  function stats(key,   i, j, m, x, v) {  # median, min, max of the runs of key (sorted in place)
    m = count[key]; med = lo = hi = 0
    if (m == 0) return 0
    for (i = 2; i <= m; ++i) { x = runs[key, i]; for (j = i - 1; j >= 1 && runs[key, j] > x; --j) runs[key, j + 1] = runs[key, j]; runs[key, j + 1] = x }
    med = m % 2 ? runs[key, (m + 1) / 2] : (runs[key, m / 2] + runs[key, m / 2 + 1]) / 2
    lo = runs[key, 1]; hi = runs[key, m]
    return 1
  }
  function cell(p, prob, impl) {
    return stats(p SUBSEP prob SUBSEP impl) ? sprintf("%.0f [%.0f-%.0f]", med, lo, hi) : "-"
  }
  END {
    split("bench-o2 bench bench-native", ps, " ")
    printf "CPU ns per call: median [min-max] of %d repetitions; ratio = kane / hand of the medians.\n\n", reps
    print "| problem | -O2: hand, kane (ratio) | -O3: hand, kane (ratio) | -O3 -march=native: hand, kane (ratio) | SymPy: -O2, -O3, native |"
    print "|---|---|---|---|---|"
    for (i = 1; i <= np; ++i) {
      line = "| " order[i]
      for (j = 1; j <= 3; ++j) {
        h = cell(ps[j], order[i], "hand"); hm = med
        k = cell(ps[j], order[i], "kane"); km = med
        line = line sprintf(" | %s, %s (%s)", h, k, hm > 0 && km > 0 ? sprintf("%.2f", km / hm) : "-")
      }
      s = "-"
      for (j = 1; j <= 3; ++j) if (stats(ps[j] SUBSEP order[i] SUBSEP "sympy")) s = ""
      if (s == "") s = cell(ps[1], order[i], "sympy") ", " cell(ps[2], order[i], "sympy") ", " cell(ps[3], order[i], "sympy")
      print line " | " s " |"
    }
    printf "\nOrocos KDL at -O3 (ns, median [min-max]):"
    for (i = 1; i <= np; ++i) if (stats("bench" SUBSEP order[i] SUBSEP "kdl")) printf " %s %s;", order[i], cell("bench", order[i], "kdl")
    print ""
  }' "$csv"
rm -f "$csv"
