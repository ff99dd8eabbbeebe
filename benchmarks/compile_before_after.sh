#!/usr/bin/env bash
# Compile cost before and after a change: measures each unit (the bicycle in one unit and split,
# examples, benchmarks' kane side, tests, a type error, <kane/kane.hpp> alone) at BEFORE_COMMIT, in
# a temporary git worktree, and in this checkout, one at a time, with the compile command of
# benchmarks/performance_page.sh (g++ -O2, user CPU seconds and peak memory by /usr/bin/time), and
# rewrites the block between "<!-- generated: compile-before-after -->" and "<!-- end -->" of
# docs/performance.md (inserted with its introduction after the compile table when missing).
# A unit which does not exist at one of the two shows "-".
# Usage: benchmarks/compile_before_after.sh BEFORE_COMMIT
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# = 1 ] || { echo "usage: $0 BEFORE_COMMIT" >&2 && exit 2; }
before=$(git rev-parse --verify --quiet "$1^{commit}") || { echo "$0: no commit $1" >&2 && exit 2; }
page=docs/performance.md
now=$PWD
work=$(mktemp -d)
trap 'git worktree remove --force "$work/before" 2>/dev/null || true; rm -rf "$work"' EXIT
git worktree add --detach --quiet "$work/before" "$before"
old=$work/before
flags=(-std=c++20 -O2 -DNDEBUG -Iinclude -Iexamples -Ibenchmarks -isystem /usr/include/eigen3 -c -o /dev/null)

# Units made for one tree ROOT, written to $work/NAME/ROOT-tag: the bicycle in one unit (the three
# files of examples/ where the model is compiled once, else examples/bicycle_benchmark.cpp, which then
# holds it all), the type error (right after the call of kane::linearize_equations where the model is
# compiled once, as performance_page.sh; else right after the call of the linearization in the
# example's main) and <kane/kane.hpp> alone.
make_units() {
  local root=$1 dir=$work/$2
  mkdir -p "$dir"
  if [ -e "$root/examples/models/bicycle_linear.cpp" ]; then
    for f in examples/models/bicycle_linear.cpp examples/models/bicycle_eigenvalues.cpp examples/bicycle_benchmark.cpp; do
      printf '#include "%s/%s"\n' "$root" "$f"
    done >"$dir/bicycle_in_one_unit.cpp"
    sed '/kane::linearize_equations/a\  int type_error = s;' "$root/examples/models/bicycle_linear.cpp" |
      sed 's,#include ",#include "'"$root"'/examples/models/,' >"$dir/type_error.cpp"
  else
    printf '#include "%s/examples/bicycle_benchmark.cpp"\n' "$root" >"$dir/bicycle_in_one_unit.cpp"
    sed '/= linearize_upright(/a\  int type_error = at0;' "$root/examples/bicycle_benchmark.cpp" |
      sed 's,#include ",#include "'"$root"'/examples/,' >"$dir/type_error.cpp"
  fi
  grep -q type_error "$dir/type_error.cpp" || rm "$dir/type_error.cpp"
  echo '#include <kane/kane.hpp>' >"$dir/kane_hpp_alone.cpp"
}
make_units "$old" old
make_units "$now" new

# measure ROOT UNIT [fail]: "CPU s | peak MB" of g++ on UNIT (a path under ROOT, or "@NAME" for a
# made unit, then any -D flags) from ROOT; "- | -" where the file is missing. With "fail" the unit
# must not compile (the time is to its first error, -Wfatal-errors).
measure() {
  local root=$1 src=$2 expect=${3:-ok} tag file extra=()
  [ "$root" = "$now" ] && tag=new || tag=old
  [ "${src:0:1}" = @ ] && src=$work/$tag/${src:1}
  file=${src%% *}
  [ "${file:0:1}" = / ] || file=$root/$file
  [ -e "$file" ] || { echo "- | -" && return; }
  [ "$expect" = fail ] && extra=(-Wfatal-errors)
  # shellcheck disable=SC2086
  if (cd "$root" && /usr/bin/time -o "$work/time" -f "%U %M" g++ "${flags[@]}" "${extra[@]}" $src 2>"$work/err"); then
    [ "$expect" = fail ] && echo "$0: $src compiled at $root" >&2 && echo "compiled | compiled" && return
  elif [ "$expect" = ok ]; then
    echo "$0: $src failed at $root:" >&2 && head -5 "$work/err" >&2 && echo "failed | failed" && return
  fi
  read -r user kb < <(tail -1 "$work/time")
  printf '%.1f | %d\n' "$user" $((kb / 1024))
}

