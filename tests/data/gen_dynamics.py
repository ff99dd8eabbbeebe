"""Reference numbers for the equations of motion of two systems, from SymPy's KanesMethod
(sympy.physics.mechanics): mass matrix M and forcing f with M u' = f, and u' = M^-1 f.

Run: python3 tests/data/gen_dynamics.py > tests/data/sympy_dynamics.hpp
CI never runs this; the generated header is committed beside it.
Conventions: C.orient_axis(P, axis, angle) turns C from P about axis (right hand);
inertia(F, ixx, iyy, izz, ixy, iyz, izx) is the dyadic ixx f1f1 + ... + ixy (f1f2 + f2f1) + ...
(products enter as given, not negated), about the mass centre. Gravity is -g N.z.
Matrices row-major; M = KanesMethod.mass_matrix, f = KanesMethod.forcing.

pendulum2: 3D double pendulum. N inertial, O fixed. A = N turned about N.x by q1, B = A
turned about A.y by q2. Ao = O - lA/2 A.z (mass centre of A), P = O - lA A.z (joint),
Bo = P - lB/2 B.z (mass centre of B), Q = P - lB B.z (particle mQ). u1 = q1', u2 = q2'.
Loads: -m g N.z at Ao, Bo, Q; torque -(k q2 + c u2) A.y on B and +(k q2 + c u2) A.y on A;
drag -d v(Q in N) at Q. T kinetic energy, V = g (mA zAo + mB zBo + mQ zQ) + k q2^2 / 2
(zX = N.z component of X - O). p[21] = lA, lB, mA, mB, mQ, IA1, IA2, IA3, IA12, IA23,
IA31, IB1, IB2, IB3, IB12, IB23, IB31, g, k, c, d (IA* in A about Ao, IB* in B about Bo).
Checked against LagrangesMethod with L = T - V and the damper and drag as forces.

free_body: B.orient_body_fixed(N, (q1, q2, q3), 'zyx') (about N.z by q1, new y by q2,
newest x by q3); Bo = O + q4 N.x + q5 N.y + q6 N.z. u1..u3 = w(B in N) . b1, b2, b3,
u4..u6 = q4', q5', q6'. Loads: -m g N.z at Bo; torque t1 b1 + t2 b2 + t3 b3 on B; force
f1 N.x + f2 N.y + f3 N.z at P = Bo + a b1 + b b2 + c b3. dcm = B.dcm(N) (row i: b_i in N),
T kinetic energy, H_N = N components of the angular momentum of B about Bo (I . w).
p[17] = m, I1, I2, I3, I12, I23, I31, g, t1, t2, t3, a, b, c, f1, f2, f3 (I* in B about Bo).

Evaluated with mpmath at 40 digits (inputs are the exact printed doubles), then rounded;
entries below 1e-30 print as 0. Asserted: M symmetric positive definite, |M ud - f| < 1e-12
in doubles, and (pendulum2) M and f equal LagrangesMethod's to 1e-25.
"""
import random
import mpmath as mp
import sympy as sp
from sympy.physics.mechanics import (ReferenceFrame, Point, RigidBody, Particle, KanesMethod,
                                     LagrangesMethod, dynamicsymbols, inertia, kinetic_energy)

mp.mp.dps = 40
random.seed(1729)


def fmt(x):
    x = mp.mpf(x)
    return "%.17g" % (float(x) if abs(x) > mp.mpf("1e-30") else 0.0)


def arr(xs):
    return "{" + ", ".join(fmt(x) for x in xs) + "}"


def inertia_pars():
    return [random.uniform(0.5, 1.5) for _ in range(3)] + [random.uniform(-0.1, 0.1) for _ in range(3)]


def check_pd(I):  # I: 3 moments, 3 products (xy, yz, zx)
    mp.cholesky(mp.matrix([[I[0], I[3], I[5]], [I[3], I[1], I[4]], [I[5], I[4], I[2]]]))


def solve_and_check(Mv, fv):
    n = len(fv)
    assert mp.norm(Mv - Mv.T) < mp.mpf("1e-30")
    mp.cholesky(Mv)  # raises unless positive definite
    udv = mp.lu_solve(Mv, fv)
    Md, fd, udd = ([float(x) for x in v] for v in (Mv, fv, udv))  # doubles, row-major
    assert all(Md[i * n + j] == Md[j * n + i] for i in range(n) for j in range(n))
    assert max(abs(sum(Md[i * n + j] * udd[j] for j in range(n)) - fd[i]) for i in range(n)) < 1e-12
    return udv


