#!/usr/bin/env bash
# Regenerates the tables of docs/performance.md on this machine: builds the presets bench-o2
# (-O2) and bench-native (-O3 -march=native), runs every benchmark binary (5 repetitions),
# measures the compile cost of the units listed below (g++ -O2, one at a time), and rewrites
# each block between "<!-- generated: NAME -->" and "<!-- end -->" of the page.
# Needs libbenchmark-dev liborocos-kdl-dev. Usage: benchmarks/performance_page.sh [--no-build]
# [--no-run] [--no-compile]: without building the presets first; without the run-time tables or
# without the compile table (a table not measured is kept as it is).
set -euo pipefail
cd "$(dirname "$0")/.."
build=1 run=1 compile=1
for arg in "$@"; do
  case $arg in
    --no-build) build=0 ;;
    --no-run) run=0 build=0 ;;
    --no-compile) compile=0 ;;
    *) echo "usage: $0 [--no-build] [--no-run] [--no-compile]" >&2 && exit 2 ;;
  esac
done
page=docs/performance.md
presets=(bench-o2 bench-native)
reps=5
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# --- run time: one CSV line per repetition, "preset,name,iterations,real,cpu,unit,..."
[ $run = 1 ] || presets=()
for p in "${presets[@]}"; do
  if [ $build = 1 ]; then
    cmake --preset "$p" >/dev/null
    cmake --build --preset "$p" >/dev/null
  fi
  for b in ./build/"$p"/benchmarks/bench_*; do
    "$b" --benchmark_repetitions=$reps --benchmark_format=csv 2>/dev/null | grep '^"' |
      grep -Ev '_(mean|median|stddev|cv)"' | sed "s/^/$p,/"
  done
done >"$work/runs.csv"

