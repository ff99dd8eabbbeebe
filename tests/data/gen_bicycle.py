"""Reference numbers for the kinematics of the Whipple bicycle of SymPy's own test
test_bicycle (sympy/physics/mechanics/tests/test_kane3.py), rebuilt here with
sympy.physics.vector / mechanics (no KanesMethod, no inertia, no forces).

Run: python3 tests/data/gen_bicycle.py > tests/data/sympy_bicycle.hpp
CI never runs this; the generated header is committed beside it.
Frames (as in the test): N inertial, Y = N turned about N.z by q1 (yaw), R = Y turned
about Y.x by q2 (roll), Frame (rear frame) = R turned about R.y by q4 + htangle (q4 pitch),
Fork = Frame turned about Frame.x by q5 (steer). Y.z = N.z is up (gravity is -g Y.z).
Points: WR_cont (rear contact, N-velocity 0), WR_mc = WR_cont + WRrad R.z,
Steer = WR_mc + framelength Frame.z, WF_mc = Steer + forklength Fork.x + forkoffset Fork.z,
WF_cont = WF_mc + WFrad * unit(( Fork.y . Y.z) Fork.y - Y.z).
Speeds: u1 yaw rate (Y in N about Y.z), u2 roll rate (R in Y about R.x), u3 rear wheel
rate (WR in Frame about Frame.y), u4 pitch rate (Frame in R about Frame.y), u5 steer rate
(Fork in Frame about Fork.x), u6 front wheel rate (WF in Fork about Fork.y);
kd: q1' = u1, q2' = u2, q4' = u4, q5' = u5. Velocities by v2pt_theory as in the test.
Independent speeds u2, u3, u5; dependent u1, u4, u6 with [u1, u4, u6]^T = A [u2, u3, u5]^T,
from the velocity constraints v(WF_cont in N) . Y.x = . Y.y = . Y.z = 0.
Pitch q4 solves the holonomic constraint WF_cont.pos_from(WR_cont) . Y.z = 0 (nsolve from 0);
checks: its residual at the double pitch < 1e-13, the constraints with the double A < 1e-12,
and A also annihilates the time derivative of the holonomic constraint.
Nonholonomic partial velocities v~_r = dv/du_r + sum_d dv/du_d A[d][r], r in (u2, u3, u5).
Tables: A[d][r] (d over u1, u4, u6; r over u2, u3, u5); v_rear[r][i], v_front[r][i],
w_frame[r][i], w_fork[r][i] = component i in N (N.x, N.y, N.z) of the nonholonomic partial
(angular) velocity of WR_mc, WF_mc, Frame, Fork in N for independent speed r.
Parameters: the geometric values of the test's val_dict, evaluated to doubles (exact binary
values used in the 40-digit evaluation). Entries below 1e-30 (structural zeros) print as 0.
"""
import random
import mpmath
import sympy as sp
from sympy import pi, sin, cos
from sympy.physics.mechanics import ReferenceFrame, Point, dynamicsymbols, dot, partial_velocity

random.seed(2007)
q1, q2, q4, q5 = dynamicsymbols("q1 q2 q4 q5")
q1d, q2d, q4d, q5d = dynamicsymbols("q1 q2 q4 q5", 1)
u1, u2, u3, u4, u5, u6 = us = dynamicsymbols("u1:7")
WFrad, WRrad, htangle, forkoffset, forklength, framelength = pars = sp.symbols(
    "WFrad WRrad htangle forkoffset forklength framelength")

N = ReferenceFrame("N")
Y = N.orientnew("Y", "Axis", [q1, N.z])
R = Y.orientnew("R", "Axis", [q2, Y.x])
Frame = R.orientnew("Frame", "Axis", [q4 + htangle, R.y])
WR = ReferenceFrame("WR")
Fork = Frame.orientnew("Fork", "Axis", [q5, Frame.x])
WF = ReferenceFrame("WF")
WR_cont = Point("WR_cont")
WR_mc = WR_cont.locatenew("WR_mc", WRrad * R.z)
Steer = WR_mc.locatenew("Steer", framelength * Frame.z)
WF_mc = Steer.locatenew("WF_mc", forklength * Fork.x + forkoffset * Fork.z)
WF_cont = WF_mc.locatenew("WF_cont", WFrad * (dot(Fork.y, Y.z) * Fork.y - Y.z).normalize())
Y.set_ang_vel(N, u1 * Y.z)
R.set_ang_vel(Y, u2 * R.x)
WR.set_ang_vel(Frame, u3 * Frame.y)
Frame.set_ang_vel(R, u4 * Frame.y)
Fork.set_ang_vel(Frame, u5 * Fork.x)
WF.set_ang_vel(Fork, u6 * Fork.y)
WR_cont.set_vel(N, 0)
WR_mc.v2pt_theory(WR_cont, N, WR)
Steer.v2pt_theory(WR_mc, N, Frame)
WF_mc.v2pt_theory(Steer, N, Fork)
WF_cont.v2pt_theory(WF_mc, N, WF)
kd = {q1d: u1, q2d: u2, q4d: u4, q5d: u5}
conlist_speed = [(WF_cont.vel(N) & e).subs(kd) for e in (Y.x, Y.y, Y.z)]
conlist_coord = [WF_cont.pos_from(WR_cont) & Y.z]
u_ind, u_dep = [u2, u3, u5], [u1, u4, u6]
M = sp.Matrix([[sp.diff(c, u) for u in u_dep + u_ind] for c in conlist_speed])
assert sp.expand(M * sp.Matrix(u_dep + u_ind) - sp.Matrix(conlist_speed)) == sp.zeros(3, 1)
pv = partial_velocity([WR_mc.vel(N), WF_mc.vel(N), Frame.ang_vel_in(N), Fork.ang_vel_in(N)],
                      u_dep + u_ind, N)

