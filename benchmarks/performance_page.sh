#!/usr/bin/env bash
# Regenerates the tables of docs/performance.md on this machine, the one entry point: builds the
# presets bench-o2 (-O2) and bench-native (-O3 -march=native), runs every benchmark binary (5
# repetitions) and rewrites each block "<!-- generated: NAME -->" ... "<!-- end -->" of the page it
# measured; the compile table is benchmarks/compile_cost.sh table. Usage: as usage() prints.
set -euo pipefail
cd "$(dirname "$0")/.."
usage() {
  cat <<'EOF'
apt-get install -y libbenchmark-dev liborocos-kdl-dev   # once: Google Benchmark and Orocos KDL
benchmarks/performance_page.sh                # every table: build both presets, run, compile
benchmarks/performance_page.sh --no-build     # every table, the presets' binaries as they are
benchmarks/performance_page.sh --no-run       # the compile table alone
benchmarks/performance_page.sh --no-compile   # the run-time tables alone
benchmarks/performance_page.sh --no-compile --only=NAME   # the table of bench_NAME alone, dated
EOF
  exit 2
}
build=1 run=1 compile=1 only=
for arg in "$@"; do
  case $arg in
    --no-build) build=0 ;;
    --no-run) run=0 build=0 ;;
    --no-compile) compile=0 ;;
    --only=*) only=${arg#--only=} ;;
    *) usage ;;
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
    cmake --build --preset "$p" ${only:+--target bench_$only} >/dev/null 2>&1 || [ -n "$only" ]
  fi
  for b in ./build/"$p"/benchmarks/bench_${only:-*}; do
    [ -x "$b" ] || continue  # a binary of one preset alone (bench_lanes_avx2)
    "$b" --benchmark_repetitions=$reps --benchmark_enable_random_interleaving=true --benchmark_format=csv 2>/dev/null | grep '^"' |
      grep -Ev '_(mean|median|stddev|cv)"' | sed "s/^/$p,/"
  done
done >"$work/runs.csv"

# One table per benchmark group (the first part of a name, group/problem/implementation):
# per preset the median [min-max] CPU ns of each implementation, kane / hand, kane / SymPy's
# C, kane / hand and / SymPy's C checked as kane is (../common/checked.hpp) and KDL / kane of the medians; with
# lanes (kane_x4, kane_x8, kane_soa) kane / kane_x4, kane / kane_x8, kane / kane_soa,
# kane_x8 / SymPy's C and kane_soa / SymPy's C.
awk -F, -v reps=$reps -v dir="$work" '
  BEGIN { rank["hand"] = 1; rank["hand_checked"] = 2; rank["sympy"] = 3; rank["sympy_checked"] = 4
          rank["kdl"] = 5; rank["kane"] = 6; rank["kane_x4"] = 7; rank["kane_x8"] = 8; rank["kane_soa"] = 8.5; rank["kane_float_x16"] = 9 }
  { gsub(/"/, "", $2); n = split($2, part, "/"); impl = part[n]; group = part[1]
    prob = substr($2, length(group) + 2, length($2) - length(group) - length(impl) - 2)
    t = $5 + 0; if ($6 == "us") t *= 1e3; else if ($6 == "ms") t *= 1e6
    key = $1 SUBSEP group SUBSEP prob SUBSEP impl; runs[key, ++count[key]] = t
    if (!((group, prob) in seen)) { seen[group, prob] = 1; probs[group, ++np[group]] = prob }
    if (!((group, impl) in has)) {  # implementations in the order of rank, others last
      has[group, impl] = 1; r = impl in rank ? rank[impl] : 10
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
      if ((G, "hand_checked") in has) refs = refs ", kane/checked hand"
      if ((G, "sympy_checked") in has) refs = refs ", kane/checked SymPy"
      if ((G, "kdl") in has) refs = refs ", KDL/kane"
      if ((G, "kane_x4") in has) refs = refs ", kane/kane_x4"
      if ((G, "kane_x8") in has) refs = refs ", kane/kane_x8"
      if ((G, "kane_soa") in has) refs = refs ", kane/kane_soa"
      if ((G, "kane_x8") in has && (G, "sympy") in has) refs = refs ", kane_x8/SymPy"
      if ((G, "kane_soa") in has && (G, "sympy") in has) refs = refs ", kane_soa/SymPy"
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
          if ((G, "hand_checked") in has) r = r ", " ratio(m["kane"], m["hand_checked"])
          if ((G, "sympy_checked") in has) r = r ", " ratio(m["kane"], m["sympy_checked"])
          if ((G, "kdl") in has) r = r ", " ratio(m["kdl"], m["kane"])
          if ((G, "kane_x4") in has) r = r ", " ratio(m["kane"], m["kane_x4"])
          if ((G, "kane_x8") in has) r = r ", " ratio(m["kane"], m["kane_x8"])
          if ((G, "kane_soa") in has) r = r ", " ratio(m["kane"], m["kane_soa"])
          if ((G, "kane_x8") in has && (G, "sympy") in has) r = r ", " ratio(m["kane_x8"], m["sympy"])
          if ((G, "kane_soa") in has && (G, "sympy") in has) r = r ", " ratio(m["kane_soa"], m["sympy"])
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
              if (P ~ /^[0-9]+$/ && P + 0 >= 12 && stats(ps[j] SUBSEP G SUBSEP P SUBSEP I)) { x = log(P + 0); y = log(med); sx += x; sy += y; sxx += x * x; sxy += x * y; ++c }
            }
            if (c >= 2) s = s (s == "" ? "" : ", ") I sprintf(" n^%.2f", (c * sxy - sx * sy) / (c * sxx - sx * sx))
          }
          printf "\nGrowth of the medians from n = 12 to 48 (least squares in log-log), %s: %s.\n", pn[j], s > out
        }
      }
    }
  }' "$work/runs.csv"

# --- the machine of the run-time tables (the compile table names its own), then every block measured
if [ -n "$only" ]; then  # one table: its own date, commit and processor, the page's line as it is
  printf '\nMeasured on %s at commit %s on %s, apart from the other tables.\n' "$(date -u +%Y-%m-%d)" \
    "$(git rev-parse --short HEAD)" "$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')" >>"$work/table_$only.md"
fi
[ $run = 1 ] && [ -z "$only" ] && {
  printf 'Run-time tables measured on %s at commit %s: %s, %s cores, %s, Eigen %s.\n' "$(date -u +%Y-%m-%d)" \
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
# --- the compile table: g++ -O2, one unit at a time
[ $compile = 0 ] || benchmarks/compile_cost.sh table
