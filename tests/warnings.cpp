// The whole public API instantiated in float or double, checked with -fsyntax-only under
//   -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion -Wold-style-cast -Werror
// by the suite's compiler in float and by clang++ in double when found (tests warnings.<compiler>).
// Nothing runs: the explicit instantiations at the end instantiate every body.
#include <array>
#include <cstddef>
#include <sstream>
#include <string>

#include <kane/kane.hpp>
#include <kane/print.hpp>

#include "../examples/models/arm6.hpp"
#include "../examples/models/bicycle.hpp"
#include "../examples/models/disc.hpp"
#include "../examples/models/fourbar.hpp"
#include "../examples/models/free_body.hpp"
#include "../examples/models/pendulum3d.hpp"

// Globals with the short names a model uses: no local of a header shadows them (-Wshadow).
[[maybe_unused]] inline constexpr int a = 0, b = 0, c = 0, d = 0, f = 0, g = 0, h = 0, i = 0, j = 0, k = 0,
                                      l = 0, m = 0, n = 0, o = 0, p = 0, r = 0, s = 0, t = 0, v = 0, w = 0,
                                      x = 0, y = 0, z = 0, I = 0, J = 0, K = 0, L = 0, M = 0, R = 0, T = 0,
                                      V = 0, W = 0, X = 0, Y = 0;

