"""The four small models' right-hand sides x = (q, u) -> dx/dt = (q', u')
(benchmarks/small/small_models.hpp) as SymPy gives them to a C++ user: sympy.physics.mechanics'
KanesMethod with every parameter a number, M u' = f solved symbolically, cse, cxxcode. Writes
benchmarks/small/small_sympy.cpp.

Run: python3 tests/data/gen_small_sympy.py   (SymPy 1.14)
CI never runs this; its output is committed.

The models are those of benchmarks/small/small_kane.cpp (read small_models.hpp there for the
conventions):
  top: C = N turned by q1 about n3, q2 about a1, q3 about b3 (3-1-3), u_i = ^N w^C . c_i.
  spacecraft: B oriented in N by the Euler parameters q1..q4 (scalar first, 'Quaternion'),
    Bo = O + q5 n1 + q6 n2 + q7 n3; kinematic equations ^N w^B . b_i = u_i (i = 1..3), the
    unit norm q1 q1' + q2 q2' + q3 q3' + q4 q4' = 0 and q5'..q7' = u4..u6; the wheel W turns
    about b3 by q8 with q8' = u7 (^N w^W = ^N w^B + u7 b3). q8 enters no output: the wheel's
    inertia is the same in B, and dx/dt holds q1'..q7', u1'..u7' (q8' = u7 left out).
  pendulum: A = N about n3 by q1, B = A about a3 by q2, point masses at 1.2 a1 and + 0.8 b1,
    gravity 9.81 n1, u_i = q_i'.
  pendulum_absolute: the same pendulum on absolute angles, B = N about n3 by q2.
Each model: KanesMethod(N, q, u, kd_eqs), kanes_equations(bodies, loads) with the parameters
exact rationals, u' = mass_matrix.LUsolve(forcing) and q' = KanesMethod's kindiffdict (the kinematic
equations solved for q'), as solved or simplified, whichever has fewer sin, cos and tan calls, then
fewer operations after cse (cheaper); the rationals become doubles, then one cse
over all of the model's outputs and each assignment printed by cxxcode. Each model's function has a
checked twin, what a careful user adds around generated code (benchmarks/common/checked.hpp).
"""
import os
import sys
import time

import sympy as sp
from sympy.physics.mechanics import (KanesMethod, Particle, Point, ReferenceFrame, RigidBody,
                                     dynamicsymbols, inertia)
from sympy.printing.cxx import cxxcode

T_START = time.perf_counter()
R = sp.Rational  # the parameters exact until printing: R("0.3") = 3/10


def log(*args):
    print("gen_small_sympy.py [%5.1f s]:" % (time.perf_counter() - T_START), *args, file=sys.stderr, flush=True)


def solve(name, frame, q, u, kd, bodies, loads, outputs_q):
    """KanesMethod on the model; dx/dt = (q' of outputs_q, u') as expressions of plain q_i, u_i."""
    t0 = time.perf_counter()
    km = KanesMethod(frame, q_ind=q, u_ind=u, kd_eqs=kd)
    km.kanes_equations(bodies, loads)
    assert list(km.q) == q and list(km.u) == u
    qd = km.kindiffdict()
    ud = km.mass_matrix.LUsolve(km.forcing)
    raw = [qd[x.diff()] for x in outputs_q] + list(ud)
    # factor first: simplify alone on the spacecraft's LU-solved q' (up to 3861 operations)
    # takes minutes; factor cancels them to E(q)^T w / (2 |q|^2) at once.
    simplified = [sp.simplify(sp.factor(e)) for e in raw]
    plain = {x: sp.Symbol(x.func.__name__) for x in q + u}
    rates = cheaper([e.xreplace(plain) for e in raw], [e.xreplace(plain) for e in simplified], name)
    t1 = time.perf_counter()
    log("%s: KanesMethod, kanes_equations, solved and chosen in %.2f s" % (name, t1 - t0))
    return rates


