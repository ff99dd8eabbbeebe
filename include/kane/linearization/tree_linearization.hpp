// kane::linearize of a system that takes the analytical derivatives (dynamics_derivatives.hpp):
// x = (q, u) with q' = u, so A = [0 1; du'/dq du'/du], and B = -M^-1 dtau/dr with dtau/dr carried
// by jets of the inputs alone through inverse dynamics at u'.
#pragma once

#include <cstddef>
#include <limits>
#include <type_traits>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "kane/dynamics/dynamics_derivatives.hpp"
#include "kane/dynamics/inverse_dynamics.hpp"
#include "kane/dynamics/mass_matrix_and_forcing.hpp"
#include "kane/linearization/jet.hpp"
#include "kane/linearization/lift.hpp"
#include "kane/linearization/linear_model.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// linearize takes the analytical derivatives: numbers, a system of joint form with steady loads,
// u = q' of all coordinates.
template <class Sys, class Ev>
constexpr bool analytical_linearization() {
  if constexpr (!std::is_floating_point_v<typename Ev::scalar> || Ev::state_type::nq != Ev::nu)
    return false;
  else
    return analytical_derivatives<Sys, Ev>();
}

template <class Sys, class Ev, class In>
model_of<Ev, In> linearize_tree(const typename Ev::state_type& s) {
  using S = typename Ev::scalar;
  constexpr std::size_t n = Ev::nu;
  constexpr auto m = Eigen::Index(n);
  Ev ev;
  ev.update(s);
  const auto d = forward_dynamics_derivatives<Sys>(ev);
  model_of<Ev, In> out;
  out.A.setZero();
  out.A.block(0, m, m, m).setIdentity();
  out.A.block(m, 0, m, m) = d.dud_dq, out.A.block(m, m, m, m) = d.dud_du;
  for (std::size_t i = 0; i < n; ++i) out.rate(Eigen::Index(i)) = s.u[i];
  out.rate.tail(m) = d.ud;
  out.status = d.status;
  if constexpr (In::n > 0) {
    using J = jet<S, In::n>;
    auto js = lift<In::n>(s);
    seed_inputs<In, J>(js, 0);
    for (std::size_t i = 0; i < n; ++i) js.ud[i] = J(d.ud(Eigen::Index(i))), js.qdd[i] = js.ud[i];
    typename rebind_evaluator<Ev, J>::type jev;
    jev.update(js);
    const auto tau = inverse_dynamics<Sys>(jev).tau;
    Eigen::Matrix<S, int(n), int(In::n)> b;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = 0; k < In::n; ++k)
        b(Eigen::Index(i), Eigen::Index(k)) = -tau(Eigen::Index(i)).part(k);
    const Eigen::LLT<Eigen::Matrix<S, int(n), int(n)>> llt(mass_matrix<Sys>(ev).M);
    llt.solveInPlace(b);
    out.B.setZero();
    out.B.block(m, 0, m, Eigen::Index(In::n)) = b;
  }
  if (out.status != solve_status::ok)
    out.A.setConstant(std::numeric_limits<S>::quiet_NaN()),
        out.B.setConstant(std::numeric_limits<S>::quiet_NaN());
  return out;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
