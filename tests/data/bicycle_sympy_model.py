"""The Whipple bicycle of kane's examples/models/bicycle.hpp (with its four bodies and gravity) in
sympy.physics.mechanics, symbol for symbol: p[k - 1] = kane::parameter<k>, q[k - 1] = q<k>,
u[k - 1] = u<k>. Shared by tests/data/gen_bicycle_dynamics.py (reference numbers) and
tests/data/gen_bicycle_sympy.py (generated C); the conventions are in the former's docstring.
"""
import sympy as sp
from sympy.physics.mechanics import ReferenceFrame, Point, RigidBody, dynamicsymbols, inertia, dot

t = dynamicsymbols._t
q = dynamicsymbols("q1:7")
u = dynamicsymbols("u1:9")
qd = [x.diff(t) for x in q]
ud_sym = sp.symbols("ud1:9")  # stand-ins for u1'..u8'
p = sp.symbols("p1:28")
(rf, rr, lam, o, c, d, g, mR, IR1, IR2, mB, xb, zb, IB11, IB22, IB33, IB31, mH, xh, zh, IH11, IH22,
 IH33, IH31, mF, IF1, IF2) = p

N, Y, R, P, H, F, Wr, Wf = (ReferenceFrame(s) for s in ("N", "Y", "R", "P", "H", "F", "Wr", "Wf"))
Y.orient_axis(N, N.z, q[2])
R.orient_axis(Y, Y.x, q[3])
P.orient_axis(R, R.y, q[4])
H.orient_axis(P, P.y, lam)
F.orient_axis(H, H.x, q[5])
# angular velocities in the speeds (uk = qk'); the wheels have only an angular velocity
Y.set_ang_vel(N, u[2] * N.z)
R.set_ang_vel(Y, u[3] * Y.x)
P.set_ang_vel(R, u[4] * R.y)
H.set_ang_vel(P, 0)
F.set_ang_vel(H, u[5] * H.x)
Wr.set_ang_vel(H, u[6] * H.y)
Wf.set_ang_vel(F, u[7] * F.y)

gy = dot(F.y, Y.z)
O = Point("O")
O.set_vel(N, 0)
Cr = O.locatenew("Cr", q[0] * N.x + q[1] * N.y)
Dr = Cr.locatenew("Dr", rr * R.z)
S = Dr.locatenew("S", d * H.z)
Df = S.locatenew("Df", c * F.x + o * F.z)
Cf = Df.locatenew("Cf", rf / sp.sqrt(1 - gy**2) * (gy * F.y - Y.z))
Bo = Dr.locatenew("Bo", xb * H.x + zb * H.z)
Ho = Df.locatenew("Ho", xh * F.x + zh * F.z)
Br = Dr.locatenew("Br", -rr * R.z)
Bf = Df.locatenew("Bf", rf / sp.sqrt(1 - gy**2) * (gy * F.y - Y.z))
Cr.set_vel(N, u[0] * N.x + u[1] * N.y)
Dr.v2pt_theory(Cr, N, R)
S.v2pt_theory(Dr, N, H)
Df.v2pt_theory(S, N, F)
Bo.v2pt_theory(Dr, N, H)
Ho.v2pt_theory(Df, N, F)
Br.v2pt_theory(Dr, N, Wr)  # the rear wheel's material point at the contact
Bf.v2pt_theory(Df, N, Wf)  # the front wheel's

qdu = dict(zip(qd, u[:6]))
ground = Cf.pos_from(O).dot(N.z)
nh = [Br.vel(N).dot(Y.x), Br.vel(N).dot(Y.y), Bf.vel(N).dot(Y.x), Bf.vel(N).dot(Y.y),
      ground.diff(t).xreplace(qdu)]
kd = [qd[k] - u[k] for k in range(6)]
u_ind, u_dep = [u[3], u[5], u[6]], [u[0], u[1], u[2], u[4], u[7]]
bodies = [RigidBody("rear_wheel", Dr, Wr, mR, (inertia(H, IR1, IR2, IR1), Dr)),
          RigidBody("rear_frame", Bo, H, mB, (inertia(H, IB11, IB22, IB33, 0, 0, IB31), Bo)),
          RigidBody("front_frame", Ho, F, mH, (inertia(F, IH11, IH22, IH33, 0, 0, IH31), Ho)),
          RigidBody("front_wheel", Df, Wf, mF, (inertia(F, IF1, IF2, IF1), Df))]
loads = [(b.masscenter, -g * b.mass * N.z) for b in bodies]
for e in nh:
    assert not sp.sympify(e).atoms(sp.Derivative)
