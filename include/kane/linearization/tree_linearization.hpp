// kane::linearize of a system that takes the analytical derivatives (dynamics_derivatives.hpp):
// x = (q, u) with q' = u, so A = [0 1; du'/dq du'/du], and B = -M^-1 dtau/dr (torque_by_inputs), M
// factored once for both. With a free joint, q holds
// its Euler parameters e, with e' = G(e) w / |e| = e (0, w) / (2 |e|), w = u_1..3 (the kinematic equations);
// du'/de is du'/dtheta L, L = 4 G(e)^T / |e|^2 (tangent.hpp): no column along |e|.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include <Eigen/Core>

#include "kane/dynamics/detail/tree/frame_steps.hpp"
#include "kane/dynamics/dynamics_derivatives.hpp"
#include "kane/dynamics/inverse_dynamics.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/linearization/attitude_map.hpp"
#include "kane/linearization/jet.hpp"
#include "kane/linearization/lift.hpp"
#include "kane/linearization/linear_model.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// linearize takes the analytical derivatives: numbers or lanes, a system of joint form with steady
// loads, u = q' of all coordinates.
template <class Sys, class Ev>
constexpr bool analytical_linearization() {
  constexpr std::size_t nq = Ev::state_type::nq, nu = Ev::nu;
  if constexpr (!Numbers<typename Ev::scalar> || !analytical_derivatives<Sys, Ev>())
    return false;
  else
    return nq == nu + (free_joint<Sys, Ev> ? 1 : 0);
}

// The rows of q' and the columns of q in u's rows, with a free joint (speed_layout.hpp).
template <class Sys, class Ev, class St, class D, class A, class R>
void free_kinematics(const St& s, const D& dud_dq, A& a, R& rate) {
  using S = typename Ev::scalar;
  using JF = joint_form_of<Sys, Ev>;
  constexpr std::size_t nq = St::nq, nu = Ev::nu;
  constexpr auto layout = layout_of<speeds_of<Ev>, typename Ev::root, typename JF::frame_list, nq>::value;
  constexpr auto c = frame_at<JF, std::size_t(JF::table.free)>::step::coordinates;
  const auto col = [](std::size_t r) { return Eigen::Index(r); };
  for (std::size_t i = 0; i < nq; ++i) {  // q_c' = u_r
    const int r = layout.rate[i];
    if (r == -1) continue;  // an Euler parameter, below
    const std::size_t k = r >= 0 ? std::size_t(r) : 3 + i + 1 - layout.position;
    a(Eigen::Index(i), col(nq + k)) = S(1), rate(Eigen::Index(i)) = s.u[k];
    a.block(Eigen::Index(nq), Eigen::Index(i), Eigen::Index(nu), 1) = dud_dq.col(col(k));
  }
  const Eigen::Matrix<S, 4, 1> e(s.q[c[0] - 1], s.q[c[1] - 1], s.q[c[2] - 1], s.q[c[3] - 1]);
  using std::sqrt;
  const S w1 = s.u[0], w2 = s.u[1], w3 = s.u[2], norm2 = e.squaredNorm(), norm = sqrt(norm2);
  Eigen::Matrix<S, 4, 4> p;  // e (0, w) = P e (a product of quaternions)
  p << S(0), -w1, -w2, -w3, w1, S(0), w3, -w2, w2, -w3, S(0), w1, w3, w2, -w1, S(0);
  const Eigen::Matrix<S, 4, 1> ed = p * e / (S(2) * norm);
  const Eigen::Matrix<S, 4, 3> g = attitude_map(e(0), e(1), e(2), e(3));
  const Eigen::Matrix<S, 4, 4> de = S(0.5) * p / norm - ed * e.transpose() / norm2;
  const Eigen::Matrix<S, int(nu), 4> du = dud_dq.template leftCols<3>() * (S(4) / norm2) * g.transpose();
  for (std::size_t i = 0; i < 4; ++i) {
    const auto row = Eigen::Index(c[i] - 1);
    rate(row) = ed(Eigen::Index(i));
    for (std::size_t j = 0; j < 4; ++j) a(row, Eigen::Index(c[j] - 1)) = de(Eigen::Index(i), Eigen::Index(j));
    for (Eigen::Index j = 0; j < 3; ++j) a(row, Eigen::Index(nq) + j) = g(Eigen::Index(i), j) / norm;
    a.block(Eigen::Index(nq), row, Eigen::Index(nu), 1) = du.col(Eigen::Index(i));
  }
}