# numeric parameters exactly as in test_kane3's val_dict, then rounded to doubles
PaperRadRear, PaperRadFront, TrailPaper, PaperWb = 0.3, 0.35, 0.08, 1.02
HTA = (pi / 2 - pi / 10).evalf()
rake = (-(TrailPaper * sin(HTA) - (PaperRadFront * cos(HTA)))).evalf()
PaperForkL = (PaperWb * cos(HTA) - (PaperRadFront - PaperRadRear) * sin(HTA)).evalf()
FrameLength = (PaperWb * sin(HTA) - (rake - (PaperRadFront - PaperRadRear) * cos(HTA))).evalf()
vals = [float(x) for x in (PaperRadFront, PaperRadRear, HTA, rake, PaperForkL, FrameLength)]
DPS = 40
mpmath.mp.dps = DPS
pm = {p: sp.Float(v, DPS) for p, v in zip(pars, vals)}  # exact binary values of the doubles
x = sp.Symbol("x")
hol = conlist_coord[0].xreplace(pm)


def num(e, m):
    return sp.N(e.xreplace(m), DPS)


def arr(xs):  # |v| < 1e-30: a structural zero left as 40-digit rounding noise, printed as 0
    return "{" + ", ".join("%.17g" % (float(v) if abs(v) > 1e-30 else 0.0) for v in xs) + "}"


def rows(m):
    return "{" + ", ".join(arr(r) for r in m) + "}"


out = ["// Generated by tests/data/gen_bicycle.py (SymPy %s); do not edit." % sp.__version__,
       "#pragma once", "namespace sympy_bicycle {",
       "// Whipple bicycle of SymPy's test_kane3.py::test_bicycle, kinematics only. Y.z = N.z up;",
       "// Frame = R turned about R.y by q4 + htangle; Fork = Frame turned about Frame.x by q5;",
       "// u3 / u6 = rear / front wheel rates relative to Frame / Fork about Frame.y / Fork.y.",
       "// Independent speeds r = (u2 roll, u3 rear wheel, u5 steer); dependent d = (u1 yaw, u4 pitch,",
       "// u6 front wheel): [u1, u4, u6]^T = A [u2, u3, u5]^T, A[d][r]. v_rear / v_front: nonholonomic",
       "// partial velocities of WR_mc / WF_mc in N; w_frame / w_fork: nonholonomic partial angular",
       "// velocities of Frame / Fork in N; [r][i] = component i on (N.x, N.y, N.z) for speed r.",
       "// pitch q4 solves WF_cont.pos_from(WR_cont) . Y.z = 0 (root nearest 0).",
       "struct parameters { double WFrad, WRrad, htangle, forkoffset, forklength, framelength; };",
       "inline constexpr parameters params = {%s};" % arr(vals)[1:-1],
       "struct sample { double yaw, roll, pitch, steer; double A[3][3]; double v_rear[3][3]; "
       "double v_front[3][3]; double w_frame[3][3]; double w_fork[3][3]; };",
       "inline constexpr sample samples[] = {"]
for _ in range(5):
    yaw, roll, steer = random.uniform(-3, 3), random.uniform(-0.6, 0.6), random.uniform(-1.0, 1.0)
    m = dict(pm)
    m.update({q1: sp.Float(yaw, DPS), q2: sp.Float(roll, DPS), q5: sp.Float(steer, DPS)})
    f = hol.xreplace(m).xreplace({q4: x})
    pitch = sp.nsolve(f, x, 0, prec=DPS, tol=sp.Float(10, DPS) ** -30)
    res = abs(num(f.xreplace({x: sp.Float(float(pitch), DPS)}), {}))
    assert res < 1e-13, res
    m[q4] = pitch
    Mn = M.xreplace(m).evalf(DPS)
    Md, Mi = (mpmath.matrix([[mpmath.mpf(v) for v in r] for r in B.tolist()]) for B in (Mn[:, :3], Mn[:, 3:]))
    A = sp.Matrix((-(mpmath.inverse(Md) * Mi)).tolist())  # rows u1, u4, u6; columns u2, u3, u5
    A = A.applyfunc(lambda v: sp.Float(v, DPS))
    Ad = sp.Matrix(3, 3, [sp.Float(float(v), DPS) for v in A])
    assert max(abs(v) for v in Mn[:, :3] * Ad + Mn[:, 3:]) < 1e-12
    dh = [num(sp.diff(hol, qq), m) for qq in (q1, q2, q4, q5)]  # d/dt of the holonomic constraint
    for r in range(3):
        assert abs(dh[0] * A[0, r] + dh[1] * int(r == 0) + dh[2] * A[1, r] + dh[3] * int(r == 2)) < 1e-25
    tabs = []
    for vecs in pv:
        comp = [[num(v.dot(e), m) for e in (N.x, N.y, N.z)] for v in vecs]  # over u_dep + u_ind
        tabs.append([[comp[3 + r][i] + sum(comp[d][i] * A[d, r] for d in range(3)) for i in range(3)]
                     for r in range(3)])
    out.append("  {%s, %s, %s, %s, %s, %s, %s, %s, %s}," % (
        "%.17g" % yaw, "%.17g" % roll, "%.17g" % float(pitch), "%.17g" % steer,
        rows(A.tolist()), *(rows(t) for t in tabs)))
out.append("};")
out.append("}  // namespace sympy_bicycle")
print("\n".join(out))
