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
#include "kane/linearization/held_coordinates.hpp"
#include "kane/linearization/jet.hpp"
#include "kane/linearization/linear_model.hpp"
#include "kane/linearization/tree_linearization.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
template <class H>
struct dependents_of {
  static constexpr std::size_t m = 0;
  static constexpr std::array<std::size_t, 0> dependents{};
};
template <class H>
requires(!std::is_void_v<H>) struct dependents_of<H> : H {
};
template <class H, std::size_t NQ>
constexpr auto independent_coordinates() {
  std::array<std::size_t, NQ - dependents_of<H>::m> out{};
  std::size_t k = 0;
  for (std::size_t i = 1; i <= NQ; ++i) {
    bool dep = false;
    for (std::size_t d : dependents_of<H>::dependents) dep = dep || d == i;
    if (!dep) out[k++] = i;
  }
  return out;
}
// At s, which closes H: dq_dep = -J_dep^-1 J_ind dq_ind (the implicit function theorem), J the
// symbolic partial derivatives of H evaluated by one pose pass on numbers, added to q_dep's jets.
// Only the directions in [lo, hi) are carried, at their place after lo.
template <class H, class Ev, auto Slots, class JSt>
solve_status dependent_jets(const typename Ev::state_type& s, JSt& js, std::size_t lo, std::size_t hi) {
  using S = typename Ev::scalar;
  using J = typename JSt::scalar;
  using Sys = newton_system<H>;
  constexpr std::size_t m = H::m;
  constexpr auto qi = independent_coordinates<H, Ev::state_type::nq>();
  // the pose pass of Ev itself where it has one (its code is already the motion's)
  constexpr bool posed = requires(Ev & e) { e.update_pose(s); };
  std::conditional_t<posed, Ev, typename pose_evaluator<Ev>::type> ev;
  if constexpr (posed)
    ev.update_pose(s);
  else
    ev.update(s);
  table<S, m, m> jac{};
  constraint_jacobian<H>(ev, jac);
  const auto factors = factor_structured<Sys>(jac);
  solve_status status = ev.status();
  static_for<qi.size()>([&](auto t) {
    if constexpr (Slots.slot[t] == no_slot) return;  // H does not hold q_t
    if (Slots.slot[t] < lo || Slots.slot[t] >= hi) return;
    table<S, m, 1> f, x;
    static_for<m>(
        [&](auto k) { f[k][0] = eval_scalar(diff(std::get<k>(H::equations), coordinate<qi[t]>{}), ev); });
    const solve_status solved = substitute_structured<Sys>(jac, factors, f, x);
    if (status == solve_status::ok) status = solved;
    static_for<m>(
        [&](auto j) { js.q[H::dependents[j] - 1] -= J::variable(S(0), Slots.slot[t] - lo) * J(x[j][0]); });
  });
  return status;
}
// The jet state of x = (q_ind, u_ind) and the inputs at s: q_dep through H (dependent_jets, or
// one Newton step on jets where inputs may enter H).
// The directions of x = (q_ind, u_ind) that jets carry: held coordinates (held_coordinates.hpp), then u_ind.
template <class Sys, class NH, class Ev, class H>
inline constexpr auto directions =
    coordinate_slots<independent_coordinates<H, Ev::state_type::nq>(), coordinates_held<Sys, NH, Ev, H>()>();
// The directions in [lo, lo + B) are carried by jets of B, at their place after lo.
template <class Sys, class NH, class Ev, class H, class In, std::size_t B>
auto constrained_point(const typename Ev::state_type& s, solve_status& status, std::size_t lo) {
  constexpr std::size_t nq = Ev::state_type::nq;
  constexpr auto qi = independent_coordinates<H, nq>();
  constexpr auto qs = directions<Sys, NH, Ev, H>;
  constexpr std::size_t nx = qs.n + NH::p;
  using J = jet<typename Ev::scalar, B>;
  using JEv = typename rebind_evaluator<Ev, J>::type;
  const std::size_t hi = lo + B;
  const auto seeded = [&](std::size_t d, auto value) {
    return d >= lo && d < hi ? J::variable(value, d - lo) : J(value);
  };
  struct {
    decltype(lift<B>(s)) js;
    std::array<J, nq + NH::p> x;
  } out{lift<B>(s), {}};  // built and returned in place
  auto& [js, x] = out;
  for (std::size_t k = 0; k < qi.size(); ++k)
    if (qs.slot[k] != no_slot) js.q[qi[k] - 1] = seeded(qs.slot[k], s.q[qi[k] - 1]);
  seed_inputs<In, J>(js, nx, lo, hi);
  status = solve_status::ok;
  if constexpr (!std::is_void_v<H> && In::n == 0) {
    status = dependent_jets<H, Ev, qs>(s, js, lo, hi);
  } else if constexpr (!std::is_void_v<H>) {  // q_dep -= J^-1 f on jets (inputs may enter f)
    JEv ev;
    const auto r = solve_configuration<H>(ev, js, {J(-1), 1});
    if (r.status != solve_status::not_converged) status = r.status;
  }
  for (std::size_t i = 0; i < nq; ++i) x[i] = js.q[i];
  for (std::size_t k = 0; k < NH::p; ++k) x[nq + k] = seeded(qs.n + k, s.u[NH::independents[k] - 1]);
  return out;
}
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

