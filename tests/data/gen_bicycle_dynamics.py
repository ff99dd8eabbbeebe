"""Reference numbers for the DYNAMICS of the Whipple bicycle in the conventions of kane's model
(examples/models/bicycle.hpp, extended by four rigid bodies and gravity), with the benchmark
parameters of Meijaard, Papadopoulos, Ruina, Schwab (2007), Proc. R. Soc. A 463, 1955-1982
("Linearized dynamics equations for the balance and steer of a bicycle: a benchmark and
review", doi:10.1098/rspa.2007.1857), from SymPy's KanesMethod.

Run: python3 tests/data/gen_bicycle_dynamics.py > tests/data/sympy_bicycle_dynamics.hpp
CI never runs this; the generated header is committed beside it. It imports
tests/data/gen_meijaard2007.py (Table 1 and the Appendix A formulas). Takes ~5 minutes, 4 of
them in KanesMethod.linearize.

The model (identical to kane's; C.orient_axis(P, P.a, x) turns C from P about P's axis a by x,
right-handed, as kane::simple<axis::a, x>):
  Y = N about n3 by q3 (yaw), R = Y about y1 by q4 (roll), P = R about r2 by q5 (pitch),
  H = P about p2 by p3 (the rear frame), F = H about h1 by q6 (steer, the fork), Wr spins
  relative to H about h2 at u7, Wf relative to F about f2 at u8 (wheel angles are ignorable
  and not coordinates). Cr = O + q1 n1 + q2 n2 (rear contact), Dr = Cr + p2 r3 (rear wheel
  centre), S = Dr + p6 h3, Df = S + p5 f1 + p4 f3 (front wheel centre), Cf = Df + p1 (g f2 -
  y3) / sqrt(1 - g^2), g = f2 . y3 (front contact); Br = Dr - p2 r3 and Bf = Cf are the wheels'
  material points at the contacts. u1..u6 = q1'..q6'.
  n3 points UP: Dr is p2 = rR above the ground in the upright configuration. The steer axis h1
  points DOWN and forward: h1 = sin(lambda) n1 - cos(lambda) n3 upright (lambda = pi/10, the
  benchmark's steer axis tilt; p3 = pi/2 - lambda). Forward is +n1 (Df is at w n1 + rF n3).
  Holonomic: (Cf - O) . n3 = 0 (makes the pitch q5 dependent; q5 = 0 upright).
  Nonholonomic: v(Br) . y1 = v(Br) . y2 = v(Bf) . y1 = v(Bf) . y2 = 0 and d/dt of the holonomic
  constraint (with qk' = uk); independent speeds u4, u6, u7, dependent u1, u2, u3, u5, u8.
  Bodies: rear wheel (Wr, at Dr, mass p8, central inertia diag(p9, p10, p9) in Wr = in H);
  rear frame (H, at Bo = Dr + p12 h1 + p13 h3, mass p11, inertia about Bo in H: I11 = p14,
  I22 = p15, I33 = p16, I31 = p17); front frame (F, at Ho = Df + p19 f1 + p20 f3, mass p18,
  inertia about Ho in F: p21, p22, p23, I31 = p24); front wheel (Wf, at Df, mass p25, diag(p26,
  p27, p26) in Wf = in F). I_jk = e_j . I . e_k (dyadic components). Gravity: -p7 m n3 on each
  mass centre (G = -p7 along e<N,3>, since n3 is up).

Parameters p1..p27 from Table 1 (x forward, y right, z down, origin at the rear contact,
upright): positions and inertia tensors turned into N (x, -y, -z) and then into H (= F at zero
steer) in the upright configuration, q = 0 (the pitch is 0 there: asserted). The sympy model's
own frames check the mapping: upright, Bo - O = (xB, 0, -zB), Ho - O = (xH, 0, -zH),
Df - O = (w, 0, rF), Cf - O = (w, 0, 0) in N and the inertia dyadics' N components equal
diag(1, -1, -1) I diag(1, -1, -1) of Table 1's tensors. Evaluated at 50 digits from the exact
decimals, then rounded to doubles; the header's p[] are those doubles and every number below is
computed from them exactly (mpmath, 50 digits, printed as doubles).

KanesMethod (constraint_solver="CRAMER": with "LU" the symbolic pivots give 0/0 = nan when the
operating point q = 0 is substituted into the linearization). SymPy 1.14's mass_matrix (8 x 8)
and forcing have columns / rows in the order u_ind + u_dep = (u4, u6, u7, u1, u2, u3, u5, u8):
rows 0-2 Kane's equations Fr + Fr* = 0 for the independent speeds (the dependent rows folded in
by A^T, A = du_dep/du_ind from the velocity constraints), rows 3-7 the time derivatives of the
velocity constraints. ud = mass_matrix^-1 forcing, reordered to u1'..u8'.
Reduced equations (independent speeds only): u_dep' = A u_ind' + b (rows 3-7), and rows 0-2
become Mr u_ind' = fr with Mr = K_i + K_d A, fr = f_0..2 - K_d b (K_i, K_d: rows 0-2,
independent / dependent columns), order (u4, u6, u7). Mr is the symmetric generalized mass
matrix sum m v~_r . v~_s + w~_r . I . w~_s of the nonholonomic partial velocities v~, w~.

States: 5 random ones, q1, q2 in [-2, 2], q3 in [-pi, pi], roll q4 and steer q6 in [-0.5, 0.5],
the pitch q5 solving the holonomic constraint (mpmath.findroot, from 0, at 50 digits), u4, u6
in [-1, 1] rad/s, u7 = v / rR for v in [2, 8] m/s (u7 > 0 is forward: see below), u1, u2, u3,
u5, u8 from the velocity constraints. Inputs q1..q4, q6, u4, u6, u7 are the printed doubles;
q5 and the dependent speeds are computed from them at 50 digits, then printed as doubles.
Asserted at each state: the pitch closes the constraint (1e-45); Mr is symmetric and equals
sum m v~_r . v~_s + w~_r . I . w~_s computed independently (numeric A, sympy partial
velocities), 1e-40; d(T + V)/dt = 0 along ud (the rolling constraints do no work; T from
sympy's kinetic_energy, V = p7 sum m (r . n3)), 1e-40; d/dt of the five velocity constraints
vanishes with ud, 1e-40; Mr ud_ind = fr in doubles, 1e-12.

Linearization (validation of the parameter mapping): KanesMethod.linearize(op_point, A_and_B=
True, linear_solver=solve_at_op) with symbolic parameters, about upright straight running at
speed v (symbolic); solve_at_op substitutes the operating point, simplifies and then LU-solves
(with SymPy's "LU" the A is all nan; "CRAMER" did not finish in 42 CPU minutes, tried with p6
free). Operating point: q = 0, u1 = v, u7 = v / rR, u8 = v / rF, all else and all u' 0, and p6
= (p1 - p2 - p4 cos p3 + p5 sin p3) / cos p3, the frame length that puts the front contact on
the ground at q = 0 (the benchmark's p6 is that; with p6 free, q = 0 is not a configuration and
the linearization carries 1 / (height of Df - p1) factors, 0/0 at the benchmark's values: at 50
digits such an A gave 10.0 for an entry whose value is 9.4897744467735567657). A evaluated at
50 and 80 digits agrees to 1e-40 (and so do ud, Mr, fr at the states above). State x = (q1, q2,
q3, q4, q6, u4, u6, u7). With Mr's (u4, u6) block at q = 0 as the mass matrix, K(v) = -Mr
A[u4', u6'][q4, q6] and C(v) = -Mr A[u4', u6'][u4, u6] give g K0 = K(0), K2 = K(1) - K(0), C1 =
C(1) (checked: K(2) = K(0) + 4 K2, C(0) = 0, C(2) = 2 C1), which are Meijaard's matrices for
phi = q4, delta = q6 (both lean right / steer right positive: right-handed about the forward
axis n1 / about the downward steer axis h1, like the paper's about x forward / z down; only the
product of the two signs shows in the matrices, and it is +1). Compared with gen_meijaard2007's
Appendix A values (exact parameters) and with the published 14-decimal values.
"""
import os
import random
import sys
import time
import mpmath as mp
import sympy as sp
from sympy.physics.mechanics import (ReferenceFrame, Point, RigidBody, KanesMethod, dynamicsymbols,
                                     inertia, dot, partial_velocity, msubs)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen_meijaard2007 as meijaard  # noqa: E402  (Table 1, Appendix A)

