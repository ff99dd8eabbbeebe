"""Reference numbers for the rolling disc with five coordinates (a nonholonomic system), from
SymPy's KanesMethod (sympy.physics.mechanics): mass matrix M and forcing f with M u' = f.

Run: python3 tests/data/gen_disc_dynamics.py > tests/data/sympy_disc_dynamics.hpp
CI never runs this; the generated header is committed beside it.
Conventions (those of examples/models/disc.hpp): C.orient_axis(P, axis, angle) turns C from P
about axis (right hand). N inertial, N.z up. Y = N turned about N.z by q1 (yaw), L = Y turned
about Y.x by q2 (lean), R = L turned about L.y by q3 (spin; R is the disc). Contact point
C = O + q4 N.x + q5 N.y, disc centre Dc = C + r L.z, the disc's point at the contact
B = Dc - r L.z. Speeds u1, u2, u3 = w(R in N) . L.x, L.y, L.z; u4 = q4', u5 = q5'; kd_eqs
q' - (q' solved from these). v(Dc in N) = d/dt (Dc - O) in N with q' substituted,
v(B in N) = v(Dc in N) + w(R in N) x (B - Dc). Constraints v(B in N) . N.x = v(B in N) . N.y = 0;
u1..u3 independent, u4, u5 dependent. Disc: mass m at Dc, inertia(L, m r^2/4, m r^2/2, m r^2/4)
about Dc (symmetric about L.y, so the same in R). Load -m g N.z at Dc, nothing else.
p[3] = r, m, g. T kinetic energy, V = m g (Dc - O) . N.z = m g r cos q2.

M = KanesMethod.mass_matrix, f = KanesMethod.forcing, 5 x 5 and 5 x 1, row-major, columns
u1'..u5'. SymPy 1.14 stacks them: rows 0-2 are Kane's dynamic equations for u1..u3
(Fr + Fr* with the dependent rows folded in by A^T, A = du_dep/du_ind); rows 3-4 are the
time derivatives of the two constraints (N.x, N.y). M is not symmetric. ud = M^-1 f.

disc: 5 random states (q1, q3 in [-3, 3], q2 in [-1, 1], q4, q5 in [-2, 2], u1..u3 in [-3, 3]);
u4, u5 from the constraints. steady: steady turning with lean q2 = theta, u1 = 0 (no lean
rate), yaw rate q1' = Omega (u3 = Omega cos theta), and u2 from the condition that u1' = 0:
u2 = sin(theta) (Omega^2 r cos(theta) - 4 g) / (6 Omega r cos(theta)) (derived below from
ud; u2' = u3' = 0 hold whenever u1 = 0). Their u1' is zero only up to the rounding of u2 to
a double (|u1'| ~ 1e-15); u4', u5' are the centripetal terms of the circling contact point.

Evaluated with mpmath at 40 digits (inputs are the exact printed doubles q, u1..u3; u4, u5,
M, f, ud, T, V are functions of those), then rounded; entries below 1e-30 print as 0.
disc3: the 3-coordinate disc's M, f and ud = M^-1 f at the same states (see below).
Asserted: |M ud - f| < 1e-12 in doubles; along the solution d(T + V)/dt = 0 (the rolling
constraints do no work) and the time derivatives of the constraints vanish, both to 1e-25,
computed from the gradients of T + V and of the constraints with ud and the kd q'; and
u1'..u3' equal those of the 3-coordinate disc (KanesMethod with q1..q3, u1..u3, the contact
point at rest and v(Dc in N) = w(R in N) x r L.z) to 1e-25.
"""
import random
import time
import mpmath as mp
import sympy as sp
from sympy.physics.mechanics import (ReferenceFrame, Point, RigidBody, KanesMethod,
                                     dynamicsymbols, inertia, kinetic_energy)

t_start = time.time()
mp.mp.dps = 40
random.seed(2718)


def fmt(x):
    x = mp.mpf(x)
    return "%.17g" % (float(x) if abs(x) > mp.mpf("1e-30") else 0.0)


def arr(xs):
    return "{" + ", ".join(fmt(x) for x in xs) + "}"


