// kane::linearize of a system without the analytical derivatives: x = (q, u).
//
// u' = M^-1 f comes from numbers, M factored once. The directions of x and of the inputs then go in
// batches of linearize_batch, each batch one evaluation on jets of that size: jets of q' = W u + X and
// of tau = M u' - f at that u' (inverse_dynamics.hpp), so that M is never formed on jets and
//   du'/dx = -M^-1 dtau/dx,   du'/dr = -M^-1 dtau/dr.
// A jet holds 8 derivatives whatever the model, an evaluation O(n) jets; M and A are numbers.
#pragma once

#include <cstddef>
#include <limits>
#include <type_traits>

#include <Eigen/Core>

#include "kane/detail/invert.hpp"
#include "kane/dynamics/detail/method.hpp"
#include "kane/dynamics/detail/rates_function.hpp"
#include "kane/dynamics/inverse_dynamics.hpp"
#include "kane/dynamics/mass_matrix_and_forcing.hpp"
#include "kane/linearization/jet.hpp"
#include "kane/linearization/lift.hpp"
#include "kane/linearization/linear_model.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// The directions of one evaluation on jets.
inline constexpr std::size_t linearize_batch = 8;

template <class Sys, class Ev, class In>
model_of<Ev, In> linearize_in_batches(const typename Ev::state_type& s) {
  using S = typename Ev::scalar;
  using St = typename Ev::state_type;
  constexpr std::size_t nq = St::nq, nu = Ev::nu, nx = nq + nu, n = nx + In::n;
  constexpr std::size_t b = n < linearize_batch ? n : linearize_batch;
  using J = jet<S, b>;
  // numbers: x's speeds as motion.hpp places them, u' = 0
  St s0 = s;
  s0.ud = {}, s0.qdd = {};
  if constexpr (std::is_void_v<typename Ev::speed_set>) s0.qd = s.u, s0.u = {};
  Ev ev;
  ev.update(s0);
  const auto eq = mass_matrix_and_forcing<Sys>(ev);
  const cholesky_factor<S, int(nu)> factor(eq.M);  // M = L D L^T, once
  Eigen::Matrix<S, int(nu), 1> ud = -eq.f;
  factor.solve_negated(ud);
  solve_status status = eq.status != solve_status::ok ? eq.status
                        : !factor.ok()                ? solve_status::singular
                        : !all_finite_matrix(ud)      ? solve_status::not_finite
                                                      : solve_status::ok;
  model_of<Ev, In> out;
  const auto qd = ev.coordinate_rates();
  for (std::size_t i = 0; i < nq; ++i) out.rate(Eigen::Index(i)) = qd[i];
  out.rate.tail(Eigen::Index(nu)) = ud;
  // jets: the state at u', every number constant
  auto at = lift<b>(s0);
  for (std::size_t i = 0; i < nu; ++i) at.ud[i] = at.qdd[i] = J(ud(Eigen::Index(i)));
  const auto put = [&](std::size_t i, std::size_t d, S v) {  // column d of [A B]
    if (d < nx)
      out.A(Eigen::Index(i), Eigen::Index(d)) = v;
    else
      out.B(Eigen::Index(i), Eigen::Index(d - nx)) = v;
  };
  Eigen::Matrix<S, int(nu), int(b)> dtau;
  for (std::size_t lo = 0; lo < n && status == solve_status::ok; lo += b) {
    const std::size_t hi = lo + b < n ? lo + b : n;
    auto js = at;
    for (std::size_t d = lo; d < hi && d < nx; ++d) {
      if (d < nq)
        js.q[d] = J::variable(s.q[d], d - lo);
      else
        speeds_of_state<Ev>(js)[d - nq] = J::variable(s.u[d - nq], d - lo);
    }
    seed_inputs<In, J>(js, nx, lo, hi);
    typename rebind_evaluator<Ev, J>::type jev;
    jev.template update_for<equation_reads<Sys, Ev, false>>(js);
    const auto jqd = jev.coordinate_rates();
    const auto tau = inverse_dynamics<Sys>(jev);
    if (tau.status != solve_status::ok) status = tau.status;
    for (std::size_t j = 0; j < b; ++j)
      for (std::size_t i = 0; i < nu; ++i)
        dtau(Eigen::Index(i), Eigen::Index(j)) = tau.tau(Eigen::Index(i)).part(j);
    factor.solve_negated(dtau);  // -M^-1 dtau
    for (std::size_t d = lo; d < hi; ++d) {
      for (std::size_t i = 0; i < nq; ++i) put(i, d, jqd[i].part(d - lo));
      for (std::size_t i = 0; i < nu; ++i) put(nq + i, d, dtau(Eigen::Index(i), Eigen::Index(d - lo)));
    }
  }
  out.status = status;
  if (status != solve_status::ok) {
    constexpr S nan = std::numeric_limits<S>::quiet_NaN();
    out.A.setConstant(nan), out.B.setConstant(nan), out.rate.setConstant(nan);
  }
  return out;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