sys.setrecursionlimit(100000)
mp.mp.dps = 50
T_START = time.perf_counter()


def log(*args):
    print("gen_bicycle_dynamics.py [%5.0f s]:" % (time.perf_counter() - T_START), *args, file=sys.stderr,
          flush=True)


# ---------------------------------------------------------------------------------------------
# The model, named as in kane: p[k - 1] = kane::parameter<k>, q[k - 1] = q<k>, u[k - 1] = u<k>.
from bicycle_sympy_model import *  # noqa: E402,F401,F403  (the model, shared with gen_bicycle_sympy.py)


# ---------------------------------------------------------------------------------------------
# Parameters: Table 1 -> p1..p27.
def kane_parameters(T):
    """p1..p27 (mpmath) from Table 1 (dict of mpmath numbers, lam = steer axis tilt)."""
    w, trail, rR, rF = T["w"], T["c"], T["rR"], T["rF"]
    a = mp.pi / 2 - T["lam"]  # p3: H = P turned about p2 by a; h1 is the steer axis
    ca, sa = mp.cos(a), mp.sin(a)
    offset = rF * ca - trail * sa  # p4 = o: fork offset (perpendicular to the steer axis)
    fork = w * ca - (rF - rR) * sa  # p5 = c: along the steer axis (f1), S to the offset line
    frame = w * sa - (offset - (rF - rR) * ca)  # p6 = d: along h3, rear wheel centre to S
    # upright, in N components (n1 forward, n2 left, n3 up) = Table 1's (x, -y, -z)
    h = [mp.matrix([ca, 0, -sa]), mp.matrix([0, 1, 0]), mp.matrix([sa, 0, ca])]
    flip = mp.diag([1, -1, -1])

    def along_h(vec):  # components on h1, h3
        return [sum(vec[i] * h[k][i] for i in range(3)) for k in (0, 2)]

    def in_h(Ixx, Iyy, Izz, Ixz):  # I11, I22, I33, I31 of a Table 1 tensor, on h1, h2, h3
        I = flip * mp.matrix([[Ixx, 0, Ixz], [0, Iyy, 0], [Ixz, 0, Izz]]) * flip
        comp = lambda j, k: (h[j].T * I * h[k])[0]
        assert abs(comp(0, 1)) + abs(comp(1, 2)) < mp.mpf("1e-45")
        return [comp(0, 0), comp(1, 1), comp(2, 2), comp(2, 0)]

    Dr_, Df_ = mp.matrix([0, 0, rR]), mp.matrix([w, 0, rF])
    rear = along_h(mp.matrix([T["xB"], 0, -T["zB"]]) - Dr_)
    front = along_h(mp.matrix([T["xH"], 0, -T["zH"]]) - Df_)
    return ([rF, rR, a, offset, fork, frame, T["g"], T["mR"], T["IRxx"], T["IRyy"], T["mB"]] + rear +
            in_h(T["IBxx"], T["IByy"], T["IBzz"], T["IBxz"]) + [T["mH"]] + front +
            in_h(T["IHxx"], T["IHyy"], T["IHzz"], T["IHxz"]) + [T["mF"], T["IFxx"], T["IFyy"]])


