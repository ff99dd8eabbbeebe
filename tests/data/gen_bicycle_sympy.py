"""The Whipple bicycle's forward dynamics and its linearization (benchmarks/bicycle/bicycle.hpp)
as SymPy gives them to a C++ user: sympy.physics.mechanics' KanesMethod, cse, cxxcode. Writes
benchmarks/bicycle/bicycle_sympy.cpp.

Run: python3 tests/data/gen_bicycle_sympy.py   (SymPy 1.14)
CI never runs this; its output is committed.

The model is the one of examples/models/bicycle.hpp with its bodies, as built in
tests/data/gen_bicycle_dynamics.py (copied below; read that file's docstring for the
conventions): parameters p1..p27, coordinates q1..q6 (the pitch q5 dependent through the
holonomic constraint "ground"), speeds u1..u6 = q', u7, u8 the wheels' spin rates, the five
velocity constraints "rolling" with u4, u6, u7 independent.

(a) Forward dynamics at any state (q1..q6 with the pitch closed, u4, u6, u7):
  KanesMethod(..., constraint_solver="CRAMER"), kanes_equations. Its A (u_dep = A u_ind, 5 x 3,
  KanesMethod._Ars, solved by Cramer's rule) gives the dependent speeds u1, u2, u3, u5, u8. Kane's
  reduced equations Mr u_ind' = fr are formed symbolically from KanesMethod's mass_matrix and
  forcing: rows 0-2 (Kane's equations, the dependent rows folded in by A^T) are
  [K_i K_d] u' = f_i, rows 3-7 (the differentiated velocity constraints) B_ind u_ind' +
  B_dep u_dep' = f_c, so u_dep' = A u_ind' + b, b = B_dep^-1 f_c (Cramer's rule, symbolic),
  Mr = K_i + K_d A (3 x 3, the 6 entries of its upper triangle), fr = f_i - K_d b.
  Code: sin and cos of the coordinates and of p3 become plain symbols; one cse over the dependent
  speeds (inputs: q, u_ind, p), one over Mr and fr (inputs: q, all u, p), printed by cxxcode;
  the symmetric 3 x 3 system is solved in C by its adjugate (Cramer's rule).
(b) The linearization A (8 x 8) of x = (q1, q2, q3, q4, q6, u4, u6, u7) at any state, the pitch
  eliminated through the holonomic constraint (dq5 = -(df/dq5)^-1 df/dq_ind dq_ind, as kane's
  linearize_constrained): KanesMethod.to_linearizer(linear_solver="CRAMER").linearize(
  A_and_B=False) without an operating point gives M dx = Amat x with M (14 x 14) and Amat
  (14 x 8) symbolic in q, u and u'; one cse over both, cxxcode, and in C: the dependent speeds
  and the accelerations u' at the state (as in (a), with u_dep' = A u_ind' + b), M and Amat,
  then M^-1 Amat by Gaussian elimination with partial pivoting and the rows of the independent
  states (what linearize(A_and_B=True) would do with a symbolic solve).
  BICYCLE_LINEARIZATION_CACHE=file keeps (M, Amat) in a pickle to rerun the printing alone.
"""
import os
import pickle
import sys
import time

import sympy as sp
from sympy.physics.mechanics import (ReferenceFrame, Point, RigidBody, KanesMethod, dynamicsymbols,
                                     inertia, dot)
from sympy.printing.cxx import cxxcode

sys.setrecursionlimit(100000)
T_START = time.perf_counter()


def log(*args):
    print("gen_bicycle_sympy.py [%5.0f s]:" % (time.perf_counter() - T_START), *args, file=sys.stderr,
          flush=True)


# The model, named as in kane: p[k - 1] = kane::parameter<k>, q[k - 1] = q<k>, u[k - 1] = u<k>.
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bicycle_sympy_model import *  # noqa: E402,F401,F403  (the model of gen_bicycle_dynamics.py)


# ---------------------------------------------------------------------------------------------
# Printing helpers: plain symbols for q, u; sin and cos of the coordinates and of p3 as symbols
# computed once at the top (a call in the middle would not be merged by the compiler).
Q = sp.symbols("q1:7")
U = sp.symbols("u1:9")
plain = dict(zip(q, Q))
plain.update(zip(u, U))
TRIG = {}
for x in list(Q) + [lam]:
    TRIG[sp.sin(x)] = sp.Symbol("s_" + str(x))
    TRIG[sp.cos(x)] = sp.Symbol("c_" + str(x))


