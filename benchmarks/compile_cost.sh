#!/usr/bin/env bash
# Compile cost of kane's translation units: $CXX (default g++) -O2, one unit at a time, user CPU
# seconds and peak memory by /usr/bin/time. One list of units (units() below): Eigen and kane.hpp
# alone, the examples, the benchmarks' kane side, the tests, the bicycle in one unit and as a user's
# unit (benchmarks/compile/), a type error.
# Usage: benchmarks/compile_cost.sh table [--print] [MATCH...]
#          every unit; rewrites the block "<!-- generated: compile -->" of docs/performance.md, or
#          prints the table (--print, or the units whose source contains a MATCH)
#        benchmarks/compile_cost.sh compare REV [--page] [MATCH...]
#          each unit at REV (in a temporary git worktree) and in this checkout, side by side; a unit
#          missing at one of the two shows "-" (benchmarks/<problem>/FILE is benchmarks/FILE in the
#          older flat layout); --page rewrites the block "<!-- generated: compile-before-after -->"
#        benchmarks/compile_cost.sh chain [N...]
#          the N-link chain's dynamics (N = 6 12 24 48 by default), wall and user seconds, peak MB,
#          and the growth exponent p (cost ~ N^p) from the first to the last N
#        benchmarks/compile_cost.sh list
#          the units
set -euo pipefail
cd "$(dirname "$0")/.."
usage() { sed -n 's/^# \{0,1\}//; 5,17p' "$0" >&2 && exit 2; }
[ $# -ge 1 ] || usage
command=$1 && shift
cxx=${CXX:-g++}
page=docs/performance.md
now=$PWD
work=$(mktemp -d)
cleanup() {
  [ ! -d "$work/before" ] || git worktree remove --force "$work/before"
  rm -rf "$work"
}
trap cleanup EXIT
flags=(-std=c++20 -O2 -DNDEBUG -Iinclude -Iexamples -isystem /usr/include/eigen3 -c -o /dev/null)

# units ROOT...: "source [flags]|what" a line (flags: -D..., -march=native), the sources of every ROOT (benchmarks in this layout);
# "@NAME" is a unit made for each tree (make_units), " fail" after the source a unit that must not
# compile (timed to its first error).
units() {
  cat <<'EOF'
benchmarks/common/eigen_only.cpp|Eigen's Core, Geometry and LU alone
@kane_hpp_alone.cpp|`#include <kane/kane.hpp>` alone
examples/models/bicycle_linear.cpp|bicycle: reduced equations and linearization, compiled once
examples/models/bicycle_eigenvalues.cpp|bicycle: the benchmark's eigenvalues, compiled once
examples/bicycle_benchmark.cpp|bicycle: the example that calls the two
@bicycle_in_one_unit.cpp|bicycle: the same three files as one unit
examples/pendulum3d.cpp|3D double pendulum, u' by kane::motion
examples/models/free_body_motion.cpp|free body: the model compiled once
benchmarks/compile/bicycle_whole.cpp|bicycle as a user's one unit: u', reduced equations, F_r and F*_r, linearization, eigenvalues
benchmarks/compile/small_models.cpp|six small models' x' and two linearizations as a user's one unit
benchmarks/compile/dynamics6_lanes.cpp -march=native|6R arm: M, f, u' and tau at double, -march=native
benchmarks/compile/dynamics6_lanes.cpp -march=native -DKANE_LANES=8|6R arm: the same at double and at 8 lanes of double, -march=native
examples/free_body_dynamics.cpp|free body: the example that calls it
EOF
  local root f n glob
  for glob in 'examples/*.cpp examples/models/*.cpp' 'benchmarks/*_kane.cpp benchmarks/*/*_kane.cpp' 'tests/test_*.cpp'; do
    for root in "$@"; do
      # shellcheck disable=SC2086  # glob: the patterns of one group
      (cd "$root" && shopt -s nullglob && printf '%s\n' $glob)
    done | sed -E 's,^benchmarks/([a-z0-9_]+)_kane\.cpp$,benchmarks/\1/\1_kane.cpp,' | sort -u
  done |
    while read -r f; do
      case $f in
        examples/bicycle_benchmark.cpp | examples/models/bicycle_*.cpp | examples/pendulum3d.cpp) ;;
        examples/models/free_body_motion.cpp | examples/free_body_dynamics.cpp) ;;
        examples/*) echo "$f|example" ;;
        benchmarks/chain_dynamics/*)
          for n in 6 12 24 48; do echo "$f -DKANE_CHAIN_N=$n|benchmark: the $n-link chain's forward dynamics"; done ;;
        # lanes wider than SSE2's registers, which plain -O2 refuses: built for this machine
        benchmarks/lanes/*) echo "$f -march=native|benchmark: kane's side of bench_lanes, -march=native" ;;
        benchmarks/*) echo "$f|benchmark: kane's side of bench_$(basename "$f" _kane.cpp)" ;;
        tests/test_chain_speeds.cpp | tests/test_lane*.cpp) echo "$f -march=native|test, -march=native (lanes)" ;;
        tests/*) echo "$f|test" ;;
      esac
    done
  cat <<'EOF'
tests/eigenvalues.cpp|tests: Eigen's EigenSolver, compiled once
tests/warnings.cpp -DKANE_WARNINGS_SCALAR=float|the whole API under strict warnings, float
tests/warnings.cpp -DKANE_WARNINGS_SCALAR=double|the whole API under strict warnings, double
@type_error.cpp fail|a type error right after `kane::linearize_equations` on the bicycle, reported (-Wfatal-errors)
EOF
}

# selected MATCH...: the lines of stdin whose source contains a MATCH (all without one).
selected() {
  local line m
  while IFS= read -r line; do
    [ $# -gt 0 ] || { echo "$line" && continue; }
    for m in "$@"; do [[ ${line%%|*} != *"$m"* ]] || { echo "$line" && break; }; done
  done
}

# make_units ROOT TAG: the made units of ROOT in $work/TAG/: <kane/kane.hpp> alone; the bicycle's three
# files as one unit and a type error right after its call of kane::linearize_equations (where the model
# is compiled once; else examples/bicycle_benchmark.cpp, which then holds it all).
make_units() {
  local root=$1 dir=$work/$2 f
  mkdir -p "$dir"
  echo '#include <kane/kane.hpp>' >"$dir/kane_hpp_alone.cpp"
  if [ -e "$root/examples/models/bicycle_linear.cpp" ]; then
    for f in examples/models/bicycle_linear.cpp examples/models/bicycle_eigenvalues.cpp examples/bicycle_benchmark.cpp; do
      printf '#include "%s/%s"\n' "$root" "$f"
    done >"$dir/bicycle_in_one_unit.cpp"
    sed '/kane::linearize_equations/a\  int type_error = s;' "$root/examples/models/bicycle_linear.cpp" |
      sed 's,#include ",#include "'"$root"'/examples/models/,' >"$dir/type_error.cpp"
  elif [ -e "$root/examples/bicycle_benchmark.cpp" ]; then
    printf '#include "%s/examples/bicycle_benchmark.cpp"\n' "$root" >"$dir/bicycle_in_one_unit.cpp"
    sed '/= linearize_upright(/a\  int type_error = at0;' "$root/examples/bicycle_benchmark.cpp" |
      sed 's,#include ",#include "'"$root"'/examples/,' >"$dir/type_error.cpp"
  fi
  [ ! -e "$dir/type_error.cpp" ] || grep -q type_error "$dir/type_error.cpp" || rm "$dir/type_error.cpp"
}

# measure ROOT TAG "SOURCE [-D...]" [fail]: "CPU s | peak MB" of the unit compiled from ROOT; "- | -"
# where it does not exist (benchmarks/DIR/FILE is looked for as benchmarks/FILE too).
measure() {
  local root=$1 tag=$2 src=${3%% *} defs=${3#"${3%% *}"} expect=${4:-ok} extra=() file user kb
  if [ "${src:0:1}" = @ ]; then
    src=$work/$tag/${src:1}
  elif [ ! -e "$root/$src" ] && [[ $src == benchmarks/*/* ]] && [ -e "$root/benchmarks/${src##*/}" ]; then
    src=benchmarks/${src##*/}
  fi
  [[ $src == /* ]] && file=$src || file=$root/$src
  [ -e "$file" ] || { echo "- | -" && return; }
  [ "$expect" = ok ] || extra=(-Wfatal-errors)
  # shellcheck disable=SC2086  # defs: the unit's flags (-D..., -march=native)
  if (cd "$root" && /usr/bin/time -o "$work/time" -f "%U %M" "$cxx" "${flags[@]}" "${extra[@]}" $defs "$src" 2>"$work/err"); then
    [ "$expect" = ok ] || { echo "$0: $3 compiled at $root" >&2 && echo "compiled | compiled" && return; }
  elif [ "$expect" = ok ]; then
    echo "$0: $3 failed at $root:" >&2 && head -5 "$work/err" >&2 && echo "failed | failed" && return
  fi
  read -r user kb < <(tail -1 "$work/time")
  printf '%.1f | %d\n' "$user" $((kb / 1024))
}

# replace_block NAME FILE: the block "<!-- generated: NAME -->" ... "<!-- end -->" of the page, now FILE.
replace_block() {
  grep -qx "<!-- generated: $1 -->" "$page" || { echo "$0: no block $1 in $page" >&2 && exit 1; }
  awk -v name="$1" -v file="$2" '
    $0 == "<!-- generated: " name " -->" { print; while ((getline line < file) > 0) print line; skip = 1; next }
    skip && $0 == "<!-- end -->" { skip = 0 }
    !skip { print }' "$page" >"$work/page.md"
  cp "$work/page.md" "$page"
  echo "rewrote the $1 block of $page" >&2
}

machine() { echo "$(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $("$cxx" --version | head -1)"; }
commit() { echo "$(git -C "$1" rev-parse --short HEAD)$(git -C "$1" diff --quiet HEAD -- include examples tests benchmarks || echo ' with uncommitted changes')"; }

case $command in
  list)
    units "$now" ;;
  table)
    print=0
    [ "${1:-}" != --print ] || { print=1 && shift; }
    [ $# = 0 ] || print=1
    make_units "$now" now
    {
      # shellcheck disable=SC2016
      printf 'Measured on %s at commit `%s`: %s.\n\n' "$(date -u +%Y-%m-%d)" "$(commit "$now")" "$(machine)"
      echo "| unit | what | CPU s | peak MB |"
      echo "|---|---|---|---|"
      units "$now" | selected "$@" | while IFS='|' read -r src what; do
        expect=ok
        [[ $src != *" fail" ]] || { src=${src% fail} && expect=fail; }
        m=$(measure "$now" now "$src" $expect)
        echo "| \`${src#@}\` | $what | $m |"
        echo "${src#@}: $m" >&2
      done
    } >"$work/table.md"
    if [ $print = 1 ]; then cat "$work/table.md"; else replace_block compile "$work/table.md"; fi ;;
  compare)
    [ $# -ge 1 ] || usage
    before=$(git rev-parse --verify --quiet "$1^{commit}") || { echo "$0: no commit $1" >&2 && exit 2; }
    shift
    write=0
    [ "${1:-}" != --page ] || { write=1 && shift; }
    git worktree add --detach --quiet "$work/before" "$before"
    old=$work/before
    make_units "$old" old
    make_units "$now" now
    {
      # shellcheck disable=SC2016
      printf 'Measured on %s: before is `%s` (%s), now is `%s`; %s.\n\n' "$(date -u +%Y-%m-%d)" \
        "$(git rev-parse --short "$before")" "$(git log -1 --format=%cs "$before")" "$(commit "$now")" "$(machine)"
      echo "| unit | before CPU s | before peak MB | now CPU s | now peak MB | now/before CPU | now/before MB |"
      echo "|---|---|---|---|---|---|---|"
      units "$old" "$now" | selected "$@" | while IFS='|' read -r src what; do
        expect=ok
        [[ $src != *" fail" ]] || { src=${src% fail} && expect=fail; }
        a=$(measure "$old" old "$src" $expect)
        b=$(measure "$now" now "$src" $expect)
        r=$(echo "$a | $b" | awk -F' [|] ' '$1 + 0 > 0 && $3 + 0 > 0 { printf "%.2f | %.2f", $3 / $1, $4 / $2; exit } { print "- | -" }')
        echo "| \`${src#@}\` | $a | $b | $r |"
        echo "${src#@}: $a | $b | $r" >&2
      done
    } >"$work/compare.md"
    if [ $write = 1 ]; then replace_block compile-before-after "$work/compare.md"; else cat "$work/compare.md"; fi ;;
  chain)
    ns=("$@")
    [ ${#ns[@]} -gt 0 ] || ns=(6 12 24 48)
    printf '%4s %9s %9s %9s\n' n wall_s user_s peak_MB
    rows=()
    for n in "${ns[@]}"; do
      /usr/bin/time -o "$work/time" -f "%e %U %M" "$cxx" "${flags[@]}" -DKANE_CHAIN_N="$n" \
        benchmarks/chain_dynamics/chain_dynamics_kane.cpp
      read -r wall user kb < <(tail -1 "$work/time")
      printf '%4s %9s %9s %9d\n' "$n" "$wall" "$user" $((kb / 1024))
      rows+=("$n $wall $user $kb")
    done
    [ ${#rows[@]} -lt 2 ] || awk -v a="${rows[0]}" -v b="${rows[${#rows[@]} - 1]}" 'BEGIN {
      split(a, x, " "); split(b, y, " "); r = log(y[1] / x[1])
      printf "growth n^p from n = %d to %d: wall p = %.2f, user p = %.2f, peak p = %.2f\n",
        x[1], y[1], log(y[2] / x[2]) / r, log(y[3] / x[3]) / r, log(y[4] / x[4]) / r }' ;;
  *) usage ;;
esac