t = dynamicsymbols._t
q = dynamicsymbols("q1:6")
u = dynamicsymbols("u1:6")
qd = [x.diff(t) for x in q]
uds = sp.symbols("ud1:6")  # stand-ins for u'
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
q2u = {x: sp.trigsimp(sol[x]) for x in qd}  # q1' = u3/cos q2, q2' = u1, q3' = u2 - u3 tan q2
kd = [x - q2u[x] for x in qd]
R.set_ang_vel(N, u[0] * L.x + u[1] * L.y + u[2] * L.z)
O = Point("O")
O.set_vel(N, 0)
C = O.locatenew("C", q[3] * N.x + q[4] * N.y)
Dc = C.locatenew("Dc", r * L.z)
Dc.set_vel(N, Dc.pos_from(O).dt(N).subs(q2u))
B = Dc.locatenew("B", -r * L.z)
B.v2pt_theory(Dc, N, R)
nh = [B.vel(N).dot(N.x), B.vel(N).dot(N.y)]
assert not any(sp.sympify(c).atoms(sp.Derivative) for c in nh)
kane = KanesMethod(N, q_ind=q, u_ind=u[:3], u_dependent=u[3:], kd_eqs=kd,
                   velocity_constraints=nh)
disc = RigidBody("disc", Dc, R, m, (inertia(L, m * r ** 2 / 4, m * r ** 2 / 2, m * r ** 2 / 4), Dc))
kane.kanes_equations([disc], [(Dc, -m * g * N.z)])
Mk, fk = kane.mass_matrix, kane.forcing
assert Mk.shape == (5, 5) and fk.shape == (5, 1)
udep = sp.solve(nh, u[3:], dict=True)[0]  # u4, u5 = r (u2 - u3 tan q2) (cos q1, sin q1)
T = kinetic_energy(N, disc)
V = m * g * Dc.pos_from(O).dot(N.z)
ud_map = dict(zip([x.diff(t) for x in u], uds))
dE = (T + V).diff(t).subs(q2u).subs(ud_map)  # d(T + V)/dt given q' and u'
dnh = sp.Matrix(nh).diff(t).subs(q2u).subs(ud_map)  # d/dt of the constraints
exprs = [sp.Matrix([udep[u[3]], udep[u[4]]]), Mk, fk, T, V, dE, dnh]
assert not any(sp.sympify(e).atoms(sp.Derivative) for e in exprs)
disc_f = sp.lambdify([q, u, uds, pp], exprs, modules="mpmath")

# steady turning: u1 = 0, q2 = theta, u3 = Omega cos theta; find u2 (s) with u1' = 0
th, Om, s = sp.symbols("theta Omega s")
st = {u[0]: 0, u[1]: s, u[2]: Om * sp.cos(th)}
Ms = Mk.subs(udep).subs(st).subs(q[1], th)
fs = fk.subs(udep).subs(st).subs(q[1], th)
ud_st = sp.simplify(Ms.LUsolve(fs))
assert ud_st[1] == 0 and ud_st[2] == 0  # u2' = u3' = 0 whenever u1 = 0
s_sol = sp.solve(sp.numer(sp.together(ud_st[0])), s)
assert len(s_sol) == 1
s_st = s_sol[0]
assert sp.simplify(s_st - sp.sin(th) * (Om ** 2 * r * sp.cos(th) - 4 * g) / (6 * Om * r * sp.cos(th))) == 0
s_f = sp.lambdify([th, Om, pp], s_st, modules="mpmath")

# independent check: the 3-coordinate disc (contact at rest, v(Dc) = w(R in N) x r L.z, no
# constraints, no dependent speeds) must give the same u1'..u3'
C3 = Point("C3")
C3.set_vel(N, 0)
D3 = C3.locatenew("D3", r * L.z)
D3.v2pt_theory(C3, N, R)
kane3 = KanesMethod(N, q_ind=q[:3], u_ind=u[:3], kd_eqs=kd[:3])
disc3 = RigidBody("disc3", D3, R, m, (inertia(L, m * r ** 2 / 4, m * r ** 2 / 2, m * r ** 2 / 4), D3))
kane3.kanes_equations([disc3], [(D3, -m * g * N.z)])
disc3_f = sp.lambdify([q, u, pp], [kane3.mass_matrix, kane3.forcing], modules="mpmath")