def to_plain(e):
    return sp.sympify(e).xreplace(plain).xreplace(TRIG)


def with_trig_arguments(used):
    return used | {f.args[0] for f, s in TRIG.items() if s in used}


def trig_lines(used):
    out = []
    for f, s in TRIG.items():
        if s in used:
            out.append("  const double %s = std::%s(%s);" % (s, f.func.__name__, f.args[0]))
    return out


def cse_lines(exprs, prefix):
    """cse of exprs: the lines of the temporaries, the reduced expressions, the cse time."""
    t0 = time.perf_counter()
    temps, reduced = sp.cse(exprs, symbols=sp.numbered_symbols(prefix))
    t1 = time.perf_counter()
    lines = ["  const double %s = %s;" % (s, cxxcode(e)) for s, e in temps]
    return lines, reduced, t1 - t0, temps


def free(exprs):
    return set().union(*(sp.sympify(e).free_symbols for e in exprs))


def count(temps, reduced):
    return sum(sp.count_ops(e) for _, e in temps) + sum(sp.count_ops(e) for e in reduced)


LOAD0 = os.getloadavg()
# ---------------------------------------------------------------------------------------------
# (a) Kane's equations and the reduced 3 x 3 system, symbolic.
t0 = time.perf_counter()
KM = KanesMethod(N, q_ind=[q[0], q[1], q[2], q[3], q[5]], u_ind=u_ind, kd_eqs=kd, q_dependent=[q[4]],
                 configuration_constraints=[ground], u_dependent=u_dep, velocity_constraints=nh,
                 constraint_solver="CRAMER")
t1 = time.perf_counter()
KM.kanes_equations(bodies, loads)
t2 = time.perf_counter()
T_KM, T_KANE = t1 - t0, t2 - t1
log("KanesMethod(...) %.1f s, kanes_equations %.1f s" % (T_KM, T_KANE))
assert list(KM.u) == u_ind + u_dep
MM, FF = KM.mass_matrix, KM.forcing
Ars = KM._Ars  # u_dep = Ars u_ind (5 x 3), Cramer's rule on the velocity constraints
K_i, K_d, B_ind, B_dep = MM[:3, :3], MM[:3, 3:], MM[3:, :3], MM[3:, 3:]
assert (B_ind - KM._k_nh[:, :3]).is_zero_matrix and (B_dep - KM._k_nh[:, 3:]).is_zero_matrix
b_acc = B_dep.solve(FF[3:, 0], method="CRAMER")  # u_dep' = Ars u_ind' + b_acc
Mr = K_i + K_d * Ars
fr = FF[:3, 0] - K_d * b_acc
t3 = time.perf_counter()
T_REDUCE = t3 - t2
log("reduced equations (symbolic Mr, fr) %.1f s" % T_REDUCE)

udep_exprs = [to_plain(e) for e in Ars * sp.Matrix(u_ind)]  # u1, u2, u3, u5, u8
dyn_exprs = [to_plain(Mr[i, j]) for i, j in ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))]
dyn_exprs += [to_plain(fr[i]) for i in range(3)]
t4 = time.perf_counter()
lines_u, red_u, T_CSE_U, temps_u = cse_lines(udep_exprs, "a")
lines_d, red_d, T_CSE_D, temps_d = cse_lines(dyn_exprs, "x")
log("cse: dependent speeds %.1f s (%d temporaries), Mr and fr %.1f s (%d temporaries)" % (
    T_CSE_U, len(temps_u), T_CSE_D, len(temps_d)))
OPS_A = count(temps_u, red_u) + count(temps_d, red_d)
used_a = with_trig_arguments(free(red_u + red_d) | free([e for _, e in temps_u + temps_d]))
rates_body = ["  const double %s;" % ", ".join(
    ["q%d = in.x[%d]" % (i + 1, i) for i in range(6) if Q[i] in used_a] +
    ["u%d = in.x[%d]" % (k, 6 + j) for j, k in enumerate((4, 6, 7))])]
