// The equations of motion of a nonholonomic system as a right-hand side for any integrator:
// x = (q, u_ind), dx/dt = (q', u_ind') with u_dep = A u_ind + B at every call and u_ind' from Kane's
// reduced equations.
//
//   kane::constrained_motion<System, NH> rhs(s);  // s: kane::state_of<System, NH::speed_set>
//   kane::constrained_motion<System, NH, Evaluator> rhs2(s2);  // an evaluator of one's own
//   kane::constrained_motion<System, NH, S> rhs3(s3);          // the own one over S (kane::lanes)
//   rhs(x, dxdt, t);                           // x: nq + p numbers
//   rhs.project<H>(x);                         // closes holonomic constraints H between steps
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>

#include "kane/dynamics/motion.hpp"
#include "kane/dynamics/reduced_equations.hpp"
#include "kane/evaluation/configuration.hpp"
#include "kane/speeds/holonomic.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
// The place of v in a, or N
template <class T, std::size_t N>
constexpr std::size_t place_in(const std::array<T, N>& a, std::size_t v) {
  std::size_t i = 0;
  while (i < N && a[i] != v) ++i;
  return i;
}
// s at the independent speeds x[nq + k]: u_dep = A u_ind + B from the constraints NH at s's q and t,
// and ev updated to s (pose, then speeds); the constraints' solution. Reads: those of
// update_speeds_for (checked_at_end: A, B and q' unchecked, for a caller that checks its results).
template <class NH, class Reads = void, class Ev, class St, class X>
auto update_at_independent_speeds(Ev& ev, St& s, const X& x) {
  constexpr std::size_t nq = St::nq;
  ev.update_pose(s);  // A and B depend on q and t alone
  constexpr checking check = std::is_void_v<Reads> ? checking::each : checking_of<Reads>;
  constexpr bool rest = requires { Reads::rest; };  // u' = 0: C and c0 unread
  const auto sol = solve_constraints_at<NH, check, !rest>(ev);
  std::array<typename St::scalar, NH::m> dep;
  static_for<NH::m>([&](auto j) {  // unrolled: a loop at -O2
    dep[j] = sol.B(Eigen::Index(j));
    static_for<NH::p>([&](auto k) { dep[j] += sol.A(Eigen::Index(j), Eigen::Index(k)) * x[nq + k]; });
  });
  store_in_blocks<NH::n>(s.u.data(), [&](auto i) KANE_ALWAYS_INLINE_LAMBDA {  // the update copies u whole
    constexpr std::size_t k = place_in(NH::independents, i + 1), j = place_in(NH::dependents, i + 1);
    if constexpr (k < NH::p)
      return typename St::scalar(x[nq + k]);
    else
      return dep[j];
  });
  if constexpr (std::is_void_v<Reads>)
    ev.update_speeds(s);
  else
    ev.template update_speeds_for<Reads>(s);
  return sol;
}

template <class... C>
list<C...> listed(const std::tuple<C...>&);
// the constraints' expressions
template <class NH>
using constraint_terms = decltype(listed(NH::equations));
}  // namespace detail

// A nonholonomic system (constraints NH): x = (q, u_ind), p independent speeds;
// at each call u_dep = A u_ind + B, then u_ind' from Kane's reduced equations. Ev: the system's
// own evaluator with NH's speed set and the frames of its constraints, or one's own.
template <System Sys, Nonholonomic NH, class EvOrScalar = double,
          class Ev =
              detail::own_evaluator_t<Sys, typename NH::speed_set, EvOrScalar, detail::constraint_terms<NH>>>
class constrained_motion
    : public detail::rates_function<constrained_motion<Sys, NH, EvOrScalar>, Ev, Ev::state_type::nq + NH::p> {
  using base = detail::rates_function<constrained_motion, Ev, Ev::state_type::nq + NH::p>;
  friend base;
  using base::s_;
  using base::status_;

 public:
  using base::index;
  using base::nq;
  using base::size;
  using typename base::scalar;
  using typename base::state_type;
  // p: the number of independent speeds
  static constexpr std::size_t p = NH::p;

  // parameters and inputs from s (each call's x gives q and u_ind); u' set to 0
  explicit constrained_motion(const state_type& s) : base(s) { s_.ud = {}; }
  // A state of another type: refused with the type to use.
  template <class St>
  requires(!std::is_same_v<St, state_type>) explicit constrained_motion(const St& s) : base(s) {}

  using base::evaluator;
  // An evaluator updated at x and the time t (the step's end), the dependent speeds solved, u' = 0.
  // A run-time size other than size gives NaN coordinates: status not_finite.
  template <class X>
  Ev evaluator(const X& x, scalar time) const {
    state_type s = s_;
    s.t = time;
    Ev ev;
    if (detail::fits<size>(x)) {
      for (std::size_t i = 0; i < nq; ++i) s.q[i] = x[i];
      detail::update_at_independent_speeds<NH>(ev, s, x);
    } else {
      detail::fill_nan(s.q);
      ev.update(s);
    }
    return ev;
  }
  // The entry of the independent speed u_R (u_R') in x (dx/dt).
  template <std::size_t R>
  static constexpr std::size_t index(speed<R>) {
    constexpr std::size_t k = [] {
      std::size_t i = 0;
      while (i < p && NH::independents[i] != R) ++i;
      return i;
    }();
    static_assert(k < p, "kane: u_r is not an independent speed of this x (a dependent speed?)");
    return nq + k;
  }
  // The state of the last call, its dependent speeds solved.
  const state_type& state() const { return s_; }
  // x's dependent coordinates of the holonomic constraints H closed again by Newton's method from x
  // (solve_configuration), to call between steps: an integrator keeps only their rates. x's other
  // entries are kept, and so are all of them unless the status is ok; a run-time size other than
  // size gives wrong_size.
  template <Holonomic H, class X>
  requires(detail::sizes_checked<size, X, X>())
      newton_result<scalar> project(X& x, newton_options<scalar> options = {}) {
    if (!detail::fits<size>(x))
      return {solve_status::wrong_size, 0, std::numeric_limits<scalar>::quiet_NaN()};
    state_type s = s_;
    for (std::size_t i = 0; i < nq; ++i) s.q[i] = x[i];
    Ev ev;
    const auto closed = solve_configuration<H>(ev, s, options);
    if (closed.status == solve_status::ok)
      for (std::size_t i : H::dependents) x[i - 1] = s.q[i - 1];
    return closed;
  }

 private:
  template <class X, class DX>
  void step(const X& x, DX& dxdt, scalar time) {
    if (!detail::size_fits<size, scalar>(x, dxdt)) {
      status_ = status_of<scalar>(solve_status::wrong_size);
      return;
    }
    detail::copy_wide<nq>(s_.q.data(), x, 0);
    s_.t = time;
    Ev ev;
    constexpr auto at_end = detail::checking::at_end;  // one check: inputs, ranks, then q' and u_ind'
    const auto sol = detail::update_at_independent_speeds<NH, detail::checked_at_end<detail::every_read<Ev>>>(
        ev, s_, x);  // the constraints' derivatives read every alpha and q''
    std::array<scalar, NH::m> b_dep;
    const auto [ud, status] = detail::speed_derivatives_at<false>(
        detail::reduced_equations_at<Sys, NH, detail::rates::at_rest, at_end>(ev, sol, b_dep));
    status_ = detail::write_checked_rates<nq, at_end, scalar>(dxdt, ev.coordinate_rates(), ud, status);
  }
};

}  // namespace kane
#pragma GCC diagnostic pop