t = dynamicsymbols._t
N = ReferenceFrame("N")
O = Point("O")
O.set_vel(N, 0)

# ---------------------------------------------------------------- pendulum2
q = dynamicsymbols("q1:3")
u = dynamicsymbols("u1:3")
qd = [x.diff(t) for x in q]
pp = sp.symbols("lA lB mA mB mQ IA1 IA2 IA3 IA12 IA23 IA31 IB1 IB2 IB3 IB12 IB23 IB31 g k c d")
lA, lB, mA, mB, mQ = pp[:5]
g, k, c, d = pp[17:]
A = ReferenceFrame("A")
A.orient_axis(N, N.x, q[0])
B = ReferenceFrame("B")
B.orient_axis(A, A.y, q[1])
Ao = O.locatenew("Ao", -lA / 2 * A.z)
P = O.locatenew("P", -lA * A.z)
Bo = P.locatenew("Bo", -lB / 2 * B.z)
Q = P.locatenew("Q", -lB * B.z)
for X in (Ao, P, Bo, Q):
    X.set_vel(N, X.pos_from(O).dt(N))
bA = RigidBody("bA", Ao, A, mA, (inertia(A, *pp[5:11]), Ao))
bB = RigidBody("bB", Bo, B, mB, (inertia(B, *pp[11:17]), Bo))
pQ = Particle("pQ", Q, mQ)
tq = k * q[1] + c * u[1]
loads = [(Ao, -mA * g * N.z), (Bo, -mB * g * N.z), (Q, -mQ * g * N.z),
         (B, -tq * A.y), (A, tq * A.y), (Q, -d * Q.vel(N))]
kane = KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=[qd[i] - u[i] for i in range(2)])
kane.kanes_equations([bA, bB, pQ], loads)
q2u = dict(zip(qd, u))
T = kinetic_energy(N, bA, bB, pQ)
V = g * sum(m * X.pos_from(O).dot(N.z) for m, X in ((mA, Ao), (mB, Bo), (mQ, Q))) + k * q[1] ** 2 / 2
# independent check: Lagrange's equations, L = T - V, damper and drag as generalized forces
lag = LagrangesMethod(T - V, q, forcelist=[(B, -c * qd[1] * A.y), (A, c * qd[1] * A.y),
                                           (Q, -d * Q.vel(N))], frame=N)
lag.form_lagranges_equations()
exprs = [kane.mass_matrix, kane.forcing, T.subs(q2u), V, lag.mass_matrix, lag.forcing.subs(q2u)]
assert not any(e.atoms(sp.Derivative) for e in exprs)
pend_f = sp.lambdify([q, u, pp], exprs, modules="mpmath")
pend_p = [random.uniform(0.5, 1.5) for _ in range(5)] + inertia_pars() + inertia_pars() + \
         [random.uniform(9.0, 10.0)] + [random.uniform(0.1, 2.0) for _ in range(3)]
check_pd(pend_p[5:11])
check_pd(pend_p[11:17])
pend_rows = []
for _ in range(5):
    qs = [random.uniform(-2, 2) for _ in range(2)]
    us = [random.uniform(-2, 2) for _ in range(2)]
    Mv, fv, Tv, Vv, ML, fL = pend_f(*([mp.mpf(x) for x in v] for v in (qs, us, pend_p)))
    Mv, fv, ML, fL = (mp.matrix(x.tolist()) for x in (Mv, fv, ML, fL))
    assert mp.norm(Mv - ML) < mp.mpf("1e-25") and mp.norm(fv - fL) < mp.mpf("1e-25")
    udv = solve_and_check(Mv, fv)
    pend_rows.append("  {%s, %s, %s, %s, %s, %s, %s}," % (
        arr(qs), arr(us), arr(Mv), arr(fv), arr(udv), fmt(Tv), fmt(Vv)))

# ---------------------------------------------------------------- free_body
q = dynamicsymbols("q1:7")
u = dynamicsymbols("u1:7")
qd = [x.diff(t) for x in q]
bp = sp.symbols("m I1 I2 I3 I12 I23 I31 g t1 t2 t3 a b c f1 f2 f3")
m, g = bp[0], bp[7]
Bf = ReferenceFrame("Bf")
Bf.orient_body_fixed(N, q[:3], "zyx")
w_q = Bf.ang_vel_in(N)  # in q1', q2', q3'
kd_raw = [w_q.dot(e) - ui for e, ui in zip((Bf.x, Bf.y, Bf.z), u[:3])] + \
         [qd[3 + i] - u[3 + i] for i in range(3)]
