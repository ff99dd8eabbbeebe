"""The rolling disc's forward dynamics x = (q1..q5, u1..u3) -> dx/dt = (q1'..q5', u1'..u3')
(benchmarks/disc_dynamics/disc_dynamics.hpp) as SymPy gives it to a C++ user:
sympy.physics.mechanics' KanesMethod with the parameters r, m, g symbols (they are runtime data),
Kane's reduced equations solved symbolically, simplified, cse, cxxcode. Writes
benchmarks/disc_dynamics/disc_dynamics_sympy.cpp.

Run: python3 tests/data/gen_disc_dynamics_sympy.py   (SymPy 1.14)
CI never runs this; its output is committed.

The model is the one of examples/models/disc.hpp (and gen_disc_sympy.py): Y = N rotated about
n3 by q1 (yaw), L = Y about y1 by q2 (lean), R = L about l2 by q3 (spin: the disc); contact at
q4 n1 + q5 n2, centre at contact + r l3; kinematic equations u1, u2, u3 = ^N w^R . l1, l2, l3,
u4 = q4', u5 = q5'; the R-fixed point at the contact has no velocity along n1 and n2, so u4, u5
are dependent. A uniform thin disc of mass m, inertia m r^2/4 about r1, r3 and m r^2/2 about
r2 (the dyadic in R; q3 cancels from the outputs), gravity -g n3 at the centre.

KanesMethod(N, q_ind=q1..q5, u_ind=u1..u3, kd_eqs, u_dependent=u4, u5, velocity_constraints),
kanes_equations: its mass_matrix (5 x 5) holds Kane's equations [K_i K_d] u' = f_i (rows 0-2,
the dependent rows folded in by A^T) above the differentiated constraints B_ind u_ind' +
B_dep u_dep' = f_c (rows 3-4), so u_dep' = A u_ind' + b, b = B_dep^-1 f_c, and the reduced
equations are M~ u_ind' = f~ with M~ = K_i + K_d A, f~ = f_i - K_d b (A = KanesMethod._Ars,
u_dep = A u_ind). u_ind' = M~^-1 f~ (LUsolve) and q' (KanesMethod's kindiffdict), u4, u5
replaced by A u_ind in both, each factored then simplified; then one cse over all 8 outputs
and each assignment printed by cxxcode.
"""
import os
import sys
import time

import sympy as sp
from sympy.physics.mechanics import KanesMethod, Point, ReferenceFrame, RigidBody, dynamicsymbols, inertia
from sympy.printing.cxx import cxxcode

T_START = time.perf_counter()


def log(*args):
    print("gen_disc_dynamics_sympy.py [%5.1f s]:" % (time.perf_counter() - T_START), *args, file=sys.stderr,
          flush=True)


t = dynamicsymbols._t
q = dynamicsymbols("q1:6")
u = dynamicsymbols("u1:6")
qd = [x.diff(t) for x in q]
r, m, g = sp.symbols("r m g", positive=True)  # p.r, p.m, p.g: data, not constants

N = ReferenceFrame("N")
Y = N.orientnew("Y", "Axis", (q[0], N.z))
L = Y.orientnew("L", "Axis", (q[1], Y.x))
R = L.orientnew("R", "Axis", (q[2], L.y))

# Kinematic differential equations: u1..u3 = ^N w^R . l1..l3, u4 = q4', u5 = q5'.
w = R.ang_vel_in(N)
kd = [w.dot(L.x) - u[0], w.dot(L.y) - u[1], w.dot(L.z) - u[2], qd[3] - u[3], qd[4] - u[4]]
qd_of_u = {k: sp.trigsimp(v) for k, v in sp.solve(kd, qd, dict=True)[0].items()}
R.set_ang_vel(N, u[0] * L.x + u[1] * L.y + u[2] * L.z)

O = Point("O")
O.set_vel(N, 0)
contact = O.locatenew("contact", q[3] * N.x + q[4] * N.y)
centre = contact.locatenew("centre", r * L.z)
below = centre.locatenew("below", -r * L.z)  # the point of R at the contact
centre.set_vel(N, centre.pos_from(O).dt(N).subs(qd_of_u).simplify())
below.v2pt_theory(centre, N, R)

# Rolling: the R-fixed point at the contact is at rest along n1 and n2 (u4, u5 dependent).
u_ind, u_dep = u[:3], u[3:]
nh = [below.vel(N).dot(N.x), below.vel(N).dot(N.y)]

