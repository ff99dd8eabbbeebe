// The equations of motion as a right-hand side for any integrator: x = (q, u),
// dx/dt = (q', u') with q' = W u + X (the kinematic equations of the speeds,
// nq != nu where orientations need it) and u' = M^-1 f.
//
//   kane::motion<System> rhs(s);              // s: a kane::state_of<System>, its parameters
//   kane::motion<System, Speeds> rhs2(s2);    // with a speed set: kane::state_of<System, Speeds>
//   kane::motion<System, Evaluator> rhs3(s3); // an evaluator of one's own (float, more frames)
//   kane::motion<System, Speeds, S> rhs4(s4); // the system's evaluator over S (float, kane::lanes)
//   rhs(x, dxdt, t);                          // Boost.Odeint's signature; x: nq + nu numbers
//   rhs.inputs() = r;                         // inputs r (kane::r<i> in loads) of the calls from now on
//
// The system's own evaluator (kane::system_evaluator) holds the frames its items read.
// Without a speed set the speeds are u = q' (x = (q, q'), dx/dt = (q', q'')).
// x and dxdt are any containers with operator[] and nq + nu entries (motion::size): std::array,
// Eigen vectors or maps, plain arrays; no allocation. A size known at compile time is checked
// then, one known at run time (size()) at each call: wrong_size, nothing read, dxdt NaN. status()
// is that of the last call: when it is not ok, dxdt is NaN.
#pragma once

#include <cstddef>
#include <type_traits>

#include "kane/dynamics/detail/method.hpp"
#include "kane/dynamics/detail/rates_function.hpp"
#include "kane/dynamics/detail/system_rules.hpp"
#include "kane/dynamics/forward_dynamics.hpp"
#include "kane/dynamics/reduced_equations.hpp"
#include "kane/dynamics/system_evaluator.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// x' = (q', u') of the system Sys for any integrator: f(x, dxdt, t). EvOrSpeeds: the evaluator, or
// the speed set (none: u = q') of the system's own evaluator.
template <System Sys, class EvOrSpeeds = void, Scalar S = double>
class motion
    : public detail::rates_function<motion<Sys, EvOrSpeeds, S>, detail::own_evaluator_t<Sys, EvOrSpeeds, S>,
                                    detail::own_evaluator_t<Sys, EvOrSpeeds, S>::state_type::nq +
                                        detail::own_evaluator_t<Sys, EvOrSpeeds, S>::nu> {
  using Ev = detail::own_evaluator_t<Sys, EvOrSpeeds, S>;
  using base = detail::rates_function<motion, Ev, Ev::state_type::nq + Ev::nu>;
  friend base;
  using base::s_;
  using base::status_;

 public:
  using base::index;
  using base::nq;
  using base::size;
  using typename base::scalar;
  using typename base::state_type;
  // nu: the number of speeds
  static constexpr std::size_t nu = Ev::nu;

  // parameters and inputs from s (each call's x gives q and u); u' and q'' set to 0
  explicit motion(const state_type& s) : base(s) {
    s_.ud = {}, s_.qdd = {};
    if constexpr (std::is_void_v<typename Ev::speed_set>) s_.u = {};  // x's speeds go to q'
  }
  // A state of another type: refused with the type to use.
  template <class St>
  requires(!std::is_same_v<St, state_type>) explicit motion(const St& s) : base(s) {}

  // An evaluator updated at x and the time t (the step's end), u' = 0, parameters and inputs as
  // now. A run-time size other than size gives NaN coordinates: status not_finite.
  using base::evaluator;
  template <class X>
  Ev evaluator(const X& x, scalar time) const {
    state_type s = s_;
    auto& u = detail::speeds_of_state<Ev>(s);
    if (detail::fits<size>(x)) {
      for (std::size_t i = 0; i < nq; ++i) s.q[i] = x[i];
      for (std::size_t i = 0; i < nu; ++i) u[i] = x[nq + i];
    } else
      detail::fill_nan(s.q);
    s.t = time;
    Ev ev;
    ev.update(s);
    return ev;
  }
  // The entry of u_R (u_R') in x (dx/dt).
  template <std::size_t R>
  static constexpr std::size_t index(speed<R>) {
    static_assert(R >= 1 && R <= nu, "kane: u_r is not a speed of this x (u_1 .. u_nu)");
    return nq + R - 1;
  }

 private:
  template <class X, class DX>
  void step(const X& x, DX& dxdt, scalar time) {
    if (!detail::size_fits<size, scalar>(x, dxdt)) {
      status_ = status_of<scalar>(solve_status::wrong_size);
      return;
    }
    auto& u = detail::speeds_of_state<Ev>(s_);
    detail::copy_wide<nq>(s_.q.data(), x, 0);
    detail::copy_wide<nu>(u.data(), x, nq);
    s_.t = time;
    Ev ev;
    constexpr auto at_end = detail::checking::at_end;  // one check: inputs, ranks, then q' and u'
    using reads = detail::reads_of_copy<detail::equation_reads<Sys, Ev, true>, scalar, X>;
    if constexpr (!detail::admitted<Sys, detail::speeds_of<Ev>>())
      return;
    else
      ev.template update_for<detail::checked_at_end<reads>>(s_);
    const auto r = detail::forward_at<Sys, detail::rates::zero, Ev, false, at_end>(ev);
    status_ = detail::write_checked_rates<nq, at_end, scalar>(dxdt, ev.coordinate_rates(), r.ud, r.status);
  }
};

}  // namespace kane
#pragma GCC diagnostic pop
