// The jets of a linearization of a nonholonomic system (linearize.hpp): the point x = (q_ind, u_ind)
// on jets with q_dep through the holonomic constraints, and the forcing of Kane's reduced equations
// there on jets.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/dynamics/constrained_motion.hpp"
#include "kane/evaluation/configuration.hpp"
#include "kane/linearization/held_coordinates.hpp"
#include "kane/linearization/jet.hpp"
#include "kane/linearization/lift.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {
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
    if (lo < qs.n) status = dependent_jets<H, Ev, qs>(s, js, lo, hi);  // no held coordinate beyond
  } else if constexpr (!std::is_void_v<H>) {  // q_dep -= J^-1 f on jets (inputs may enter f)
    JEv ev;
    const auto r = solve_configuration<H>(ev, js, {J(-1), 1});
    if (r.status != solve_status::not_converged) status = r.status;
  }
  for (std::size_t i = 0; i < nq; ++i) x[i] = js.q[i];
  for (std::size_t k = 0; k < NH::p; ++k) x[nq + k] = seeded(qs.n + k, s.u[NH::independents[k] - 1]);
  return out;
}
// One batch of directions [lo, lo + B) on jets: f = -(M~ u' - f~) = T^T (f - M u'_s) with u'_s =
// (u_ind', A u_ind' + b_dep): the forcing along v~ at the rest accelerations plus v u'_s
// (rates::of_state takes away v times the u' it is given: here -u'_s). M is never formed on jets.
// u_ind' may be jets: f is linear in u', so its derivatives along u_ind' are -M~, exactly.
template <class Sys, class NH, class Ev, class H, class In, std::size_t B>
auto reduced_forcing_on_jets(const typename Ev::state_type& s,
                             const Eigen::Matrix<jet<typename Ev::scalar, B>, int(NH::p), 1>& ud,
                             std::size_t lo) {
  using J = jet<typename Ev::scalar, B>;
  using JEv = typename rebind_evaluator<Ev, J>::type;
  constexpr std::size_t p = NH::p, m = NH::m;
  struct {
    Eigen::Matrix<J, int(p), 1> f;
    solve_status status;
  } out;
  auto [js, x] = constrained_point<Sys, NH, Ev, H, In, B>(s, out.status, lo);
  js.ud = {};  // the state at x: u_dep = A u_ind + B, u' = 0
  JEv ev;
  const auto sol = update_at_independent_speeds<NH, every_read<JEv>>(ev, js, x);
  std::array<J, m> b_dep;
  const auto rates_solved = dependent_rates_at_rest<NH, rates::at_rest>(ev, sol, b_dep);
  Eigen::Matrix<J, int(NH::n), 1> minus_ud;  // -u'_s = -T u_ind' but for b_dep, which the columns add
  for (std::size_t k = 0; k < p; ++k) minus_ud(Eigen::Index(NH::independents[k] - 1)) = -ud(Eigen::Index(k));
  for (std::size_t j = 0; j < m; ++j) {  // by hand: Eigen's product on jets costs the compiler more
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
  out.f = f.f;
  out.status = failed_first(out.status, failed_first(sol.status, failed_first(rates_solved, f.status)));
  return out;
}
}  // namespace kane::detail
#pragma GCC diagnostic pop