// dtau/dr, which does not depend on u'. Inputs r_k move loads alone (no pass reads them), so
// dtau/dr_k sums the partial derivatives of the loads by r_k inward. Parameters, which masses and
// lengths may read, go by jets through inverse dynamics at u' = 0.
template <class Sys, class Ev, class In>
Eigen::Matrix<typename Ev::scalar, int(Ev::nu), int(In::n)> torque_by_inputs(
    const Ev& ev, const typename Ev::state_type& s) {
  using S = typename Ev::scalar;
  constexpr std::size_t n = Ev::nu;
  Eigen::Matrix<S, int(n), int(In::n)> b;
  constexpr bool of_state = [] {
    for (bool x : In::of_state)
      if (!x) return false;
    return true;
  }();
  if constexpr (of_state) {
    using JF = joint_form_of<Sys, Ev>;
    const body_frames<JF, Ev> bf(ev);
    static_for<In::n>([&](auto k) {
      std::array<v3<S>, JF::nf> f, m;
      own_loads<JF, Sys, input<In::slots[k]>>(bf, ev, f, m);
      Eigen::Matrix<S, int(n), 1> tau;
      inward_forces<JF, false>(bf, f, m, tau);
      b.col(Eigen::Index(k)) = tau;
    });
  } else if constexpr (lane_traits<S>::width > 1) {  // the assertion alone: no jets of lanes follow it
    static_assert(lane_traits<S>::width == 1,
                  "kane: linearize over kane::lanes takes inputs of the state (kane::r<k>), not parameters");
  } else {
    using J = jet<S, In::n>;
    auto js = lift<In::n>(s);
    seed_inputs<In, J>(js, 0);
    for (std::size_t i = 0; i < n; ++i) js.ud[i] = J(0), js.qdd[i] = js.ud[i];
    typename rebind_evaluator<Ev, J>::type jev;
    jev.update(js);
    const auto tau = inverse_dynamics<Sys>(jev).tau;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = 0; k < In::n; ++k)
        b(Eigen::Index(i), Eigen::Index(k)) = tau(Eigen::Index(i)).part(k);
  }
  return b;
}

template <class Sys, class Ev, class In>
model_of<Ev, In> linearize_tree(const typename Ev::state_type& s) {
  constexpr std::size_t n = Ev::nu;
  constexpr auto m = Eigen::Index(n);
  Ev ev;
  ev.update(s);
  model_of<Ev, In> out;
  out.B.setZero();
  const auto d = [&] {  // B = -M^-1 dtau/dr, by the factor of M that the derivatives take
    if constexpr (In::n > 0) {
      auto b = torque_by_inputs<Sys, Ev, In>(ev, s);
      const auto fd = forward_derivatives_solving<Sys>(ev, b);
      out.B.bottomRows(m) = b;
      return fd;
    } else
      return forward_dynamics_derivatives<Sys>(ev);
  }();
  out.A.setZero();
  if constexpr (!free_joint<Sys, Ev>) {
    out.A.block(0, m, m, m).setIdentity();
    out.A.block(m, 0, m, m) = d.dud_dq;
    for (std::size_t i = 0; i < n; ++i) out.rate(Eigen::Index(i)) = s.u[i];
  } else
    free_kinematics<Sys, Ev>(s, d.dud_dq, out.A, out.rate);
  out.A.bottomRightCorner(m, m) = d.dud_du;
  out.rate.tail(m) = d.ud;
  out.status = d.status;
  finish_results(out.status, out.B, out.A);
  return out;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