def cost(rates):
    """(sin, cos and tan calls, operations) of the rates after one cse: what the C computes."""
    temps, reduced = sp.cse(rates)
    every = [e for _, e in temps] + reduced
    calls = len(set().union(*(e.atoms(sp.sin, sp.cos, sp.tan) for e in every)))
    return calls, sum(sp.count_ops(e) for e in every)


def cheaper(raw, simplified, name):
    """The rates as solved or simplified, whichever costs the C less: simplify turns the
    pendulums' sin q1, cos q2, ... into sines of sums and double angles, more libm calls."""
    a, b = cost(raw), cost(simplified)
    log("%s: as solved %d calls, %d operations; simplified %d calls, %d operations" % (name, *a, *b))
    return raw if a < b else simplified


def doubles(e):
    """The exact rationals of e as doubles (17 significant digits), integers kept."""
    return e.xreplace({a: sp.Float(a, 17) for a in e.atoms(sp.Rational) if not a.is_Integer})


def function(name, signature, n_q, n_u, rates):
    """The C++ function: the used inputs, one cse over all outputs, cxxcode."""
    t0 = time.perf_counter()
    temps, reduced = sp.cse([doubles(e) for e in rates], symbols=sp.numbered_symbols("x"))
    t_cse = time.perf_counter() - t0
    used = set().union(*(e.free_symbols for e in reduced), *(e.free_symbols for _, e in temps))
    names = ["q%d" % (i + 1) for i in range(n_q)] + ["u%d" % (i + 1) for i in range(n_u)]
    inputs = ["%s = in.x[%d]" % (s, i) for i, s in enumerate(names) if sp.Symbol(s) in used]
    assert used <= set(sp.Symbol(s) for s in names) | set(s for s, _ in temps), used
    body = ["void small::%s(%s) {" % (name, signature)]
    body += ["  const double %s;" % ", ".join(inputs)]
    body += ["  const double %s = %s;" % (s, cxxcode(e)) for s, e in temps]
    body += ["  out.xd[%d] = %s;" % (i, cxxcode(e)) for i, e in enumerate(reduced)]
    body += ["}", ""]
    body += ["[[gnu::flatten]] void small::%s_checked(%s) { bench::checked(in, out, small::%s); }" % (name, signature, name)]
    log("%s: cse %.2f s, %d temporaries" % (name, t_cse, len(temps)))
    return body, len(temps)


t = dynamicsymbols._t
functions = []

# ---------------------------------------------------------------------------------------------
# top: the heavy symmetric top on a fixed point, 3-1-3 body-fixed angles, body rates as speeds.
q = dynamicsymbols("q1:4")
u = dynamicsymbols("u1:4")
N = ReferenceFrame("N")
A = N.orientnew("A", "Axis", (q[0], N.z))
B = A.orientnew("B", "Axis", (q[1], A.x))
C = B.orientnew("C", "Axis", (q[2], B.z))
w = C.ang_vel_in(N)
kd = [w.dot(C.x) - u[0], w.dot(C.y) - u[1], w.dot(C.z) - u[2]]
C.set_ang_vel(N, u[0] * C.x + u[1] * C.y + u[2] * C.z)
O = Point("O")
O.set_vel(N, 0)
Co = O.locatenew("Co", R("0.3") * C.z)
Co.v2pt_theory(O, N, C)
m = R("1.5")
top = RigidBody("top", Co, C, m, (inertia(C, R("0.02"), R("0.02"), R("0.035")), Co))
rates = solve("top", N, q, u, kd, [top], [(Co, -m * R("9.81") * N.z)], q)
functions.append(("top_sympy", "const top_in& in, top_out& out", 3, 3, rates))

