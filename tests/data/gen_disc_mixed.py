"""Reference numbers for the rolling disc with five coordinates (examples/models/disc.hpp)
whose velocity constraints are passed to SymPy's KanesMethod as mixtures, not one per
dependent speed: mass matrix M, forcing f (M u' = f) and ud = M^-1 f.

Run: python3 tests/data/gen_disc_mixed.py > tests/data/sympy_disc_mixed.hpp
CI never runs this; the generated header is committed beside it.
Conventions: as tests/data/gen_disc_dynamics.py (same frames N, Y, L, R, coordinates q1..q5,
speeds u1..u3 = w(R in N) . L.x, L.y, L.z, u4 = q4', u5 = q5', same kd_eqs, body, inertia
and load -m g N.z at Dc; p[3] = r, m, g). The one difference: the velocity constraints are
  c1 = 2 (v(B in N) . N.x) + (v(B in N) . N.y),  c2 = (v(B in N) . N.x) - 3 (v(B in N) . N.y),
so their Jacobian with respect to the dependent speeds (u4, u5) is [[2, 1], [1, -3]], not the
identity. u1..u3 independent, u4, u5 dependent.

M = KanesMethod.mass_matrix, f = KanesMethod.forcing, 5 x 5 and 5 x 1, row-major, columns
u1'..u5'. Rows 0-2 are Kane's dynamic equations for u1..u3; rows 3-4 are SymPy's constraint
rows C u' = -(C' u + c0'), C = d[c1, c2]/du (not normalized), so M rows 3-4 = C.

disc: 5 random states (q1, q3 in [-3, 3], q2 in [-1, 1], q4, q5 in [-2, 2], u1..u3 in
[-3, 3]); u4, u5 from the constraints. Evaluated with mpmath at 40 digits (inputs are the
exact printed doubles q, u1..u3), then rounded; entries below 1e-30 print as 0.
Asserted at 40 digits: (a) |M ud - f| < 1e-30 (and < 1e-12 in doubles); (b) u1'..u3' equal
those of the model with the plain constraints v(B in N) . N.x, . N.y to 1e-25; (c) M rows
3-4 equal the Jacobian of [c1, c2] with respect to u1..u5 to 1e-30.
"""
import random
import sys
import time
import mpmath as mp
import sympy as sp
from sympy.physics.mechanics import (ReferenceFrame, Point, RigidBody, KanesMethod,
                                     dynamicsymbols, inertia)

t_start = time.time()
mp.mp.dps = 40
random.seed(4646)


def fmt(x):
    x = mp.mpf(x)
    return "%.17g" % (float(x) if abs(x) > mp.mpf("1e-30") else 0.0)


def arr(xs):
    return "{" + ", ".join(fmt(x) for x in xs) + "}"


t = dynamicsymbols._t
q = dynamicsymbols("q1:6")
u = dynamicsymbols("u1:6")
qd = [x.diff(t) for x in q]
pp = sp.symbols("r m g")
r, m, g = pp
N, Y, L, R = (ReferenceFrame(s) for s in "NYLR")
Y.orient_axis(N, N.z, q[0])
L.orient_axis(Y, Y.x, q[1])
R.orient_axis(L, L.y, q[2])
w_q = R.ang_vel_in(N)  # in q1', q2', q3'
kd_raw = [w_q.dot(e) - ui for e, ui in zip((L.x, L.y, L.z), u[:3])] + \
         [qd[3] - u[3], qd[4] - u[4]]
sol = sp.solve(kd_raw, qd, dict=True)[0]
q2u = {x: sp.trigsimp(sol[x]) for x in qd}
kd = [x - q2u[x] for x in qd]
R.set_ang_vel(N, u[0] * L.x + u[1] * L.y + u[2] * L.z)
O = Point("O")
O.set_vel(N, 0)
C = O.locatenew("C", q[3] * N.x + q[4] * N.y)
Dc = C.locatenew("Dc", r * L.z)
Dc.set_vel(N, Dc.pos_from(O).dt(N).subs(q2u))
B = Dc.locatenew("B", -r * L.z)
B.v2pt_theory(Dc, N, R)
vx, vy = B.vel(N).dot(N.x), B.vel(N).dot(N.y)
nh_plain = [vx, vy]
nh_mixed = [2 * vx + vy, vx - 3 * vy]  # c1, c2
assert not any(sp.sympify(c).atoms(sp.Derivative) for c in nh_mixed)
Jc = sp.Matrix(nh_mixed).jacobian(u)  # 2 x 5
assert sp.simplify(Jc[:, 3:] - sp.Matrix([[2, 1], [1, -3]])) == sp.zeros(2, 2)