sol = sp.solve(kd_raw, qd, dict=True)[0]
kd = [qd[i] - sp.trigsimp(sol[qd[i]]) for i in range(6)]
Bf.set_ang_vel(N, u[0] * Bf.x + u[1] * Bf.y + u[2] * Bf.z)
Bo = O.locatenew("Bo", q[3] * N.x + q[4] * N.y + q[5] * N.z)
Bo.set_vel(N, u[3] * N.x + u[4] * N.y + u[5] * N.z)
Pb = Bo.locatenew("Pb", bp[11] * Bf.x + bp[12] * Bf.y + bp[13] * Bf.z)
Pb.v2pt_theory(Bo, N, Bf)
body = RigidBody("body", Bo, Bf, m, (inertia(Bf, *bp[1:7]), Bo))
loads = [(Bo, -m * g * N.z), (Bf, bp[8] * Bf.x + bp[9] * Bf.y + bp[10] * Bf.z),
         (Pb, bp[14] * N.x + bp[15] * N.y + bp[16] * N.z)]
kane = KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
kane.kanes_equations([body], loads)
H = body.angular_momentum(Bo, N)
dcm = Bf.dcm(N)
rows = sp.Matrix([[e.dot(n) for n in (N.x, N.y, N.z)] for e in (Bf.x, Bf.y, Bf.z)])
exprs = [dcm, dcm - rows, kane.mass_matrix, kane.forcing, kinetic_energy(N, body),
         sp.Matrix([H.dot(n) for n in (N.x, N.y, N.z)])]
assert not any(e.atoms(sp.Derivative) for e in exprs)
body_f = sp.lambdify([q, u, bp], exprs, modules="mpmath")
body_p = [random.uniform(0.5, 2.0)] + inertia_pars() + [random.uniform(9.0, 10.0)] + \
         [random.uniform(-1, 1) for _ in range(9)]
check_pd(body_p[1:7])
body_rows = []
for _ in range(5):
    qs = [random.uniform(-1.2, 1.2) for _ in range(3)] + [random.uniform(-2, 2) for _ in range(3)]
    us = [random.uniform(-2, 2) for _ in range(6)]
    Dv, Dr, Mv, fv, Tv, Hv = body_f(*([mp.mpf(x) for x in v] for v in (qs, us, body_p)))
    Dv, Dr, Mv, fv, Hv = (mp.matrix(x.tolist()) for x in (Dv, Dr, Mv, fv, Hv))
    assert mp.norm(Dr) < mp.mpf("1e-30")  # row i of B.dcm(N) is b_i in N
    udv = solve_and_check(Mv, fv)
    body_rows.append("  {%s, %s, %s, %s, %s, %s, %s, %s}," % (
        arr(qs), arr(us), arr(Dv), arr(Mv), arr(fv), arr(udv), fmt(Tv), arr(Hv)))

out = ["// Generated by tests/data/gen_dynamics.py (SymPy %s); do not edit." % sp.__version__,
       "#pragma once", "namespace sympy_dynamics {",
       "// pendulum2 p: lA, lB, mA, mB, mQ, IA1, IA2, IA3, IA12, IA23, IA31, "
       "IB1, IB2, IB3, IB12, IB23, IB31, g, k, c, d",
       "inline constexpr double pendulum_p[21] = %s;" % arr(pend_p),
       "struct pendulum_case { double q[2], u[2], M[4], f[2], ud[2], T, V; };  // M row-major",
       "inline constexpr pendulum_case pendulum[] = {"] + pend_rows + ["};",
       "// free_body p: m, I1, I2, I3, I12, I23, I31, g, t1, t2, t3, a, b, c, f1, f2, f3",
       "inline constexpr double body_p[17] = %s;" % arr(body_p),
       "struct body_case { double q[6], u[6], dcm[9], M[36], f[6], ud[6], T, H_N[3]; };"
       "  // dcm, M row-major",
       "inline constexpr body_case body[] = {"] + body_rows + ["};", "}  // namespace sympy_dynamics"]
print("\n".join(out))