// linearize_equations with the directions in batches of jets of Batch. M~ and u_ind' at s come from
// numbers, by the calls constrained_motion makes. On jets res = M~ u' - f~ = T^T (M u'_s - f) is
// the forcing along v~ at u'_s = (u_ind', A u_ind' + b_dep): the rest accelerations plus v u'_s
// (rates::of_state takes away v times the u' it is given: here -u'_s). M is never formed on jets.
template <class Sys, class NH, class Ev, class H, class In, std::size_t Batch>
equations_of<NH, Ev, H, In> equations_in_batches(const typename Ev::state_type& s) {
  using S = typename Ev::scalar;
  constexpr std::size_t nq = Ev::state_type::nq, p = NH::p, m = NH::m;
  constexpr auto qi = independent_coordinates<H, nq>();
  constexpr auto qs = directions<Sys, NH, Ev, H>;
  constexpr std::size_t nj = qs.n + p, n = nj + In::n, b = batch_of<n, Batch>;
  using J = jet<S, b>;
  using JEv = typename rebind_evaluator<Ev, J>::type;
  equations_of<NH, Ev, H, In> out;
  out.K.setZero();  // the columns of held coordinates
  Eigen::Matrix<S, int(p), 1> ud;
  {  // numbers at s: M~ u_ind' = f~
    typename Ev::state_type s0 = s;
    std::array<S, nq + p> x0;
    for (std::size_t i = 0; i < nq; ++i) x0[i] = s.q[i];
    for (std::size_t k = 0; k < p; ++k) x0[nq + k] = s.u[NH::independents[k] - 1];
    Ev ev;
    const auto sol = update_at_independent_speeds<NH, checked_at_end<every_read<Ev>>>(ev, s0, x0);
    std::array<S, m> b_dep;
    const auto eq = reduced_equations_at<Sys, NH, rates::at_rest, checking::at_end>(ev, sol, b_dep);
    const auto solved = speed_derivatives_at(eq);
    out.M = eq.M;
    ud = solved.ud;
    out.status = solved.status;
  }
  for (std::size_t lo = 0; lo < n; lo += b) {
    solve_status status;
    auto [js, x] = constrained_point<Sys, NH, Ev, H, In, b>(s, status, lo);
    js.ud = {};  // the state at x: u_dep = A u_ind + B, u' = 0
    JEv ev;
    const auto sol = update_at_independent_speeds<NH, every_read<JEv>>(ev, js, x);
    std::array<J, m> b_dep;
    const auto rates_solved = dependent_rates_at_rest<NH, rates::at_rest>(ev, sol, b_dep);
    Eigen::Matrix<J, int(NH::n), 1> minus_ud;  // -u'_s but for b_dep, which the columns add
    for (std::size_t k = 0; k < p; ++k)
      minus_ud(Eigen::Index(NH::independents[k] - 1)) = J(-ud(Eigen::Index(k)));
    for (std::size_t j = 0; j < m; ++j) {
      J a(0);
      for (std::size_t k = 0; k < p; ++k) a += sol.A(Eigen::Index(j), Eigen::Index(k)) * ud(Eigen::Index(k));
      minus_ud(Eigen::Index(NH::dependents[j] - 1)) = -a;
    }
    forcing_only<J, p> f{Eigen::Matrix<J, int(p), 1>::Zero(), ev.status()};
    with_common_subexpressions(system_terms<typename JEv::root, speeds_of<JEv>>(typename Sys::items{}), ev,
                               [&](const auto& e) {
                                 add_items<Sys, rates::of_state, parts::forcing>(
                                     f, e, independent_speeds<NH, J>{sol.A, b_dep}, minus_ud);
                               });
    if (out.status == solve_status::ok)
      out.status = failed_first(status, failed_first(sol.status, failed_first(rates_solved, f.status)));
    const auto in_batch = [&](std::size_t d) { return d != no_slot && d >= lo && d < lo + b; };
    for (std::size_t r = 0; r < p; ++r) {
      const J& res = f.f(Eigen::Index(r));  // -(M~ u' - f~); 0 - x keeps zeros +0
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