def evaluate(qs, us3, p):
    """us3 = u1..u3 (doubles); returns u (u4, u5 at 40 digits), M, f, ud, T, V."""
    qm, pm = [mp.mpf(x) for x in qs], [mp.mpf(x) for x in p]
    um = [mp.mpf(x) for x in us3] + [0, 0]
    um[3:] = list(disc_f(qm, um, [0] * 5, pm)[0])
    _, Mv, fv, Tv, Vv, _, _ = disc_f(qm, um, [0] * 5, pm)
    Mv, fv = mp.matrix(Mv.tolist()), mp.matrix(fv.tolist())
    udv = mp.lu_solve(Mv, fv)
    _, _, _, _, _, dEv, dnhv = disc_f(qm, um, list(udv), pm)
    assert abs(dEv) < mp.mpf("1e-25"), dEv  # energy conserved
    assert mp.norm(mp.matrix(dnhv.tolist())) < mp.mpf("1e-25")  # constraints kept
    M3, f3 = (mp.matrix(x.tolist()) for x in disc3_f(qm, um, pm))
    assert mp.norm(mp.lu_solve(M3, f3) - udv[:3]) < mp.mpf("1e-25")  # = 3-coordinate disc
    Md, fd, udd = ([float(x) for x in v] for v in (Mv, fv, udv))
    assert max(abs(sum(Md[i * 5 + j] * udd[j] for j in range(5)) - fd[i]) for i in range(5)) < 1e-12
    return um, Mv, fv, udv, Tv, Vv, M3, f3


par = [random.uniform(0.2, 0.6), random.uniform(0.5, 2.0), 9.81]
disc_rows = []
disc3_rows = []
for _ in range(5):
    qs = [random.uniform(-3, 3), random.uniform(-1, 1), random.uniform(-3, 3)] + \
         [random.uniform(-2, 2) for _ in range(2)]
    us = [random.uniform(-3, 3) for _ in range(3)]
    um, Mv, fv, udv, Tv, Vv, M3, f3 = evaluate(qs, us, par)
    disc_rows.append("  {%s, %s, %s, %s, %s, %s, %s}," % (
        arr(qs), arr(um), arr(Mv), arr(fv), arr(udv), fmt(Tv), fmt(Vv)))
    disc3_rows.append("  {%s, %s, %s}," % (arr(M3), arr(f3), arr(mp.lu_solve(M3, f3))))

steady_rows = []
for _ in range(3):
    theta = random.choice((-1, 1)) * random.uniform(0.2, 0.8)
    omega = random.choice((-1, 1)) * random.uniform(0.5, 3.0)
    qs = [random.uniform(-3, 3), theta, random.uniform(-3, 3)] + [random.uniform(-2, 2) for _ in range(2)]
    us = [0.0, float(s_f(mp.mpf(theta), mp.mpf(omega), [mp.mpf(x) for x in par])),
          float(mp.mpf(omega) * mp.cos(theta))]
    um, Mv, fv, udv, Tv, Vv, _, _ = evaluate(qs, us, par)
    assert abs(udv[0]) < 1e-14 and abs(udv[1]) < 1e-30 and abs(udv[2]) < 1e-30
    steady_rows.append("  {%s, %s, %s}," % (arr(qs), arr(um), arr(udv)))

out = ["// Generated by tests/data/gen_disc_dynamics.py (SymPy %s); do not edit." % sp.__version__,
       "#pragma once", "namespace sympy_disc_dynamics {",
       "// rolling disc, 5 coordinates (examples/models/disc.hpp); p: r, m, g",
       "inline constexpr double p[3] = %s;" % arr(par),
       "// u[3], u[4]: dependent speeds from the constraints. M row-major, 5 x 5, columns u1'..u5':",
       "// rows 0-2 Kane's dynamic equations for u1..u3, rows 3-4 d/dt of the constraints",
       "// v(B in N) . N.x, . N.y. M ud = f. T kinetic energy, V = m g r cos q2.",
       "struct disc_case { double q[5], u[5], M[25], f[5], ud[5], T, V; };",
       "inline constexpr disc_case disc[] = {"] + disc_rows + ["};",
       "// The 3-coordinate disc at the states of disc (q1..q3, u1..u3): the contact point at rest,",
       "// v(Dc in N) = w(R in N) x r L.z, KanesMethod with q1..q3, u1..u3. M row-major 3 x 3, M ud = f.",
       "struct disc3_case { double M[9], f[3], ud[3]; };",
       "inline constexpr disc3_case disc3[] = {"] + disc3_rows + ["};",
       "// steady turning: q2 = theta, u1 = 0, u3 = Omega cos theta (q1' = Omega), u2 =",
       "// sin(theta) (Omega^2 r cos(theta) - 4 g) / (6 Omega r cos(theta)); ud[0..2] = 0 up to",
       "// the rounding of u[1] (|ud[0]| ~ 1e-15).",
       "struct steady_case { double q[5], u[5], ud[5]; };",
       "inline constexpr steady_case steady[] = {"] + steady_rows + ["};",
       "}  // namespace sympy_disc_dynamics"]
print("\n".join(out))
print("gen_disc_dynamics.py: %.1f s" % (time.time() - t_start), file=__import__("sys").stderr)