rates_body += ["  const double %s;" % ", ".join("p%d = p[%d]" % (k + 1, k) for k in range(27) if p[k] in used_a)]
rates_body += trig_lines(used_a)
rates_body += ["  // the dependent speeds u_dep = A u_ind (Cramer's rule on the velocity constraints)"]
rates_body += lines_u
rates_body += ["  const double %s = %s;" % (n, cxxcode(e)) for n, e in zip(("u1", "u2", "u3", "u5", "u8"), red_u)]
rates_body += ["  // Kane's reduced equations Mr u_ind' = fr (Mr symmetric: its upper triangle)"]
rates_body += lines_d
rates_body += ["  const double %s = %s;" % (n, cxxcode(e))
               for n, e in zip(("m11", "m12", "m13", "m22", "m23", "m33", "f1", "f2", "f3"), red_d)]
rates_body += [
    "  // the adjugate of the symmetric Mr (Cramer's rule)",
    "  const double c11 = m22 * m33 - m23 * m23, c12 = m13 * m23 - m12 * m33, c13 = m12 * m23 - m13 * m22;",
    "  const double c22 = m11 * m33 - m13 * m13, c23 = m12 * m13 - m11 * m23, c33 = m11 * m22 - m12 * m12;",
    "  const double inv = 1 / (m11 * c11 + m12 * c12 + m13 * c13);",
    "  out.xd[0] = u1, out.xd[1] = u2, out.xd[2] = u3, out.xd[3] = u4, out.xd[4] = u5, out.xd[5] = u6;",
    "  out.xd[6] = (c11 * f1 + c12 * f2 + c13 * f3) * inv;",
    "  out.xd[7] = (c12 * f1 + c22 * f2 + c23 * f3) * inv;",
    "  out.xd[8] = (c13 * f1 + c23 * f2 + c33 * f3) * inv;"]
if U[7] not in used_a:
    rates_body += ["  (void)u8;"]
log("(a) printed: %d operations after cse" % OPS_A)

# ---------------------------------------------------------------------------------------------
# (b) The linearization at any state: KanesMethod's Linearizer (linear_solver="CRAMER"),
# linearize(A_and_B=False) without an operating point gives M dx = Amat x symbolically, dx the
# rates of all 14 states (q1, q2, q3, q4, q6, q5, u4, u6, u7, u1, u2, u3, u5, u8: KanesMethod's
# order), x = (q1, q2, q3, q4, q6, u4, u6, u7); M (14 x 14) and Amat (14 x 8) hold q, all u and
# all u' (the accelerations at the state). A = rows (0-4, 6-8) of M^-1 Amat, what
# linearize(A_and_B=True) returns after a symbolic solve (the solve is left to C here, as a
# user of the generated code would: the symbolic 14 x 14 solve at any state is out of reach).
t5 = time.perf_counter()
CACHE = os.environ.get("BICYCLE_LINEARIZATION_CACHE")  # a pickle of (Ml, Al), to rerun the printing
if CACHE and os.path.exists(CACHE):
    with open(CACHE, "rb") as f:
        Ml, Al = pickle.load(f)
else:
    linearizer = KM.to_linearizer(linear_solver="CRAMER")
    Ml, Al, _ = linearizer.linearize(A_and_B=False)
    if CACHE:
        with open(CACHE, "wb") as f:
            pickle.dump((Ml, Al), f)
t6 = time.perf_counter()
T_LIN = t6 - t5
assert Ml.shape == (14, 14) and Al.shape == (14, 8)
log("to_linearizer + linearize(A_and_B=False) at any state %.1f s" % T_LIN)
UD = sp.symbols("ud1:9")
dmap = {u[k].diff(t): UD[k] for k in range(8)}
lin_exprs = [to_plain(e.xreplace(dmap)) for e in list(Ml) + list(Al)]
allowed = set(Q) | set(U) | set(UD) | set(p) | set(TRIG.values())
assert free(lin_exprs) <= allowed, free(lin_exprs) - allowed
t7 = time.perf_counter()
T_PLAIN_LIN = t7 - t6
log("plain symbols %.1f s" % T_PLAIN_LIN)
lines_L, red_L, T_CSE_L, temps_L = cse_lines(lin_exprs, "y")
OPS_LIN = count(temps_L, red_L)
log("cse of M and Amat %.1f s (%d temporaries, %d operations)" % (T_CSE_L, len(temps_L), OPS_LIN))

