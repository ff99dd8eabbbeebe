// Linearization of Kane's equations about a state, exact (forward-mode jets
// through the same evaluator, or analytical derivatives; no differences):
//
//   auto lin = kane::linearize<Sys, Ev>(s);                 // x = (q, u)
//   auto lin = kane::linearize<Sys, Ev, kane::inputs<kane::r<1>>>(s);  // B = df/dr
//   auto lin = kane::linearize_constrained<Sys, NH, Ev, H>(s);  // x = (q_ind, u_ind)
//   dx' = lin.A dx + lin.B dr,  lin.rate = x' at s
//
// Inputs r are inputs of the state (kane::r<k>) or parameter slots (kane::parameter<k>{}). For a
// nonholonomic system NH the state is (q_ind, u_ind): the dependent speeds are
// A u_ind + B of the constraints at every perturbed state, and the dependent
// coordinates of H (void: none) follow q_ind through the constraints' Jacobian
// (the implicit function theorem, one Newton step on jets); s must close H.
//
// linearize_equations gives the second-order form of the reduced equations
// M u' + C u + K q_ind = B r about s with u' fixed at its value there:
// M = M~, C = d(M~ u' - f~)/du_ind, K = d(M~ u' - f~)/dq_ind, B = -d(..)/dr.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/dynamics/constrained_motion.hpp"
#include "kane/dynamics/motion.hpp"
#include "kane/evaluation/configuration.hpp"
#include "kane/linearization/batched_linearization.hpp"
#include "kane/linearization/detail/constrained_jets.hpp"
#include "kane/linearization/held_coordinates.hpp"
#include "kane/linearization/jet.hpp"
#include "kane/linearization/linear_model.hpp"
#include "kane/linearization/tree_linearization.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
// The jets' size of a batch of a linearization in n directions.
template <std::size_t N, std::size_t Batch>
inline constexpr std::size_t batch_of = N < Batch ? N : Batch;
// The results' types, declared so that a call does not instantiate the model to learn them.
template <class NH, class Ev, class H, class In>
using constrained_model_of =
    linear_model<typename Ev::scalar, independent_coordinates<H, Ev::state_type::nq>().size() + NH::p, In::n,
                 state_order<independent_coordinates<H, Ev::state_type::nq>(), NH::independents>>;
template <class NH, class Ev, class H, class In>
using equations_of =
    linear_equations<typename Ev::scalar, NH::p, independent_coordinates<H, Ev::state_type::nq>().size(),
                     In::n, state_order<independent_coordinates<H, Ev::state_type::nq>(), NH::independents>>;
}  // namespace detail

// x = (q, u) of an unconstrained system; the derivatives of x' = (W u + X, M^-1 f).
template <System Sys, Evaluator Ev, class In = inputs<>>
detail::model_of<Ev, In> linearize(const typename Ev::state_type& s) {
  if constexpr (detail::analytical_linearization<Sys, Ev>())
    return detail::linearize_tree<Sys, Ev, In>(s);
  else {
    static_assert(lane_traits<typename Ev::scalar>::width == 1,
                  "kane: linearize over kane::lanes takes the analytical derivatives (a tree of simple "
                  "rotations, u = q'): linearize other systems one state at a time");
    return detail::linearize_in_batches<Sys, Ev, In>(s);
  }
}