TABLE = {k: (mp.mpf(v) if v is not None else mp.pi / 10) for k, v in meijaard.TABLE1.items()}
P_EXACT = kane_parameters(TABLE)
P_DOUBLE = [float(x) for x in P_EXACT]
P_NUM = [mp.mpf(x) for x in P_DOUBLE]  # the exact binary values of the doubles

# the mapping seen through the sympy model's frames, upright (q = 0)
up = {x: 0 for x in q}
pe = {s: sp.Float(x, 50) for s, x in zip(p, P_EXACT)}
in_n = lambda vec: [sp.N(vec.dot(e).xreplace(up).xreplace(pe), 50) for e in (N.x, N.y, N.z)]
for pt, want in ((Bo, (TABLE["xB"], 0, -TABLE["zB"])), (Ho, (TABLE["xH"], 0, -TABLE["zH"])),
                 (Df, (TABLE["w"], 0, TABLE["rF"])), (Cf, (TABLE["w"], 0, 0)), (Dr, (0, 0, TABLE["rR"]))):
    got = in_n(pt.pos_from(O))
    assert all(abs(mp.mpf(str(x)) - y) < mp.mpf("1e-45") for x, y in zip(got, want)), (pt, got)
TENSORS = [("IRxx", "IRyy", "IRxx", None), ("IBxx", "IByy", "IBzz", "IBxz"), ("IHxx", "IHyy", "IHzz", "IHxz"),
           ("IFxx", "IFyy", "IFxx", None)]