# ---------------------------------------------------------------------------------------------
# spacecraft: a free body with Euler parameters, its mass centre's coordinates in N, a reaction
# wheel about b3 at the free speed u7.
q = dynamicsymbols("q1:9")
u = dynamicsymbols("u1:8")
N = ReferenceFrame("N")
B = ReferenceFrame("B")
B.orient_quaternion(N, q[:4])
w = B.ang_vel_in(N)
kd = [w.dot(B.x) - u[0], w.dot(B.y) - u[1], w.dot(B.z) - u[2],
      sum(x * x.diff(t) for x in q[:4]),  # the unit norm, differentiated
      q[4].diff(t) - u[3], q[5].diff(t) - u[4], q[6].diff(t) - u[5], q[7].diff(t) - u[6]]
B.set_ang_vel(N, u[0] * B.x + u[1] * B.y + u[2] * B.z)
W = B.orientnew("W", "Axis", (q[7], B.z))
W.set_ang_vel(B, u[6] * B.z)
O = Point("O")
O.set_vel(N, 0)
Bo = O.locatenew("Bo", q[4] * N.x + q[5] * N.y + q[6] * N.z)
Bo.set_vel(N, Bo.pos_from(O).dt(N))
body = RigidBody("body", Bo, B, 10, (inertia(B, R("1.2"), R("1.5"), R("1.9")), Bo))
wheel = RigidBody("wheel", Bo, W, R("0.5"), (inertia(B, R("0.01"), R("0.01"), R("0.02")), Bo))
rates = solve("spacecraft", N, q, u, kd, [body, wheel], [], q[:7])
assert not any(sp.Symbol("q8") in e.free_symbols for e in rates)
functions.append(("spacecraft_sympy", "const spacecraft_in& in, spacecraft_out& out", 7, 7, rates))

# ---------------------------------------------------------------------------------------------
# pendulum: a planar double pendulum of point masses, u = q'; B turned from A by q2 (relative),
# or from N (absolute: pendulum_absolute).
def pendulum(name, absolute):
    q = dynamicsymbols("q1:3")
    u = dynamicsymbols("u1:3")
    N = ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (q[0], N.z))
    B = (N if absolute else A).orientnew("B", "Axis", (q[1], N.z if absolute else A.z))
    kd = [q[0].diff(t) - u[0], q[1].diff(t) - u[1]]
    O = Point("O")
    O.set_vel(N, 0)
    P1 = O.locatenew("P1", R("1.2") * A.x)
    P2 = P1.locatenew("P2", R("0.8") * B.x)
    P1.v2pt_theory(O, N, A)
    P2.v2pt_theory(P1, N, B)
    m1, m2, g = 1, R("0.7"), R("9.81")
    particles = [Particle("p1", P1, m1), Particle("p2", P2, m2)]
    rates = solve(name, N, q, u, kd, particles, [(P1, m1 * g * N.x), (P2, m2 * g * N.x)], q)
    functions.append((name + "_sympy", "const pendulum_in& in, pendulum_out& out", 2, 2, rates))


pendulum("pendulum", False)
pendulum("pendulum_absolute", True)

# ---------------------------------------------------------------------------------------------
bodies, summary = [], []
for name, signature, n_q, n_u, rates in functions:
    body, n_temps = function(name, signature, n_q, n_u, rates)
    bodies += [""] + body
    summary.append("%s %d" % (name[:-6], n_temps))
lines = [
    "// Generated by tests/data/gen_small_sympy.py (SymPy %s); do not edit by hand." % sp.__version__,
    "// The four small models' right-hand sides (small_models.hpp) from sympy.physics.mechanics'",
    "// KanesMethod, the parameters numbers: u' = M^-1 f (LUsolve) and q' (kindiffdict) as solved or",
    "// simplified, whichever is cheaper; one cse per model over all its outputs, cxxcode; each with its",
    "// checked twin (../common/checked.hpp).",
]
lines += ["// cse temporaries: %s." % ", ".join(summary)]
lines += ["#include <cmath>", "", '#include "../common/checked.hpp"', '#include "small_models.hpp"'] + bodies
path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "benchmarks", "small",
                    "small_sympy.cpp")
with open(path, "w") as f:
    f.write("\n".join(lines) + "\n")
log("wrote", path)