namespace detail {
// linearize_constrained with the directions in batches of jets of Batch
template <class Sys, class NH, class Ev, class H, class In, std::size_t Batch>
constrained_model_of<NH, Ev, H, In> constrained_in_batches(const typename Ev::state_type& s) {
  using S = typename Ev::scalar;
  constexpr std::size_t nq = Ev::state_type::nq;
  constexpr auto qi = independent_coordinates<H, nq>();
  constexpr auto qs = directions<Sys, NH, Ev, H>;
  constexpr std::size_t nx = qi.size() + NH::p, nj = qs.n + NH::p, n = nj + In::n, b = batch_of<n, Batch>;
  using J = jet<S, b>;
  constrained_model_of<NH, Ev, H, In> out;
  out.A.setZero();  // the columns of held coordinates
  out.status = solve_status::ok;
  for (std::size_t lo = 0; lo < n; lo += b) {
    solve_status status;
    auto [js, x] = constrained_point<Sys, NH, Ev, H, In, b>(s, status, lo);
    constrained_motion<Sys, NH, typename rebind_evaluator<Ev, J>::type> rhs(js);
    std::array<J, nq + NH::p> dx;
    rhs(x, dx, js.t);
    if (out.status == solve_status::ok) out.status = status != solve_status::ok ? status : rhs.status();
    for (std::size_t i = 0; i < nx; ++i) {
      const J& r = i < qi.size() ? dx[qi[i] - 1] : dx[nq + i - qi.size()];
      out.rate(Eigen::Index(i)) = r.v;
      for (std::size_t j = 0; j < nx; ++j) {
        const std::size_t d = j < qi.size() ? qs.slot[j] : qs.n + j - qi.size();
        if (d != no_slot && d >= lo && d < lo + b) out.A(Eigen::Index(i), Eigen::Index(j)) = r.part(d - lo);
      }
      for (std::size_t k = 0; k < In::n; ++k)
        if (nj + k >= lo && nj + k < lo + b) out.B(Eigen::Index(i), Eigen::Index(k)) = r.part(nj + k - lo);
    }
  }
  if (out.status != solve_status::ok) set_nan(out.A), set_nan(out.B), set_nan(out.rate);
  return out;
}

// linearize_equations with the directions in batches of jets of Batch. First M~ and f~ at s: the
// reduced forcing at u' = 0 with u_ind' as the directions (M~ = -df/du_ind'), u_ind' = M~^-1 f~ on
// numbers. Then C, K, B from the jets of f = -(M~ u' - f~) at that u', held.
template <class Sys, class NH, class Ev, class H, class In, std::size_t Batch>
equations_of<NH, Ev, H, In> equations_in_batches(const typename Ev::state_type& s) {
  using S = typename Ev::scalar;
  constexpr std::size_t nq = Ev::state_type::nq, p = NH::p;
  constexpr auto qi = independent_coordinates<H, nq>();
  constexpr auto qs = directions<Sys, NH, Ev, H>;
  constexpr std::size_t nj = qs.n + p, n = nj + In::n, b = batch_of<n, Batch>;
  using J = jet<S, b>;
  equations_of<NH, Ev, H, In> out;
  out.K.setZero();  // the columns of held coordinates
  equations_of_motion<S, p> at{{}, {}, solve_status::ok};
  for (std::size_t lo = 0; lo < p; lo += b) {  // u_ind' in [lo, lo + b) as directions, no state's
    Eigen::Matrix<J, int(p), 1> ud;
    for (std::size_t k = 0; k < p; ++k)
      ud(Eigen::Index(k)) = k >= lo && k < lo + b ? J::variable(S(0), k - lo) : J(0);
    const auto [f, status] = reduced_forcing_on_jets<Sys, NH, Ev, H, In, b>(s, ud, n);
    if (at.status == solve_status::ok) at.status = status;
    for (std::size_t r = 0; r < p; ++r) {
      at.f(Eigen::Index(r)) = f(Eigen::Index(r)).v;
      for (std::size_t c = lo; c < p && c < lo + b; ++c)
        at.M(Eigen::Index(r), Eigen::Index(c)) = S(0) - f(Eigen::Index(r)).part(c - lo);
    }
  }
  out.M = at.M = (at.M + at.M.transpose()) * S(0.5);  // symmetric up to rounding
  const auto solved = speed_derivatives_at(at);
  out.status = solved.status;
  Eigen::Matrix<J, int(p), 1> ud;
  for (std::size_t k = 0; k < p; ++k) ud(Eigen::Index(k)) = J(solved.ud(Eigen::Index(k)));
  for (std::size_t lo = 0; lo < n; lo += b) {
    const auto [f, status] = reduced_forcing_on_jets<Sys, NH, Ev, H, In, b>(s, ud, lo);
    if (out.status == solve_status::ok) out.status = status;
    const auto in_batch = [&](std::size_t d) { return d != no_slot && d >= lo && d < lo + b; };
    for (std::size_t r = 0; r < p; ++r) {
      const auto& res = f(Eigen::Index(r));  // -(M~ u' - f~); 0 - x keeps zeros +0
      for (std::size_t j = 0; j < qi.size(); ++j)
        if (in_batch(qs.slot[j])) out.K(Eigen::Index(r), Eigen::Index(j)) = S(0) - res.part(qs.slot[j] - lo);
      for (std::size_t c = 0; c < p; ++c)
        if (in_batch(qs.n + c)) out.C(Eigen::Index(r), Eigen::Index(c)) = S(0) - res.part(qs.n + c - lo);
      for (std::size_t k = 0; k < In::n; ++k)
        if (in_batch(nj + k)) out.B(Eigen::Index(r), Eigen::Index(k)) = res.part(nj + k - lo);
    }
  }
  if (out.status != solve_status::ok) set_nan(out.M), set_nan(out.C), set_nan(out.K), set_nan(out.B);
  return out;
}
}  // namespace detail

// x = (q_ind, u_ind) of a nonholonomic system NH with holonomic constraints H.
template <System Sys, Nonholonomic NH, Evaluator Ev, class H = void, class In = inputs<>>
requires(std::is_void_v<H> || Holonomic<H>) detail::constrained_model_of<NH, Ev, H, In> linearize_constrained(
    const typename Ev::state_type& s) {
  static_assert(lane_traits<typename Ev::scalar>::width == 1,
                "kane: linearize_constrained takes one state at a time, not kane::lanes");
  return detail::constrained_in_batches<Sys, NH, Ev, H, In, detail::linearize_batch>(s);
}

// M u' + C u + K q_ind = B r: Kane's reduced equations linearized about s, u' held.
template <System Sys, Nonholonomic NH, Evaluator Ev, class H = void, class In = inputs<>>
requires(std::is_void_v<H> || Holonomic<H>) detail::equations_of<NH, Ev, H, In> linearize_equations(
    const typename Ev::state_type& s) {
  static_assert(lane_traits<typename Ev::scalar>::width == 1,
                "kane: linearize_equations takes one state at a time, not kane::lanes");
  return detail::equations_in_batches<Sys, NH, Ev, H, In, detail::linearize_batch>(s);
}

}  // namespace kane
#pragma GCC diagnostic pop