for body, (Ixx, Iyy, Izz, Ixz) in zip(bodies, TENSORS):
    tens = [[TABLE[Ixx], 0, TABLE[Ixz] if Ixz else 0], [0, TABLE[Iyy], 0],
            [TABLE[Ixz] if Ixz else 0, 0, TABLE[Izz]]]
    sgn = [1, -1, -1]
    Idy = body.central_inertia
    for i, ei in enumerate((N.x, N.y, N.z)):
        for j, ej in enumerate((N.x, N.y, N.z)):
            got = mp.mpf(str(sp.N(ei.dot(Idy.dot(ej)).xreplace(up).xreplace(pe), 50)))
            assert abs(got - sgn[i] * sgn[j] * tens[i][j]) < mp.mpf("1e-45"), (body, i, j)
assert abs(mp.mpf(str(sp.N(ground.xreplace(up).xreplace(pe), 50)))) < mp.mpf("1e-45")  # pitch 0 upright
log("parameter mapping checked")

# ---------------------------------------------------------------------------------------------
# Kane's equations and the linearization, timed.
LOAD0 = os.getloadavg()
t0 = time.perf_counter()
KM = KanesMethod(N, q_ind=[q[0], q[1], q[2], q[3], q[5]], u_ind=u_ind, kd_eqs=kd, q_dependent=[q[4]],
                 configuration_constraints=[ground], u_dependent=u_dep, velocity_constraints=nh,
                 constraint_solver="CRAMER")
t1 = time.perf_counter()
KM.kanes_equations(bodies, loads)
t2 = time.perf_counter()
log("KanesMethod(...) %.1f s, kanes_equations %.1f s" % (t1 - t0, t2 - t1))
assert list(KM.u) == u_ind + u_dep
MM, FF = KM.mass_matrix, KM.forcing
assert MM.shape == (8, 8) and FF.shape == (8, 1)
assert not MM.atoms(sp.Derivative) and not FF.atoms(sp.Derivative)

# ---------------------------------------------------------------------------------------------
# Numerical functions (mpmath).
def mpm(x):
    return mp.matrix(x.tolist()) if hasattr(x, "tolist") else x


t5 = time.perf_counter()
Mf = sp.lambdify([q, u, p], [MM, FF], modules="mpmath", cse=True)
C_nh = sp.Matrix([[sp.diff(e, x) for x in u] for e in nh])  # nh = C_nh u (linear, homogeneous)
Cf_nh = sp.lambdify([q, p], C_nh, modules="mpmath")
nh_f = sp.lambdify([q, u, p], nh, modules="mpmath")
_rq, _ru = [mp.mpf(random.random()) for _ in q], [mp.mpf(random.random()) for _ in u]
assert mp.norm(mpm(Cf_nh(_rq, P_NUM)) * mp.matrix(_ru) - mp.matrix(nh_f(_rq, _ru, P_NUM))) < mp.mpf("1e-45")
ground_f = sp.lambdify([q, p], ground, modules="mpmath")
# independent generalized mass: sum m v_j . v_k + w_j . I . w_k over all 8 speeds
vels = [(b.mass, b.masscenter.vel(N), b.frame.ang_vel_in(N), b.central_inertia) for b in bodies]
pv = [(m, partial_velocity([vv], u, N)[0], partial_velocity([w], u, N)[0], I) for m, vv, w, I in vels]
M_full = sp.Matrix(8, 8, lambda j, k: sum(m * vj[j].dot(vj[k]) + wj[j].dot(I.dot(wj[k]))
                                          for m, vj, wj, I in pv))