# One table per benchmark group (the first part of a name, group/problem/implementation):
# per preset the median [min-max] CPU ns of each implementation, kane / hand, kane / SymPy's
# C and KDL / kane of the medians.
awk -F, -v reps=$reps -v dir="$work" '
  BEGIN { rank["hand"] = 1; rank["sympy"] = 2; rank["kdl"] = 3; rank["kane"] = 4 }
  { gsub(/"/, "", $2); n = split($2, part, "/"); impl = part[n]; group = part[1]
    prob = substr($2, length(group) + 2, length($2) - length(group) - length(impl) - 2)
    t = $5 + 0; if ($6 == "us") t *= 1e3; else if ($6 == "ms") t *= 1e6
    key = $1 SUBSEP group SUBSEP prob SUBSEP impl; runs[key, ++count[key]] = t
    if (!((group, prob) in seen)) { seen[group, prob] = 1; probs[group, ++np[group]] = prob }
    if (!((group, impl) in has)) {  # implementations in the order hand, sympy, kdl, kane, others
      has[group, impl] = 1; r = impl in rank ? rank[impl] : 5
      for (i = ++ni[group]; i > 1 && impl_rank[group, i - 1] > r; --i) { impls[group, i] = impls[group, i - 1]; impl_rank[group, i] = impl_rank[group, i - 1] }
      impls[group, i] = impl; impl_rank[group, i] = r }
    if (!(group in gseen)) { gseen[group] = 1; groups[++ng] = group } }
  function stats(key,   i, j, m, x) {
    m = count[key]; if (m == 0) return 0
    for (i = 2; i <= m; ++i) { x = runs[key, i]; for (j = i - 1; j >= 1 && runs[key, j] > x; --j) runs[key, j + 1] = runs[key, j]; runs[key, j + 1] = x }
    med = m % 2 ? runs[key, (m + 1) / 2] : (runs[key, m / 2] + runs[key, m / 2 + 1]) / 2
    lo = runs[key, 1]; hi = runs[key, m]; return 1 }
  function num(x) { return x >= 100 ? sprintf("%.0f", x) : sprintf("%.1f", x) }
  function ratio(a, b) { return a > 0 && b > 0 ? sprintf("%.2f", a / b) : "-" }
  END {
    split("bench-o2 bench-native", ps, " "); split("-O2|-O3 -march=native", pn, "|")
    for (g = 1; g <= ng; ++g) {
      G = groups[g]; out = dir "/table_" G ".md"; names = ""
      for (i = 1; i <= ni[G]; ++i) names = names (i > 1 ? ", " : "") impls[G, i]
      refs = ""
      if ((G, "hand") in has) refs = refs ", kane/hand"
      if ((G, "sympy") in has) refs = refs ", kane/SymPy"
      if ((G, "kdl") in has) refs = refs ", KDL/kane"
      head = "| " G
      for (j = 1; j <= 2; ++j) head = head " | " pn[j] ": " names (refs == "" ? "" : " | " substr(refs, 3))
      print head " |" > out
      line = "|---"; for (j = 1; j <= 2; ++j) line = line (refs == "" ? "|---" : "|---|---"); print line "|" > out
      for (k = 1; k <= np[G]; ++k) {
        P = probs[G, k]; row = "| " P
        for (j = 1; j <= 2; ++j) {
          cells = ""; delete m
          for (i = 1; i <= ni[G]; ++i) {
            I = impls[G, i]
            if (stats(ps[j] SUBSEP G SUBSEP P SUBSEP I)) { m[I] = med; c = num(med) " [" num(lo) "-" num(hi) "]" } else c = "-"
            cells = cells (i > 1 ? ", " : "") c
          }
          r = ""
          if ((G, "hand") in has) r = r ", " ratio(m["kane"], m["hand"])
          if ((G, "sympy") in has) r = r ", " ratio(m["kane"], m["sympy"])
          if ((G, "kdl") in has) r = r ", " ratio(m["kdl"], m["kane"])
          row = row " | " cells (r == "" ? "" : " | " substr(r, 3))
        }
        print row " |" > out
      }
      if (G == "chain_dynamics") {  # growth n^p from n = 12 to n = 48, least squares over 12, 24, 48
        for (j = 1; j <= 2; ++j) {
          s = ""
          for (i = 1; i <= ni[G]; ++i) {
            I = impls[G, i]; sx = sy = sxx = sxy = c = 0
            for (k = 1; k <= np[G]; ++k) {
              P = probs[G, k]
              if (P + 0 >= 12 && stats(ps[j] SUBSEP G SUBSEP P SUBSEP I)) { x = log(P + 0); y = log(med); sx += x; sy += y; sxx += x * x; sxy += x * y; ++c }
            }
            if (c >= 2) s = s (s == "" ? "" : ", ") I sprintf(" n^%.2f", (c * sxy - sx * sy) / (c * sxx - sx * sx))
          }
          printf "\nGrowth of the medians from n = 12 to 48 (least squares in log-log), %s: %s.\n", pn[j], s > out
        }
      }
    }
  }' "$work/runs.csv"

# --- compile cost: g++ -O2, user CPU seconds and peak memory, one unit at a time.
if [ $compile = 1 ]; then
flags=(-std=c++20 -O2 -DNDEBUG -Iinclude -Iexamples -Ibenchmarks -isystem /usr/include/eigen3 -c -o /dev/null)
for f in examples/models/bicycle_linear.cpp examples/models/bicycle_eigenvalues.cpp examples/bicycle_benchmark.cpp; do
  printf '#include "%s/%s"\n' "$PWD" "$f"
done >"$work/bicycle_in_one_unit.cpp"
units=(
  "examples/models/bicycle_linear.cpp|bicycle: reduced equations and linearization, compiled once"
  "examples/models/bicycle_eigenvalues.cpp|bicycle: the benchmark's eigenvalues, compiled once"
  "examples/bicycle_benchmark.cpp|bicycle: the example that calls the two"
  "$work/bicycle_in_one_unit.cpp|bicycle: the same three files as one unit"
  "examples/pendulum3d.cpp|3D double pendulum, u' by kane::motion"
  "examples/models/free_body_motion.cpp|free body: the model compiled once"
  "examples/free_body_dynamics.cpp|free body: the example that calls it"
)
for f in benchmarks/*_kane.cpp; do
  case $f in *chain_dynamics_kane.cpp) continue ;; esac
  units+=("$f|benchmark: kane's side of bench_$(basename "$f" _kane.cpp)")
done
for n in 6 12 24 48; do units+=("benchmarks/chain_dynamics_kane.cpp -DKANE_CHAIN_N=$n|benchmark: the $n-link chain's forward dynamics"); done
for f in tests/test_*.cpp; do units+=("$f|test"); done
units+=("tests/eigenvalues.cpp|tests: Eigen's EigenSolver, compiled once")
for scalar in float double; do units+=("tests/warnings.cpp -DKANE_WARNINGS_SCALAR=$scalar|the whole API under strict warnings, $scalar"); done
{
  echo "| unit | what | CPU s | peak MB |"
  echo "|---|---|---|---|"
  for u in "${units[@]}"; do
    src=${u%%|*} what=${u#*|}
    # shellcheck disable=SC2086
    /usr/bin/time -o "$work/time" -f "%U %M" g++ "${flags[@]}" $src
    read -r user kb <"$work/time"
    name=${src/$work\//}
    printf '| `%s` | %s | %.1f | %d |\n' "$name" "$what" "$user" $((kb / 1024))
  done
  # a plain type error right after the bicycle's call of the linearization, -Wfatal-errors
  sed '/kane::linearize_equations/a\  int type_error = s;' examples/models/bicycle_linear.cpp |
    sed 's,#include ",#include "'"$PWD"'/examples/models/,' >"$work/type_error.cpp"
  if /usr/bin/time -o "$work/time" -f "%U %M" g++ "${flags[@]}" -Wfatal-errors "$work/type_error.cpp" 2>/dev/null; then
    echo "type_error.cpp compiled" >&2
    exit 1
  fi
  read -r user kb < <(tail -1 "$work/time")
  printf '| `type_error.cpp` | %s | %.1f | %d |\n' \
    "a type error right after \`kane::linearize_equations\` on the bicycle, reported (-Wfatal-errors)" "$user" $((kb / 1024))
} >"$work/table_compile.md"
fi

# --- the machine (when every table is measured), then every generated block of the page
[ $run = 1 ] && [ $compile = 1 ] && {
  printf 'Measured on %s at commit %s: %s, %s cores, %s, Eigen %s.\n' "$(date -u +%Y-%m-%d)" \
    "$(git rev-parse --short HEAD)" "$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')" "$(nproc)" \
    "$(g++ --version | head -1)" "$(sed -n 's/#define EIGEN_[A-Z]*_VERSION \([0-9]*\)/\1/p' /usr/include/eigen3/Eigen/src/Core/util/Macros.h | paste -sd.)"
} >"$work/table_machine.md"
awk -v dir="$work" '
  /^<!-- generated: [a-z0-9_]+ -->$/ { print; file = dir "/table_" $3 ".md"
    if ((getline line < file) > 0) { print line; while ((getline line < file) > 0) print line; close(file); skip = 1 }
    next }
  /^<!-- end -->$/ { skip = 0 }
  !skip { print }' "$page" >"$work/page.md"
cp "$work/page.md" "$page"
echo "rewrote $page"