# the accelerations at the state: A of the constraints, u_dep, Mr, fr, b (u_dep' = A u_ind' + b)
ars_exprs = [to_plain(Ars[i, j]) for i in range(5) for j in range(3)]
lines_r, red_r, _, temps_r = cse_lines(ars_exprs, "a")
acc_exprs = dyn_exprs + [to_plain(e) for e in b_acc]
lines_c, red_c, T_CSE_C, temps_c = cse_lines(acc_exprs, "x")
used_L = with_trig_arguments(free(red_L + red_r + red_c) | free([e for _, e in temps_L + temps_r + temps_c]))
dep = ("u1", "u2", "u3", "u5", "u8")
A_BODY = ["void bicycle::sympy_A(const input& in, linear& out) {"]
A_BODY += ["  const double %s;" % ", ".join(
    ["q%d = in.x[%d]" % (i + 1, i) for i in range(6) if Q[i] in used_L] +
    ["u%d = in.x[%d]" % (k, 6 + j) for j, k in enumerate((4, 6, 7))])]
A_BODY += ["  const double %s;" % ", ".join("p%d = p[%d]" % (k + 1, k) for k in range(27) if p[k] in used_L)]
A_BODY += trig_lines(used_L)
A_BODY += ["  // A of the velocity constraints (u_dep = A u_ind), the dependent speeds"] + lines_r
A_BODY += ["  const double ar[5][3] = {%s};" % ", ".join(
    "{%s}" % ", ".join(cxxcode(red_r[3 * i + j]) for j in range(3)) for i in range(5))]
A_BODY += ["  const double %s = ar[%d][0] * u4 + ar[%d][1] * u6 + ar[%d][2] * u7;" % (n, i, i, i)
           for i, n in enumerate(dep)]
A_BODY += ["  // the accelerations: Mr u_ind' = fr, u_dep' = A u_ind' + b"] + lines_c
ud_used = [n for k, n in enumerate(dep) if UD[int(n[1:]) - 1] in used_L]
A_BODY += ["  const double %s = %s;" % (n, cxxcode(e)) for n, e in zip(
    ("m11", "m12", "m13", "m22", "m23", "m33", "f1", "f2", "f3", "b1", "b2", "b3", "b5", "b8"), red_c)
    if n[0] != "b" or "u" + n[1:] in ud_used]
A_BODY += [
    "  const double c11 = m22 * m33 - m23 * m23, c12 = m13 * m23 - m12 * m33, c13 = m12 * m23 - m13 * m22;",
    "  const double c22 = m11 * m33 - m13 * m13, c23 = m12 * m13 - m11 * m23, c33 = m11 * m22 - m12 * m12;",
    "  const double inv = 1 / (m11 * c11 + m12 * c12 + m13 * c13);",
    "  const double ud4 = (c11 * f1 + c12 * f2 + c13 * f3) * inv;",
    "  const double ud6 = (c12 * f1 + c22 * f2 + c23 * f3) * inv;",
    "  const double ud7 = (c13 * f1 + c23 * f2 + c33 * f3) * inv;"]
A_BODY += ["  const double u%s = ar[%d][0] * ud4 + ar[%d][1] * ud6 + ar[%d][2] * ud7 + b%s;" % (
    "d" + n[1:], i, i, i, n[1:]) for i, n in enumerate(dep) if n in ud_used]
A_BODY += ["  // Linearizer's M dx = Amat x (14 x 14, 14 x 8)"] + lines_L
A_BODY += ["  double m[14][14] = {%s};" % ", ".join(
    "{%s}" % ", ".join(cxxcode(red_L[14 * i + j]) for j in range(14)) for i in range(14))]
A_BODY += ["  double r[14][8] = {%s};" % ", ".join(
    "{%s}" % ", ".join(cxxcode(red_L[196 + 8 * i + j]) for j in range(8)) for i in range(14))]