M_full_f = sp.lambdify([q, p], M_full, modules="mpmath", cse=True)
# energy and its rate, d/dt of the velocity constraints
Tk = sum(b.kinetic_energy(N) for b in bodies)
V = g * sum(b.mass * b.masscenter.pos_from(O).dot(N.z) for b in bodies)
ud_map = dict(zip([x.diff(t) for x in u], ud_sym))
dE = (Tk + V).diff(t).xreplace(qdu).xreplace(ud_map)
dnh = sp.Matrix(nh).diff(t).xreplace(qdu).xreplace(ud_map)
assert not sp.sympify(dE).atoms(sp.Derivative) and not dnh.atoms(sp.Derivative)
E_f = sp.lambdify([q, u, ud_sym, p], [Tk, V, dE, dnh], modules="mpmath", cse=True)
log("lambdify %.1f s" % (time.perf_counter() - t5))


def dependent_speeds(qs, ui, pp):
    """u1..u8 from q (with the pitch) and (u4, u6, u7), from the velocity constraints."""
    Cn = mpm(Cf_nh(qs, pp))
    dep, ind = [0, 1, 2, 4, 7], [3, 5, 6]
    Cd = mp.matrix([[Cn[i, j] for j in dep] for i in range(5)])
    Ci = mp.matrix([[Cn[i, j] for j in ind] for i in range(5)])
    ud_ = mp.lu_solve(Cd, -(Ci * mp.matrix(ui)))
    us = [mp.mpf(0)] * 8
    for j, x in zip(ind, ui):
        us[j] = mp.mpf(x)
    for j, x in zip(dep, ud_):
        us[j] = x
    return us, -(mp.inverse(Cd) * Ci)


def dynamics(qs, us, pp):
    """ud (u1'..u8'), Mr, fr (order u4, u6, u7) and the checks, at 50 digits."""
    Mv, fv = (mpm(x) for x in Mf(qs, us, pp))
    x = mp.lu_solve(Mv, fv)  # KM order u4, u6, u7, u1, u2, u3, u5, u8
    order = [3, 5, 6, 0, 1, 2, 4, 7]  # KM position -> speed index
    ud = [mp.mpf(0)] * 8
    for i, j in enumerate(order):
        ud[j] = x[i]
    Ki = Mv[0:3, 0:3]
    Kd = Mv[0:3, 3:8]
    Md, Mi = Mv[3:8, 3:8], Mv[3:8, 0:3]
    A = -(mp.inverse(Md) * Mi)
    b = mp.lu_solve(Md, fv[3:8, 0])
    Mr = Ki + Kd * A
    fr = fv[0:3, 0] - Kd * b
    return ud, Mr, fr, A