diametral = m * r**2 / 4
disc = RigidBody("disc", centre, R, m, (inertia(R, diametral, 2 * diametral, diametral), centre))
loads = [(centre, -m * g * N.z)]

t0 = time.perf_counter()
KM = KanesMethod(N, q_ind=q, u_ind=u_ind, kd_eqs=kd, u_dependent=u_dep, velocity_constraints=nh)
KM.kanes_equations([disc], loads)
assert list(KM.q) == q and list(KM.u) == u_ind + u_dep
log("KanesMethod, kanes_equations %.2f s" % (time.perf_counter() - t0))

# Kane's reduced equations M~ u_ind' = f~ and the dependent speeds u_dep = A u_ind.
t0 = time.perf_counter()
MM, FF = KM.mass_matrix, KM.forcing
A = KM._Ars.applyfunc(sp.trigsimp)
K_i, K_d, B_dep = MM[:3, :3], MM[:3, 3:], MM[3:, 3:]
assert (MM[3:, :] - KM._k_nh).is_zero_matrix
b_acc = B_dep.LUsolve(FF[3:, 0])  # u_dep' = A u_ind' + b_acc
dep = dict(zip(u_dep, A * sp.Matrix(u_ind)))
Mr = (K_i + K_d * A).xreplace(dep)
fr = (FF[:3, 0] - K_d * b_acc).xreplace(dep)
ud = Mr.LUsolve(fr)
qdot = KM.kindiffdict()
exprs = [qdot[x].xreplace(dep) for x in qd] + list(ud)
log("reduced equations solved %.2f s" % (time.perf_counter() - t0))

# factor first, then simplify (as gen_small_sympy.py): factor cancels M~'s determinant at once.
t0 = time.perf_counter()
rates = [sp.simplify(sp.factor(e)) for e in exprs]
plain = {x: sp.Symbol(x.func.__name__) for x in q + u}
rates = [e.xreplace(plain) for e in rates]
log("simplified %.2f s" % (time.perf_counter() - t0))
for i, e in enumerate(rates):
    log("  xd[%d] = %s" % (i, e))

# One cse over all 8 outputs.
t0 = time.perf_counter()
temps, reduced = sp.cse(rates, symbols=sp.numbered_symbols("x"))
log("cse %.2f s, %d temporaries" % (time.perf_counter() - t0, len(temps)))

used = set().union(*(e.free_symbols for e in reduced), *(e.free_symbols for _, e in temps))
names = ["q%d" % (i + 1) for i in range(5)] + ["u%d" % (i + 1) for i in range(3)]
assert used <= set(sp.Symbol(s) for s in names) | {r, m, g} | set(s for s, _ in temps), used
inputs = ["%s = in.x[%d]" % (s, i) for i, s in enumerate(names) if sp.Symbol(s) in used]
params = ["%s = p.%s" % (s, s) for s in (r, m, g) if s in used]

lines = [
    "// Generated by tests/data/gen_disc_dynamics_sympy.py (SymPy %s); do not edit by hand." % sp.__version__,
    "// The rolling disc's forward dynamics (disc_dynamics.hpp) from sympy.physics.mechanics'",
    "// KanesMethod, r, m, g symbols: Kane's reduced equations M~ u_ind' = f~ solved (LUsolve) and q'",
    "// (kindiffdict, u4, u5 = A u_ind) factored and simplified, one cse over all 8 outputs, cxxcode;",
    "// its checked twin (../common/checked.hpp).",
    "// cse temporaries: %d." % len(temps),
    "#include <cmath>",
    "",
    '#include "../common/checked.hpp"',
    '#include "disc_dynamics.hpp"',
    "",
    "void disc_dynamics::sympy_rates(const input& in, output& out) {",
]
lines += ["  const double %s;" % ", ".join(inputs)]
lines += ["  const double %s;" % ", ".join(params)] if params else []
lines += ["  const double %s = %s;" % (s, cxxcode(e)) for s, e in temps]
lines += ["  out.xd[%d] = %s;" % (i, cxxcode(e)) for i, e in enumerate(reduced)]
lines += ["}", ""]
lines += ["[[gnu::flatten]] void disc_dynamics::sympy_rates_checked(const input& in, output& out) {",
          "  bench::checked(in, out, sympy_rates);", "}"]

path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "benchmarks", "disc_dynamics",
                    "disc_dynamics_sympy.cpp")
with open(path, "w") as f:
    f.write("\n".join(lines) + "\n")
log("wrote", path)
