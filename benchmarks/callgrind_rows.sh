#!/usr/bin/env bash
# Instructions per call of every benchmark row of the bench-o2 build (-O2, no -march=native), by
# callgrind; with revisions, side by side with the ratio, rows matched by name.
# Method: each row runs alone (--benchmark_filter=^ROW$) under valgrind --tool=callgrind, collecting
# only inside bench::run<F, States> (one call of F per iteration, on the next of 64 states); a call's
# instructions are the inclusive Ir of run's calls to F over their number, both from callgrind's call
# graph, so every run Google Benchmark makes to size its iterations counts, and its loop does not.
# Usage: benchmarks/callgrind_rows.sh [--filter REGEX] [--work DIR] [--no-build] [BEFORE [AFTER]]
#   no revision: this checkout's rows; BEFORE: BEFORE beside this checkout; BEFORE AFTER: the two.
#   A revision is built in a temporary git worktree with its own benchmarks/ and CMakePresets.json
#   (cmake --preset bench-o2, nice -n 10, -j1); this checkout's build/bench-o2 is built unless
#   --no-build. --filter keeps the rows whose name matches REGEX (grep -E). --work DIR keeps the
#   worktrees, builds and callgrind files in DIR and reuses them. MIN_TIME (default 0.2) is passed
#   as --benchmark_min_time. Needs valgrind and what the benchmarks need.
set -euo pipefail
cd "$(dirname "$0")/.."
usage() { sed -n 's/^# \{0,1\}//; 8,14p' "$0" >&2 && exit 2; }
filter='' work='' build=1 revs=()
while [ $# -gt 0 ]; do
  case $1 in
    --filter) [ $# -ge 2 ] || usage; filter=$2 && shift ;;
    --work) [ $# -ge 2 ] || usage; work=$2 && shift ;;
    --no-build) build=0 ;;
    -*) usage ;;
    *) revs+=("$1") ;;
  esac
  shift
done
[ ${#revs[@]} -le 2 ] || usage
min_time=${MIN_TIME:-0.2}
top=$PWD
if [ -n "$work" ]; then
  mkdir -p "$work" && work=$(cd "$work" && pwd)
else
  work=$(mktemp -d)
  cleanup() {
    local t
    for t in "$work"/tree-*; do [ ! -d "$t" ] || git -C "$top" worktree remove --force "$t"; done
    rm -rf "$work"
  }
  trap cleanup EXIT
fi

# build ROOT: the bench-o2 preset's benchmarks in ROOT (its log in $work/build.log).
build() {
  (cd "$1" && nice -n 10 cmake --preset bench-o2 && nice -n 10 cmake --build --preset bench-o2 -j 1) >"$work/build.log" 2>&1 ||
    { echo "$0: the build in $1 failed:" >&2 && tail -20 "$work/build.log" >&2 && exit 1; }
}

# tree REV: a worktree of REV under $work, built; prints its path.
tree() {
  local sha dir
  sha=$(git rev-parse --verify --quiet "$1^{commit}") || { echo "$0: no commit $1" >&2 && exit 2; }
  dir=$work/tree-${sha:0:12}
  [ -d "$dir" ] || git worktree add --detach --quiet "$dir" "$sha"
  echo "building $1 (${sha:0:12}) in $dir" >&2
  build "$dir"
  echo "$dir"
}

# measure ROOT TAG: "row calls Ir_per_call" for every row of ROOT's bench-o2 binaries, in $work/TAG.txt.
measure() {
  local root=$1 out=$work/$2.txt bin row cg
  : >"$out"
  for bin in "$root"/build/bench-o2/benchmarks/bench_*; do
    [ -x "$bin" ] || continue
    for row in $("$bin" --benchmark_list_tests=true | grep -E "${filter:-.}" || true); do
      cg=$work/$2.$(echo "$row" | tr / .).callgrind
      valgrind --tool=callgrind --callgrind-out-file="$cg" --compress-strings=no \
        --toggle-collect='*bench::run<*' "$bin" --benchmark_filter="^$row\$" \
        --benchmark_min_time="$min_time" >/dev/null 2>"$work/valgrind.log" ||
        { echo "$0: $bin failed on $row under valgrind:" >&2 && tail -5 "$work/valgrind.log" >&2 && exit 1; }
      # the callee of bench::run called most often is F (the others: Google Benchmark's and ld.so's)
      awk -v row="$row" '
        /^fn=/ { inrun = ($0 ~ /bench::run</) }
        inrun && /^cfn=/ { callee = substr($0, 5) }
        inrun && /^calls=/ { split($0, a, /[= ]/); getline; calls[callee] += a[2]; ir[callee] += $2 }
        END { for (c in calls) if (calls[c] > n) { n = calls[c]; f = c }
              if (n == 0) { print row ": no call from bench::run" > "/dev/stderr"; exit 1 }
              printf "%s %d %.1f\n", row, n, ir[f] / n }' "$cg" | tee -a "$out" >&2
    done
  done
}

case ${#revs[@]} in
  0) [ $build = 0 ] || build "$top"; measure "$top" here; cols=(here) ;;
  1) a=$(tree "${revs[0]}"); [ $build = 0 ] || build "$top"
     measure "$a" before; measure "$top" after; cols=(before after) ;;
  2) a=$(tree "${revs[0]}"); b=$(tree "${revs[1]}"); measure "$a" before; measure "$b" after; cols=(before after) ;;
esac

# The table: rows in the order of the last column's binaries, then those only in the first.
label() { [ $# -gt 0 ] && git rev-parse --short "$1" || echo "this checkout"; }
if [ ${#cols[@]} = 1 ]; then
  echo "| row | Ir per call | calls |"
  echo "|---|---|---|"
  awk '{ printf "| %s | %.0f | %d |\n", $1, $3, $2 }' "$work/here.txt"
else
  echo "before: $(label "${revs[0]}"), after: $(label "${revs[@]:1}"); Ir per call, bench-o2 (-O2), callgrind"
  echo "| row | before | after | after/before |"
  echo "|---|---|---|---|"
  awk 'FNR == NR { b[$1] = $3; next }
    { seen[$1] = 1; x = y = "-"
      if ($1 in b) { x = sprintf("%.0f", b[$1]); if (b[$1] > 0) y = sprintf("%.3f", $3 / b[$1]) }
      printf "| %s | %s | %.0f | %s |\n", $1, x, $3, y }
    END { for (r in b) if (!(r in seen)) printf "| %s | %.0f | - | - |\n", r, b[r] }' \
    "$work/before.txt" "$work/after.txt"
fi