# ---------------------------------------------------------------------------------------------
# Step 1: random non-upright states.
random.seed(1857)
cases = []
for n in range(5):
    qs = [random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-3.14, 3.14),
          random.uniform(-0.5, 0.5), 0.0, random.uniform(-0.5, 0.5)]
    speed = random.uniform(2, 8)
    ui = [random.uniform(-1, 1), random.uniform(-1, 1), speed / P_DOUBLE[1]]
    qm = [mp.mpf(x) for x in qs]
    qm[4] = mp.findroot(lambda x: ground_f(qm[:4] + [x, qm[5]], P_NUM), mp.mpf(0), tol=mp.mpf(10) ** -90)
    assert abs(ground_f(qm, P_NUM)) < mp.mpf("1e-45")
    us, Adep = dependent_speeds(qm, ui, P_NUM)
    ud, Mr, fr, A = dynamics(qm, us, P_NUM)
    with mp.workdps(80):  # no cancellation: the same at 80 digits
        ud80, Mr80, fr80, _ = dynamics(qm, us, P_NUM)
        assert max(abs(x - y) for x, y in zip(ud, ud80)) < mp.mpf("1e-40") * (1 + max(abs(x) for x in ud))
        assert mp.mnorm(Mr80 - Mr, 1) + mp.mnorm(fr80 - fr, 1) < mp.mpf("1e-40") * mp.mnorm(Mr, 1)
    # checks
    assert mp.mnorm(A - Adep, 1) < mp.mpf("1e-40")
    assert mp.mnorm(Mr - Mr.T, 1) < mp.mpf("1e-40") * mp.mnorm(Mr, 1)
    Mfull = mpm(M_full_f(qm, P_NUM))
    At = mp.zeros(8, 3)  # u = At u_ind
    for i, j in enumerate([3, 5, 6]):
        At[j, i] = 1
    for i, j in enumerate([0, 1, 2, 4, 7]):
        for k in range(3):
            At[j, k] = Adep[i, k]
    assert mp.mnorm(At.T * Mfull * At - Mr, 1) < mp.mpf("1e-40") * mp.mnorm(Mr, 1)
    Tv, Vv, dEv, dnhv = E_f(qm, us, ud, P_NUM)
    assert abs(dEv) < mp.mpf("1e-40") * (1 + abs(Tv)), dEv
    assert mp.mnorm(mpm(dnhv), 1) < mp.mpf("1e-40")
    Mr_d = [[float(Mr[i, j]) for j in range(3)] for i in range(3)]
    ud_d = [float(ud[j]) for j in (3, 5, 6)]
    assert max(abs(sum(Mr_d[i][j] * ud_d[j] for j in range(3)) - float(fr[i])) for i in range(3)) < 1e-12
    cases.append((qm, us, ud, Mr, fr, Tv, Vv, speed))
    log("state %d: v = %.3f m/s, pitch %s, |dE/dt| %s" % (n, speed, mp.nstr(qm[4], 8), mp.nstr(abs(dEv), 2)))


# ---------------------------------------------------------------------------------------------
# Step 2: the linearization against Meijaard's matrices.
v = sp.Symbol("v")
op = {x: 0 for x in q}
op.update({x: 0 for x in u})
op.update({u[0]: v, u[6]: v / rr, u[7]: v / rf})
op.update({x.diff(t): 0 for x in u})
# q = 0 is a configuration (the front contact on the ground) only if p6 closes the loop upright;
# for other p6 the linearization has 1 / (that gap) factors, 0/0 at the benchmark's values
op[d] = (rf - rr - o * sp.cos(lam) + c * sp.sin(lam)) / sp.cos(lam)
assert abs(mp.mpf(str(sp.N(op[d].xreplace(pe), 50))) - P_EXACT[5]) < mp.mpf("1e-45")


def solve_at_op(Am, Bm):
    """The linearizer's linear solver: substitute the operating point, simplify the matrix to be
    factored (its entries are small there), then LU. C_0, C_1, C_2 (the holonomic and velocity
    constraints' Jacobians solved for the dependent q, u) are only used at the operating point.
    With linear_solver="LU" this A is all nan (symbolic LU before the substitution);
    "CRAMER" did not finish in 42 CPU minutes (tried with p6 free, see the module docstring)."""
    return msubs(Am, op).applyfunc(sp.simplify).LUsolve(msubs(Bm, op))


t3 = time.perf_counter()
A_lin, B_lin, _ = KM.linearize(op_point=op, A_and_B=True, linear_solver=solve_at_op)
t4 = time.perf_counter()
LOAD1 = os.getloadavg()
log("linearize %.1f s" % (t4 - t3))
assert A_lin.shape == (8, 8) and B_lin.shape[0] * B_lin.shape[1] == 0
assert not A_lin.has(sp.nan) and not A_lin.has(sp.zoo) and A_lin.free_symbols <= set(p) | {v}

A_f = sp.lambdify([p, v], A_lin, modules="mpmath", cse=True)


