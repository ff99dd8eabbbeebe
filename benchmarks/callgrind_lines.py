#!/usr/bin/env python3
"""Where one call of a benchmark row spends its instructions, by kane's source lines.

Usage: benchmarks/callgrind_lines.py ROW [--depth D] [--min N] [--no-build]
  ROW: a row of a bench-o2 binary, such as disc_dynamics/forward/kane.
  Builds the row's binary as the bench-o2 preset does, with -g added (build/bench-o2-g; -g leaves
  the code as it is), runs the row under callgrind as callgrind_rows.sh does, and folds each
  executed instruction's inlined call chain (addr2line -i) from the first frame in include/kane/
  down to D frames (default 4). It prints the instructions per call of each fold of N or more
  (default 3), as a tree; a library's instructions are folded under its name.
Needs valgrind, binutils and what the benchmarks need.
"""
import argparse
import collections
import os
import re
import subprocess
import sys
import tempfile

top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def build(group):
    out = os.path.join(top, "build", "bench-o2-g")
    run = lambda *a: subprocess.run(a, cwd=top, check=True, stdout=subprocess.DEVNULL)
    run("cmake", "--preset", "bench-o2", "-B", out, "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -g -DNDEBUG")
    run("cmake", "--build", out, "--target", "bench_" + group)
    return os.path.join(out, "benchmarks", "bench_" + group)


def profile(binary, row, cg):
    subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + cg, "--dump-instr=yes",
                    "--compress-strings=no", "--compress-pos=no", "--toggle-collect=*bench::run<*",
                    binary, "--benchmark_filter=^" + row + "$", "--benchmark_min_time=0.05"],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def costs(cg):
    """Ir by (object, address) outside the call lines, and the calls of F from bench::run."""
    ir = collections.Counter()
    calls = collections.Counter()
    ob = fn = callee = None
    skip = False
    for line in open(cg):
        if skip:  # the inclusive cost of a call
            skip = False
            if fn and "bench::run<" in fn:
                calls[callee] += count
            continue
        if line.startswith("ob="):
            ob = line[3:].strip()
        elif line.startswith("fn="):
            fn = line[3:].strip()
        elif line.startswith("cfn="):
            callee = line[4:].strip()
        elif line.startswith("calls="):
            count = int(line[6:].split()[0])
            skip = True
        elif re.match(r"^0x[0-9a-f]+ ", line):
            address, value = line.split()[0], line.split()[-1]
            ir[(ob, int(address, 16), fn)] += int(value)
    return ir, max(calls.values())


def chains(binary, addresses):
    out = subprocess.run(["addr2line", "-a", "-i", "-e", binary] + [hex(a) for a in addresses],
                         capture_output=True, text=True, check=True).stdout.splitlines()
    result, current = {}, None
    for line in out:
        if line.startswith("0x"):
            current = int(line, 16)
            result[current] = []
        else:
            result[current].append(line.split(" ")[0])
    return result


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("row")
    p.add_argument("--depth", type=int, default=4)
    p.add_argument("--min", type=float, default=3)
    p.add_argument("--no-build", action="store_true")
    a = p.parse_args()
    group = a.row.split("/")[0]
    binary = os.path.join(top, "build", "bench-o2-g", "benchmarks", "bench_" + group)
    if not a.no_build:
        binary = build(group)
    with tempfile.TemporaryDirectory() as work:
        cg = os.path.join(work, "callgrind.out")
        profile(binary, a.row, cg)
        ir, calls = costs(cg)
    own = {k for k in ir if k[0] and os.path.realpath(k[0]) == os.path.realpath(binary)}
    where = chains(binary, sorted({k[1] for k in own}))
    tree = collections.Counter()
    for key, value in ir.items():
        if key in own:
            frames = list(reversed(where.get(key[1], [])))  # outermost first
            first = next((i for i, f in enumerate(frames) if "/include/kane/" in f), None)
            frames = ["(outside kane) " + os.path.basename(frames[-1] if frames else "?")] if first is None \
                else [f.split("/include/")[-1] for f in frames[first:]]
        else:
            frames = [os.path.basename(key[0] or "?")]
        for d in range(1, a.depth + 1):
            if d <= len(frames):
                tree[tuple(frames[:d])] += value
    total = sum(ir.values())
    print(f"{a.row}: {total / calls:.0f} instructions per call ({calls} calls)")
    for k in sorted(tree):
        per_call = tree[k] / calls
        if per_call >= a.min:
            print(f"{'  ' * (len(k) - 1)}{per_call:7.1f} {k[-1]}")


if __name__ == "__main__":
    sys.exit(main())