A_BODY += [
    "  // M^-1 Amat: Gaussian elimination with partial pivoting",
    "  for (int k = 0; k < 14; ++k) {",
    "    int piv = k;",
    "    for (int i = k + 1; i < 14; ++i)",
    "      if (std::fabs(m[i][k]) > std::fabs(m[piv][k])) piv = i;",
    "    if (piv != k) {",
    "      for (int j = 0; j < 14; ++j) std::swap(m[k][j], m[piv][j]);",
    "      for (int j = 0; j < 8; ++j) std::swap(r[k][j], r[piv][j]);",
    "    }",
    "    for (int i = k + 1; i < 14; ++i) {",
    "      const double l = m[i][k] / m[k][k];",
    "      if (l == 0) continue;",
    "      for (int j = k + 1; j < 14; ++j) m[i][j] -= l * m[k][j];",
    "      for (int j = 0; j < 8; ++j) r[i][j] -= l * r[k][j];",
    "    }",
    "  }",
    "  for (int k = 13; k >= 0; --k)",
    "    for (int j = 0; j < 8; ++j) {",
    "      double x = r[k][j];",
    "      for (int i = k + 1; i < 14; ++i) x -= m[k][i] * r[i][j];",
    "      r[k][j] = x / m[k][k];",
    "    }",
    "  const int rows[8] = {0, 1, 2, 3, 4, 6, 7, 8};  // q1', q2', q3', q4', q6', u4', u6', u7'",
    "  for (int i = 0; i < 8; ++i)",
    "    for (int j = 0; j < 8; ++j) out.A[8 * i + j] = r[rows[i]][j];",
    "}"]
A_HEADER = [
    "// The linearization at any state: KanesMethod.to_linearizer(linear_solver=\"CRAMER\") and",
    "//   linearize(A_and_B=False) %.1f s, plain symbols %.1f s, cse %.1f s (%d temporaries," % (
        T_LIN, T_PLAIN_LIN, T_CSE_L, len(temps_L)),
    "//   %d operations) of M (14 x 14) and Amat (14 x 8); A = rows of M^-1 Amat, solved in C." % OPS_LIN,
]
A_HEADER += ["//   The accelerations it needs: cse %.1f s (%d temporaries)." % (T_CSE_C, len(temps_c))]

# ---------------------------------------------------------------------------------------------
LOAD1 = os.getloadavg()
T_TOTAL = time.perf_counter() - T_START
lines = [
    "// Generated by tests/data/gen_bicycle_sympy.py (SymPy %s); do not edit by hand." % sp.__version__,
    "// The Whipple bicycle's forward dynamics (bicycle.hpp) from sympy.physics.mechanics'",
    "// KanesMethod: the dependent speeds from its A (Cramer's rule), Kane's reduced equations",
    "// Mr u_ind' = fr formed symbolically, cse, cxxcode; the 3 x 3 system solved by its adjugate.",
    "// SymPy wall times on this machine (load average %.1f -> %.1f on %d CPUs):" % (
        LOAD0[0], LOAD1[0], os.cpu_count()),
    "//   KanesMethod(...) %.1f s, kanes_equations %.1f s, reduced Mr, fr %.1f s," % (T_KM, T_KANE, T_REDUCE),
    "//   cse %.1f s (dependent speeds, %d temporaries) + %.1f s (Mr, fr, %d temporaries);" % (
        T_CSE_U, len(temps_u), T_CSE_D, len(temps_d)),
    "//   %d operations (sympy count_ops) after cse." % OPS_A,
]
lines += A_HEADER if A_BODY else []
lines += ["// The whole generator ran %.0f s." % T_TOTAL,
          "#include <cmath>", "#include <utility>", "", '#include "bicycle.hpp"', "",
          "void bicycle::sympy_rates(const input& in, rates& out) {"] + rates_body + ["}", ""]
lines += A_BODY if A_BODY else [
    "void bicycle::sympy_A(const input&, linear& out) {",
    "  for (double& a : out.A) a = 0;  // not generated",
    "}"]
path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "benchmarks", "bicycle",
                    "bicycle_sympy.cpp")
with open(path, "w") as f:
    f.write("\n".join(lines) + "\n")
log("wrote", path)