def canonical_from_linearization(pp):
    """(M, C1, K0, K2) in kane's (q4, q6), from the linearized A and Mr at q = 0."""
    q0 = [mp.mpf(0)] * 6
    u0, _ = dependent_speeds(q0, [0, 0, 1], pp)  # any speed; Mr depends on q only
    _, Mr, _, _ = dynamics(q0, u0, pp)
    Mls = Mr[0:2, 0:2]
    KC = {}
    for vv in (0, 1, 2):
        A = mpm(A_f(pp, mp.mpf(vv)))
        with mp.workdps(80):  # no cancellation: the same at 80 digits
            assert mp.mnorm(mpm(A_f(pp, mp.mpf(vv))) - A, 1) < mp.mpf("1e-40")
        assert A[3, 5] == 1 and A[4, 6] == 1  # q4' = u4, q6' = u6: x = (q1, q2, q3, q4, q6, u4, u6, u7)
        for i in (5, 6, 7):  # no coupling of lean / steer with q1..q3 and u7; u7' = 0
            for j in range(8):
                if i == 7 or j in (0, 1, 2, 7):
                    assert abs(A[i, j]) < mp.mpf("1e-40"), (vv, i, j, A[i, j])
        KC[vv] = (-(Mls * A[5:7, 3:5]), -(Mls * A[5:7, 5:7]))
    K0 = KC[0][0] / pp[6]
    K2 = KC[1][0] - KC[0][0]
    C1 = KC[1][1]
    assert mp.mnorm(KC[2][0] - KC[0][0] - 4 * K2, 1) < mp.mpf("1e-40")
    assert mp.mnorm(KC[2][1] - 2 * C1, 1) < mp.mpf("1e-40") and mp.mnorm(KC[0][1], 1) < mp.mpf("1e-40")
    # forward motion: at the operating point u7 = v / rR > 0 drives the rear contact along +n1
    uop, _ = dependent_speeds(q0, [0, 0, 1 / pp[1]], pp)
    assert abs(uop[0] - 1) < mp.mpf("1e-45") and abs(uop[7] - 1 / pp[0]) < mp.mpf("1e-45")
    assert max(abs(uop[k]) for k in (1, 2, 3, 4, 5)) < mp.mpf("1e-45")
    return Mls, C1, K0, K2


def mdev(a, b, relative=False):
    err = mp.mpf(0)
    for i in range(2):
        for j in range(2):
            e = abs(a[i, j] - b[i, j])
            if relative and b[i, j] != 0:
                e /= abs(b[i, j])
            err = max(err, e)
    return err


PUB = {k: mp.matrix([[mp.mpf(x) for x in r] for r in m]) for k, m in meijaard.PUBLISHED.items()}
APPX = dict(zip(("M", "C1", "K0", "K2"), meijaard.canonical(TABLE)))
lin = {}
for label, pp in (("exact", P_EXACT), ("double", P_NUM)):
    lin[label] = dict(zip(("M", "C1", "K0", "K2"), canonical_from_linearization(pp)))
# the sign mapping: phi = s1 q4, delta = s2 q6 turns the matrices into S X S, S = diag(s1, s2);
# only s1 s2 shows in them (the diagonal is invariant); s1 = s2 = +1 by the geometry (see above)
s12 = mp.sign(lin["exact"]["M"][0, 1] / APPX["M"][0, 1])
assert s12 == 1
agree = {}
for name in ("M", "C1", "K0", "K2"):
    agree[name] = (mdev(lin["exact"][name], APPX[name]), mdev(lin["exact"][name], PUB[name]),
                   mdev(lin["exact"][name], PUB[name], True), mdev(lin["double"][name], APPX[name], True))
    assert agree[name][0] < mp.mpf("1e-40"), (name, agree[name])
    assert agree[name][1] <= mp.mpf("0.5e-14"), (name, agree[name])
    assert agree[name][3] < 1e-14, (name, agree[name])
log("linearization vs Appendix A (exact parameters): max abs %s; vs published: max abs %s, rel %s; "
    "double parameters vs Appendix A: rel %s" % tuple(
        mp.nstr(max(a[k] for a in agree.values()), 3) for k in range(4)))

# ---------------------------------------------------------------------------------------------
def fmt(x):
    x = mp.mpf(x)
    return "%.17g" % (float(x) if abs(x) > mp.mpf("1e-30") else 0.0)


def arr(xs):
    return "{" + ", ".join(fmt(x) for x in xs) + "}"


NAMES = ["rf", "rr", "lambda (pi/2 - tilt)", "o", "c", "d", "g", "mR", "IRxx", "IRyy", "mB", "Bo . h1",
         "Bo . h3", "IB11", "IB22", "IB33", "IB31", "mH", "Ho . f1", "Ho . f3", "IH11", "IH22", "IH33",
         "IH31", "mF", "IFxx", "IFyy"]