namespace warnings {
using kane::cross;
using kane::dot;
using kane::e;
using kane::q;
using kane::u;
template <std::size_t I>
using qc = kane::coordinate<I>;

struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, qc<1>>> {};
struct B : kane::frame<A, kane::simple<kane::axis::x, qc<2>>> {};
struct C : kane::frame<B, kane::simple<kane::axis::y, qc<3>>> {};
struct D : kane::frame<N, kane::simple<kane::direction<1, 2, 2>, qc<4>>> {};
struct E : kane::frame<D, kane::body_fixed<3, 1, 3, qc<5>, qc<6>, qc<1>>> {};
struct F : kane::frame<C, kane::space_fixed<1, 2, 3, qc<2>, qc<5>, qc<6>>> {};

struct L1 : kane::parameter<1> {};
struct L2 : kane::parameter<2> {};
inline constexpr L1 l1;
inline constexpr L2 l2;

// A user function, differentiated by dual numbers.
struct ramp {
  template <class T>
  constexpr T operator()(T x) const {
    return x * x + x;
  }
};

// Points: a literal moves into the type, a parameter and a coordinate stay nodes.
struct O : kane::origin<N> {};
struct P1 : kane::point<O, l1 * e<A, 1>> {};
struct P2 : kane::point<P1, 0.5 * e<C, 2> + l2 * e<C, 3>> {};
struct P3 : kane::point<P2, q<4> * e<C, 1>> {};  // moving on C

// Expressions of every kind.
inline constexpr auto scalar_expr = kane::sin(q<1>) * kane::cos(q<2>) + kane::sqrt(l1 * l1 + kane::t) -
                                    kane::pow<2>(q<3>) / l2 + kane::pow<-1>(2.0 + kane::cos(q<4>)) +
                                    kane::invoke(ramp{}, q<5>) - 3.0 * kane::dt(q<6>);  // u: in speeds()
inline constexpr auto vector_expr =
    scalar_expr * e<A, 1> - cross(e<B, 2>, l1* e<E, 3>) + dot(e<F, 1>, e<D, 2>) * e<N, 3>;

// Generalized speeds: u = q', body rates of C and the remaining rates, and the disc's.
using q6 = kane::qdot_speeds<6>;
using rates = kane::angular_velocity_speeds<N, C, C, kane::dt(q<4>), kane::dt(q<5>), kane::dt(q<6>)>;
using rolling = models::disc::rolling;
using disc_speeds = models::disc::speeds5;

// One holonomic constraint set: the point P1 on the unit circle, q4 = 0.
using cfg = kane::configuration<2, 0, kane::pow<2>(q<1>) + kane::pow<2>(q<2>) - l1 * l1, q<4>>;

template <class S>
using state6 = kane::state<S, 6, 6, 2>;

// Frames, vectors and direction cosines with numbers.
template <class S>
S frames_and_vectors(const state6<S>& s) {
  const kane::vec<C, S> pC(S(1), S(2), S(3));
  kane::vec<C, S> r = pC + kane::vec<C, S>::e1() - S(2) * pC / S(3) + pC * 2;
  r += -pC;
  r -= kane::vec<C, S>::e2();
  r *= S(0.5);
  r /= S(4);
  r[1] = r[0] + dot(r, pC) + norm(cross(r, pC));
  const auto NPC = kane::direction_cosines<N, C>(s);
  const auto CPN = NPC.transpose();
  const auto DPF = kane::direction_cosines<D, F>(s);
  const kane::vec<N, S> pN = CPN * pC;
  const kane::vec<E, S> pE = kane::express<E>(pN, s);
  const bool same = r == pC || kane::is_approx(NPC * pN, pC, S(1e-5)) || (CPN * NPC).is_rotation(S(1e-5));
  return pN.eigen().sum() + pE[2] + DPF(1, 2) + kane::vec<A, S>(pN.eigen()).eigen()(0) + S(same);
}

// Every kinematic quantity, evaluated at each level.
template <class S>
S kinematics(const state6<S>& s) {
  constexpr auto w = kane::angular_velocity<N, C>() + kane::angular_velocity<C, F>();
  constexpr auto al = kane::angular_acceleration<N, E>();
  constexpr auto v3 = kane::velocity<N, P3>();
  constexpr auto a3 = kane::acceleration<N, P3>();
  constexpr auto tv = kane::two_point_velocity<N, C, P1, P2>();
  constexpr auto ta = kane::two_point_acceleration<N, C, P1, P2>();
  constexpr auto ov = kane::one_point_velocity<N, C, P2, P3>();
  constexpr auto oa = kane::one_point_acceleration<N, C, P2, P3>();
  constexpr auto bv = kane::body_point_velocity<N, C, P1, P3>();
  constexpr auto r = kane::position<O, P3>();
  const auto ds = kane::dt(scalar_expr);
  const auto dq = kane::diff(scalar_expr, q<1>);
  const auto dv = kane::dt<B>(vector_expr);
  const auto dvq = kane::diff<B>(vector_expr, q<2>);

  kane::evaluator<state6<S>, kane::frames<C, E, F>, kane::level::pose> pose;
  kane::evaluator<state6<S>, kane::frames<C, E, F>, kane::level::velocity> velocity;
  kane::evaluator<state6<S>, kane::frames<C, E, F>> acceleration;
  pose.update(s);
  velocity.update(s);
  acceleration.update(s);
  const auto sum = [](const auto& xs) { return xs[0] + xs[1] + xs[2]; };
  return sum(kane::express<N>(r, pose)) + sum(kane::express<C>(vector_expr, pose)) +
         kane::evaluate(dq, pose) + pose.template sin_q<1>() + pose.template cos_q<6>() +
         sum(kane::express<N>(w, velocity)) + sum(kane::express<B>(v3, velocity)) +
         sum(kane::express<N>(tv, velocity)) + sum(kane::express<N>(ov, velocity)) +
         sum(kane::express<N>(bv, velocity)) + kane::evaluate(ds, velocity) +
         sum(kane::express<A>(dvq, velocity)) + sum(kane::express<N>(al, acceleration)) +
         sum(kane::express<D>(a3, acceleration)) + sum(kane::express<N>(ta, acceleration)) +
         sum(kane::express<N>(oa, acceleration)) + sum(kane::express<N>(dv, acceleration)) +
         acceleration.template coordinate_value<2, 2>();
}

// Speeds, partial velocities, constraints.
template <class S>
S speeds(const state6<S>& s) {
  constexpr auto v3 = kane::velocity<N, P3>();
  constexpr auto w = kane::angular_velocity<N, F>();
  constexpr auto vr = kane::partial_velocity<rates>(v3, u<2>);
  constexpr auto vt = kane::velocity_remainder<rates>(v3);
  constexpr auto vq = kane::partial_velocity<q6>(w, u<3>);

  kane::evaluator<state6<S>, kane::frames<F>, kane::level::acceleration, rates> ev;
  ev.update(s);
  kane::evaluator<state6<S>, kane::frames<F>, kane::level::velocity, q6> evq;
  evq.update(s);
  kane::evaluator<state6<S>, kane::frames<F>, kane::level::pose, rates> evp;  // W alone
  evp.update(s);
  kane::evaluator<state6<S>, kane::frames<F>, kane::level::acceleration, q6> eva;
  eva.update(s);
  const auto [T, rest] = kane::linear_in_speeds<N>(v3, ev);
  const auto V = kane::partial_velocities<C>(v3, ev);
  const auto W = kane::partial_velocities<N>(w, evq);
  const auto Ts = kane::partial_velocities<N>(dot(v3, e<N, 1>), ev);
  const auto res = kane::residuals<cfg>(ev);
  const auto vres = kane::velocity_residuals<cfg>(ev);
  S out = T.sum() + rest.sum() + V.sum() + W.sum() + Ts.sum() + kane::remainder<N>(v3, ev).sum() + res[0] +
          vres[1] + ev.template coordinate_value<1, 1>() + ev.template coordinate_value<1, 2>() +
          kane::express<N>(vr, ev)[0] + kane::express<N>(vt, ev)[1] + kane::express<N>(vq, evq)[2];
  out += kane::partial_velocities<B>(v3, evp).sum() + kane::express<N>(kane::acceleration<N, P3>(), eva)[0];
  if (ev.status() != kane::solve_status::ok) out += S(1);

  // The rolling disc: u4, u5 dependent.
  using St5 = kane::state<S, 5, 5, 1>;
  St5 s5;
  for (std::size_t i = 0; i < 5; ++i) s5.q[i] = s.q[i], s5.u[i] = s.u[i];
  s5.p[0] = S(0.25);
  kane::evaluator<St5, kane::frames<models::disc::R>, kane::level::velocity, disc_speeds> ed;
  ed.update(s5);
  const auto sol = kane::solve_constraints<rolling>(ed);
  constexpr auto vc = kane::velocity<models::disc::N, models::disc::Centre5>();
  const auto V5 = kane::nonholonomic_partial_velocities<models::disc::N, rolling>(vc, ed, sol);
  const auto B5 = kane::nonholonomic_remainder<models::disc::N, rolling>(vc, ed, sol);
  return out + sol.A.sum() + sol.B.sum() + V5.sum() + B5.sum() + S(sol.status == kane::solve_status::ok);
}

// The arm: a chain of six frames with literals in its positions.
template <class S>
S arm(const kane::state<S, 6>& s) {
  namespace m = models::arm6;
  kane::evaluator<kane::state<S, 6>, kane::frames<m::B6>> ev;
  ev.update(s);
  const auto J = kane::partial_velocities<m::N>(kane::velocity<m::N, m::End>(), ev);
  return J.sum() + kane::express<m::N>(kane::acceleration<m::N, m::End>(), ev)[0] +
         kane::direction_cosines<m::N, m::B6>(s)(0, 0);
}

// The four-bar: Newton on its loop, then its velocity constraints.
template <class S>
S fourbar(const kane::state<S, 6>& s6) {
  namespace m = models::fourbar;
  kane::state<S, 3, 3, 4> s;
  s.q = {s6.q[0], s6.q[1], s6.q[2]};
  s.u = {s6.q[3], S(0), S(0)};
  s.p = {S(0.3), S(1), S(0.8), S(1.1)};
  kane::evaluator<decltype(s), kane::frames<m::A, m::B, m::C>, kane::level::velocity, m::speeds> ev;
  const kane::newton_result<S> r = kane::solve_configuration<m::loop>(ev, s, {S(1e-5), 10});
  const auto sol = kane::solve_constraints<m::rates>(ev);
  return r.residual + S(r.iterations) + sol.A.sum() + S(kane::degrees_of_freedom<decltype(s), m::loop>);
}

// Euler parameters (nq = 7, nu = 6), and rotations by a parameter, a constant and q + c.
struct lean : kane::parameter<1> {};
struct H : kane::frame<models::free_body::B, kane::simple<kane::axis::y, lean>> {};
struct K : kane::frame<H, kane::simple<kane::axis::x, kane::angle<kane::q<5> + kane::literal(0.5)>>> {};
template <class S>
S free_body(const kane::state<S, 6>& s6) {
  namespace m = models::free_body;
  kane::state<S, 7, 6, 3> s;
  s.q = {S(1), s6.q[0], s6.q[1], s6.q[2], s6.q[3], s6.q[4], s6.q[5]};
  s.u = {s6.q[0], s6.q[1], s6.q[2], S(0), S(0), S(0)};
  s.ud = {};
  s.p = {S(0.2), S(0.1), S(0.3)};
  kane::evaluator<decltype(s), kane::frames<K>, kane::level::acceleration, m::speeds> ev;
  ev.update(s);
  return ev.coordinate_rates()[0] + kane::express<m::N>(kane::acceleration<m::N, m::P>(), ev)[0] +
         kane::express<m::N>(kane::angular_acceleration<m::N, K>(), ev)[1] +
         kane::direction_cosines<m::N, K>(s)(0, 0);
}

// Wheels that spin at free speeds (the bicycle), and an attitude read from the state.
struct Att
    : kane::frame<N, kane::attitude<kane::rotation_matrix<1>,
                                    kane::parent_rates<kane::speed<1>, kane::speed<2>, kane::speed<3>>>> {};
template <class S>
S spins_and_attitudes(const kane::state<S, 6>& s6) {
  namespace m = models::bicycle;
  kane::state<S, 6, 8, 6> s;
  s.q = s6.q;
  s.p = {S(0.35), S(0.3), S(1.25), S(0.03), S(0.27), S(0.95)};
  kane::evaluator<decltype(s), kane::frames<m::Wr, m::Wf>, kane::level::acceleration, m::speeds> ev;
  const auto r = kane::solve_configuration<m::pitch>(ev, s);
  const auto sol = kane::solve_constraints<m::rolling>(ev);
  kane::state<S, 0, 3, 9> a;
  a.p = {S(1), S(0), S(0), S(0), S(1), S(0), S(0), S(0), S(1)};
  using free3 = kane::speeds<kane::free_speed, kane::free_speed, kane::free_speed>;
  kane::evaluator<decltype(a), kane::frames<Att>, kane::level::acceleration, free3> ea;
  ea.update(a);
  using unit_rates = kane::attitude<kane::unit_quaternion<1>,
                                    kane::body_rates<kane::speed<1>, kane::speed<2>, kane::speed<3>>>;
  return r.residual + sol.A.sum() + kane::express<m::N>(kane::angular_acceleration<m::N, m::Wf>(), ev)[0] +
         kane::express<N>(kane::angular_acceleration<N, Att>(), ea)[2] + kane::rotation_tolerance<S> +
         S(unit_rates::rotation(a));
}

// Kane's dynamical equations and the right-hand side for integrators.
template <class S>
S dynamics(const kane::state<S, 6>& s6) {
  namespace m = models::pendulum3d;
  kane::state<S, 2, 2, 21> s;
  s.q = {s6.q[0], s6.q[1]};
  s.p.fill(S(1));
  kane::evaluator<decltype(s), kane::frames<m::B>, kane::level::acceleration, kane::qdot_speeds<2>> ev;
  ev.update(s);
  const auto eom = kane::mass_matrix_and_forcing<m::system>(ev);
  const auto ud = kane::speed_derivatives(eom).ud;
  kane::motion<m::system, decltype(ev)> rhs(s);
  std::array<S, 4> x{}, dx{};
  rhs(x, dx, S(0));
  const auto lin = kane::linearize<m::system, decltype(ev), kane::inputs<m::p<19>>>(s);
  const auto spectrum = kane::eigenvalues(lin.A);
  const S active =
      kane::evaluate(kane::generalized_active_force<m::N, m::system, kane::qdot_speeds<2>, 1>(), ev);
  const auto pin = kane::reaction<m::system, kane::cut<m::J, m::B, m::Q>>(ev);
  // absolute-angle rates: W's numbers and their time derivatives in the partial velocities
  using absolute = kane::speeds<kane::dt(kane::q<1>), kane::dt(kane::q<1>) + kane::dt(kane::q<2>)>;
  kane::evaluator<decltype(s), kane::frames<m::B>, kane::level::acceleration, absolute> ea;
  ea.update(s);
  const S absolute_f = kane::mass_matrix_and_forcing<m::system>(ea).f.sum();
  return eom.M.sum() + ud.sum() + kane::kinetic_energy<m::system>(ev) +
         kane::potential_energy<m::system>(ev) + kane::linear_momentum<m::system>(ev)[0] +
         kane::angular_momentum<m::system>(ev)[1] + dx[3] + lin.A.sum() + lin.B.sum() + active +
         pin.force[0] + pin.moment[1] + absolute_f + spectrum.values(0).real();
}

// Printing.
template <class S>
std::string printing(const state6<S>& s) {
  std::ostringstream os;
  os << kane::vec<B, S>(S(1), S(-2), S(0.5)) << kane::direction_cosines<N, E>(s) << vector_expr
     << kane::acceleration<N, P3>() << kane::frame_name<E::tree_parent>() << kane::type_name<F>();
  return os.str() + kane::to_string(scalar_expr) +
         kane::to_string(kane::velocity_remainder<rates>(kane::velocity<N, P3>())) +
         kane::to_string(kane::partial_velocity<disc_speeds>(models::disc::v_below, u<3>)) +
         kane::to_string(kane::angular_acceleration<N, F>()) +
         kane::to_string(kane::angular_velocity<models::bicycle::N, models::bicycle::Wr>());
}

template <class S>
S all(const state6<S>& s, const kane::state<S, 6>& s6) {
  return frames_and_vectors(s) + kinematics(s) + speeds(s) + arm(s6) + fourbar(s6) + free_body(s6) +
         spins_and_attitudes(s6) + dynamics(s6) + S(printing(s).size());
}

// One scalar when KANE_WARNINGS_SCALAR names it, else both (the suite's tests).
#ifdef KANE_WARNINGS_SCALAR
template KANE_WARNINGS_SCALAR all<KANE_WARNINGS_SCALAR>(const state6<KANE_WARNINGS_SCALAR>&,
                                                        const kane::state<KANE_WARNINGS_SCALAR, 6>&);
#else
template float all<float>(const state6<float>&, const kane::state<float, 6>&);
template double all<double>(const state6<double>&, const kane::state<double, 6>&);
#endif
}  // namespace warnings