# "unit|label": every listed unit is measured in both trees.
units=(
  "@bicycle_in_one_unit.cpp|bicycle, everything in one unit: the three files below as one, or \`examples/bicycle_benchmark.cpp\` where they do not exist"
  "examples/models/bicycle_linear.cpp|\`examples/models/bicycle_linear.cpp\`: the bicycle's reduced equations and linearization, compiled once"
  "examples/models/bicycle_eigenvalues.cpp|\`examples/models/bicycle_eigenvalues.cpp\`: the bicycle's eigenvalues, compiled once"
  "examples/bicycle_benchmark.cpp|\`examples/bicycle_benchmark.cpp\`: the program that calls the two"
  "examples/pendulum3d.cpp|\`examples/pendulum3d.cpp\`"
  "@type_error.cpp fail|\`type_error.cpp\`: a type error right after the bicycle's call of the linearization, reported (-Wfatal-errors)"
  "@kane_hpp_alone.cpp|\`#include <kane/kane.hpp>\` alone"
)
others=$(for root in "$old" "$now"; do
  (cd "$root" && shopt -s nullglob && printf '%s\n' examples/*.cpp examples/models/*.cpp benchmarks/*_kane.cpp tests/test_*.cpp tests/eigenvalues.cpp)
done | sort -u | awk '{ d = $0; sub(/\/[^\/]*$/, "", d); print (d == "tests" ? 3 : d == "benchmarks" ? 2 : 1) " " $0 }' | sort | cut -d' ' -f2)
for f in $others; do
  case $f in
    examples/bicycle_benchmark.cpp | examples/models/bicycle_*.cpp | examples/pendulum3d.cpp) ;;
    benchmarks/chain_dynamics_kane.cpp) for n in 6 12 24 48; do units+=("$f -DKANE_CHAIN_N=$n|\`$f -DKANE_CHAIN_N=$n\`"); done ;;
    *) units+=("$f|\`$f\`") ;;
  esac
done

{
  # shellcheck disable=SC2016
  printf 'Measured on %s: before is `%s` (%s), now is `%s`; %s, %s.\n\n' "$(date -u +%Y-%m-%d)" \
    "$(git rev-parse --short "$before")" "$(git log -1 --format=%cs "$before")" \
    "$(git rev-parse --short HEAD)$(git diff --quiet HEAD -- include examples tests benchmarks || echo ' with uncommitted changes')" \
    "$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //')" "$(g++ --version | head -1)"
  echo "| unit | before CPU s | before peak MB | now CPU s | now peak MB |"
  echo "|---|---|---|---|---|"
  for u in "${units[@]}"; do
    src=${u%%|*} label=${u#*|} expect=ok
    case $src in *" fail") src=${src% fail} expect=fail ;; esac
    # the program that calls the compiled-once bicycle exists only where they do
    if [ "$src" = examples/bicycle_benchmark.cpp ] && [ ! -e "$old/examples/models/bicycle_linear.cpp" ]; then a="- | -"
    else a=$(measure "$old" "$src" $expect); fi
    if [ "$src" = examples/bicycle_benchmark.cpp ] && [ ! -e "$now/examples/models/bicycle_linear.cpp" ]; then b="- | -"
    else b=$(measure "$now" "$src" $expect); fi
    echo "| $label | $a | $b |"
    echo "$label: $a | $b" >&2
  done
} >"$work/block.md"

# The block, rewritten; inserted with its introduction right after the compile table when missing.
has=0; grep -qx '<!-- generated: compile-before-after -->' "$page" && has=1
awk -v file="$work/block.md" -v has=$has '
  function block(  line) { print "<!-- generated: compile-before-after -->"; while ((getline line < file) > 0) print line; close(file); print "<!-- end -->" }
  $0 == "<!-- generated: compile-before-after -->" { block(); skip = 1; done = 1; next }
  skip { if ($0 == "<!-- end -->") skip = 0; next }
  $0 == "<!-- generated: compile -->" { incompile = 1 }
  { print }
  incompile && $0 == "<!-- end -->" { incompile = 0; after = 1 }
  END { if (!done) exit 1 }
  after && !has { after = 0
    print ""
    print "Before and after a change: the before columns are kane at the commit named below and the now columns"
    print "this checkout, measured by `benchmarks/compile_before_after.sh` as the table above (g++ -O2, one unit at"
    print "a time); a unit which does not exist there shows \"-\"."
    print ""
    block(); done = 1 }' "$page" >"$work/page.md" || { echo "$0: no compile table in $page" >&2 && exit 1; }
cp "$work/page.md" "$page"
echo "rewrote $page"