load = "load average %.1f -> %.1f on %d CPUs" % (LOAD0[0], LOAD1[0], os.cpu_count())
out = ["// Generated by tests/data/gen_bicycle_dynamics.py (SymPy %s, mpmath %s); do not edit." % (
           sp.__version__, mp.__version__),
       "#pragma once",
       "// Whipple bicycle dynamics in kane's conventions (examples/models/bicycle.hpp plus bodies),",
       "// benchmark parameters of Meijaard, Papadopoulos, Ruina, Schwab (2007), Proc. R. Soc. A 463,",
       "// 1955-1982, Table 1. n3 up; gravity G = -p7 along e<N,3> on every mass centre; the steer axis",
       "// h1 points down (and forward); forward is +n1, u7 > 0 (u7 = v / rR, u8 = v / rF upright).",
       "// phi (the paper's lean) = q4, delta (its steer) = q6; the paper's yaw psi = -q3.",
       "// Bodies: rear wheel Wr at Dr (p8; diag(p9, p10, p9)); rear frame H at Bo = Dr + p12 h1 + p13 h3",
       "// (p11; I11 p14, I22 p15, I33 p16, I31 p17 in H); front frame F at Ho = Df + p19 f1 + p20 f3",
       "// (p18; p21..p23, I31 p24 in F); front wheel Wf at Df (p25; diag(p26, p27, p26)).",
       "// I_jk = e_j . I . e_k. The paper's I_xz turn into H's components through diag(1, -1, -1).",
       "// SymPy timings on this machine (%s):" % load,
       "//   KanesMethod(...) (solving the 5 velocity constraints, CRAMER) %.1f s, kanes_equations %.1f s,"
       % (t1 - t0, t2 - t1),
       "//   KanesMethod.linearize(A_and_B=True, symbolic parameters and v; linear solver: simplify and",
       "//   LU after substituting the operating point) about upright straight running %.1f s." % (t4 - t3),
       "// Linearization check (symbolic v): Mr's (u4, u6) block and -Mr A give Meijaard's M, C1, K0, K2",
       "// with phi = q4, delta = q6: vs Appendix A at exact parameters %s, vs the printed values %s" % (
           mp.nstr(max(a[0] for a in agree.values()), 2), mp.nstr(max(a[1] for a in agree.values()), 2)),
       "// (relative %s), with the double p[] below %s relative." % (
           mp.nstr(max(a[2] for a in agree.values()), 2), mp.nstr(max(a[3] for a in agree.values()), 2)),
       "namespace sympy_bicycle_dynamics {",
       "// p[k - 1] = kane::parameter<k>: " + ", ".join(NAMES[:9]) + ",",
       "// " + ", ".join(NAMES[9:20]) + ",",
       "// " + ", ".join(NAMES[20:]) + ".",
       "inline constexpr double p[27] = %s;" % arr(P_NUM),
       "// q[6]: q5 (pitch) solves the holonomic constraint; u[8]: u4, u6, u7 chosen, u1, u2, u3, u5, u8",
       "// from the velocity constraints (computed at 50 digits from the double inputs, then rounded).",
       "// ud[8] = u1'..u8'. Reduced equations Mr ud_ind = fr, order (u4, u6, u7), Mr symmetric.",
       "// T kinetic energy, V = p7 sum m (mass centre . n3) (constant along the motion).",
       "struct dynamics_case { double q[6], u[8], ud[8], Mr[3][3], fr[3], T, V; };",
       "inline constexpr dynamics_case cases[] = {"]
for qm, us, ud, Mr, fr, Tv, Vv, speed in cases:
    out.append("  {%s, %s, %s, {%s, %s, %s}, %s, %s, %s}," % (
        arr(qm), arr(us), arr(ud), *(arr([Mr[i, j] for j in range(3)]) for i in range(3)),
        arr([fr[i] for i in range(3)]), fmt(Tv), fmt(Vv)))
out += ["};", "}  // namespace sympy_bicycle_dynamics"]
print("\n".join(out))
log("done")