def kane_model(nh):
    kane = KanesMethod(N, q_ind=q, u_ind=u[:3], u_dependent=u[3:], kd_eqs=kd,
                       velocity_constraints=nh)
    disc = RigidBody("disc", Dc, R, m, (inertia(L, m * r ** 2 / 4, m * r ** 2 / 2, m * r ** 2 / 4), Dc))
    kane.kanes_equations([disc], [(Dc, -m * g * N.z)])
    Mk, fk = kane.mass_matrix, kane.forcing
    assert Mk.shape == (5, 5) and fk.shape == (5, 1)
    assert not any(e.atoms(sp.Derivative) for e in (Mk, fk))
    return Mk, fk


M_mix, f_mix = kane_model(nh_mixed)
M_pl, f_pl = kane_model(nh_plain)
udep = sp.solve(nh_mixed, u[3:], dict=True)[0]
exprs = [sp.Matrix([udep[u[3]], udep[u[4]]]), M_mix, f_mix, M_pl, f_pl, Jc]
assert not any(sp.sympify(e).atoms(sp.Derivative) for e in exprs)
disc_f = sp.lambdify([q, u, pp], exprs, modules="mpmath")


def evaluate(qs, us3, p):
    """us3 = u1..u3 (doubles); returns u (u4, u5 at 40 digits), M, f, ud (mixed model)."""
    qm, pm = [mp.mpf(x) for x in qs], [mp.mpf(x) for x in p]
    um = [mp.mpf(x) for x in us3] + [0, 0]
    um[3:] = list(disc_f(qm, um, pm)[0])
    _, Mv, fv, Mp, fp, Jv = (mp.matrix(x.tolist()) for x in disc_f(qm, um, pm))
    udv = mp.lu_solve(Mv, fv)
    assert mp.norm(Mv * udv - fv) < mp.mpf("1e-30")  # (a)
    udp = mp.lu_solve(Mp, fp)
    assert mp.norm(udp[:3] - udv[:3]) < mp.mpf("1e-25")  # (b) same dynamics
    assert max(abs(Mv[3 + i, j] - Jv[i, j]) for i in range(2) for j in range(5)) < mp.mpf("1e-30")  # (c)
    Md, fd, udd = ([float(x) for x in v] for v in (Mv, fv, udv))
    assert max(abs(sum(Md[i * 5 + j] * udd[j] for j in range(5)) - fd[i]) for i in range(5)) < 1e-12
    return um, Mv, fv, udv


par = [random.uniform(0.2, 0.6), random.uniform(0.5, 2.0), 9.81]
rows = []
for _ in range(5):
    qs = [random.uniform(-3, 3), random.uniform(-1, 1), random.uniform(-3, 3)] + \
         [random.uniform(-2, 2) for _ in range(2)]
    us = [random.uniform(-3, 3) for _ in range(3)]
    um, Mv, fv, udv = evaluate(qs, us, par)
    rows.append("  {%s, %s, %s, %s, %s}," % (arr(qs), arr(um), arr(Mv), arr(fv), arr(udv)))

out = ["// Generated by tests/data/gen_disc_mixed.py (SymPy %s); do not edit." % sp.__version__,
       "#pragma once", "namespace sympy_disc_mixed {",
       "// rolling disc, 5 coordinates (examples/models/disc.hpp); p: r, m, g",
       "inline constexpr double p[3] = %s;" % arr(par),
       "// Constraints c1 = 2 vBx + vBy, c2 = vBx - 3 vBy (vB = v(B in N) in N.x, N.y), so",
       "// dc/d(u4, u5) = [[2, 1], [1, -3]]. u[3], u[4]: dependent speeds from the constraints.",
       "// M row-major, 5 x 5, columns u1'..u5': rows 0-2 Kane's dynamic equations for u1..u3,",
       "// rows 3-4 d/dt of c1, c2 (M rows 3-4 = dc/du, not normalized). M ud = f.",
       "struct mixed_case { double q[5], u[5], M[25], f[5], ud[5]; };",
       "inline constexpr mixed_case disc[] = {"] + rows + ["};",
       "}  // namespace sympy_disc_mixed"]
print("\n".join(out))
print("gen_disc_mixed.py: %.1f s" % (time.time() - t_start), file=sys.stderr)
