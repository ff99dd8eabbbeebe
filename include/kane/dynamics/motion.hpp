// The equations of motion as a right-hand side for any integrator: x = (q, u),
// dx/dt = (q', u') with q' = W u + X (the kinematic equations of the speeds,
// nq != nu where orientations need it) and u' = M^-1 f.
//
//   kane::motion<System> rhs(s);              // s: a kane::state_of<System>, its parameters
//   kane::motion<System, Speeds> rhs2(s2);    // with a speed set: kane::state_of<System, Speeds>
//   kane::motion<System, Evaluator> rhs3(s3); // an evaluator of one's own (float, more frames)
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

#include <array>
#include <cstddef>
#include <cstring>
#include <iterator>
#include <limits>
#include <tuple>
#include <type_traits>

#include "kane/dynamics/inverse_dynamics.hpp"
#include "kane/dynamics/reduced_equations.hpp"
#include "kane/dynamics/system_evaluator.hpp"
#include "kane/dynamics/system_rules.hpp"
#include "kane/evaluation/reads.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
// The number of entries of a container known at compile time (std::array, a C array, a
// fixed-size Eigen vector), or 0.
template <class X>
constexpr std::size_t fixed_size() {
  using T = std::remove_cvref_t<X>;
  if constexpr (std::is_array_v<T>)
    return std::extent_v<T>;
  else if constexpr (requires { std::tuple_size<T>::value; })
    return std::tuple_size<T>::value;
  else if constexpr (requires { T::SizeAtCompileTime; })
    return T::SizeAtCompileTime > 0 ? std::size_t(T::SizeAtCompileTime) : 0;
  else
    return 0;
}
template <std::size_t Size, class X, class DX>
constexpr bool sizes_checked() {
  static_assert((fixed_size<X>() == 0 || fixed_size<X>() == Size) &&
                    (fixed_size<DX>() == 0 || fixed_size<DX>() == Size),
                "kane: x and dx/dt of kane::motion hold nq + nu numbers (constrained_motion: nq + p); "
                "declare them with motion::size entries");
  return true;
}
// The reads of Ev's update_for: every angular acceleration and q'', at u' = 0 (motion's state).
template <class Ev>
struct every_read {
  static constexpr auto alpha = every<size<typename Ev::closure>::value>();
  static constexpr auto qdd = every<Ev::state_type::nq>();
  static constexpr bool rest = true;
};
// x and dxdt hold Size entries: known at compile time (sizes_checked), or by size() at run time
// (a container without size() is taken at its word). Otherwise the call reads nothing, writes NaN
// into as many entries of dxdt as it has, up to Size, and says wrong_size.
template <std::size_t Size, class X>
KANE_ALWAYS_INLINE bool fits(const X& x) {
  if constexpr (fixed_size<X>() == 0 && requires { x.size(); })
    return std::size_t(x.size()) == Size;
  else
    return true;
}
template <std::size_t Size, class S, class X, class DX>
KANE_ALWAYS_INLINE bool size_fits(const X& x, DX& dxdt) {
  if (fits<Size>(x) && fits<Size>(dxdt)) return true;
  std::size_t n = Size;
  if constexpr (fixed_size<DX>() == 0 && requires { dxdt.size(); })
    n = std::size_t(dxdt.size()) < Size ? std::size_t(dxdt.size()) : Size;
  for (std::size_t i = 0; i < n; ++i) dxdt[i] = std::numeric_limits<S>::quiet_NaN();
  return false;
}
// x's numbers one after the other in memory: a C array, a std::array, an Eigen vector or map of unit
// inner stride
template <class X>
constexpr bool contiguous() {
  if constexpr (std::is_array_v<X> || requires { std::tuple_size<X>::value; }) return requires(const X& x) {
      std::data(x);
    };
  else if constexpr (requires { X::InnerStrideAtCompileTime; })
    return X::InnerStrideAtCompileTime == 1 && requires(const X& x) { x.data(); };
  else
    return false;
}
// to[i] = x[from + i], i < N: for contiguous doubles in pairs of 16 bytes, whose later wide reads
// (the evaluator's copies) find them whole in the store buffer; narrow stores would stall them.
template <std::size_t N, class S, class X>
KANE_ALWAYS_INLINE void copy_wide(S* to, const X& x, std::size_t from) {
  if constexpr (std::is_same_v<S, double> && contiguous<X>()) {
    using pair = double __attribute__((vector_size(16)));
    const double* in = &x[0] + from;
    for (std::size_t i = 0; i + 1 < N; i += 2) {
      pair v;
      std::memcpy(&v, in + i, sizeof v);
      std::memcpy(to + i, &v, sizeof v);
    }
    if constexpr (N % 2 == 1) to[N - 1] = in[N - 1];
  } else
    for (std::size_t i = 0; i < N; ++i) to[i] = x[from + i];
}
// dxdt[i] = q'_i, i < N, NaN unless ok (q' may be finite where u' is NaN): by products and a flag
// the optimizer cannot thread, since a branch here keeps the local evaluator's dead stores (and
// the work behind them, such as sin and cos of an angle nothing reads) alive.
template <std::size_t N, class S, class Q, class DX>
KANE_ALWAYS_INLINE void write_rates(DX& dxdt, const Q& qd, bool ok) {
  const auto spoil = nan_unless<S>(opaque(ok));
  static_for<N>([&](auto i) {
    S v = qd[i];
    spoil(v);
    dxdt[i] = v;
  });
}
}  // namespace detail

// x' = (q', u') of the system Sys for any integrator: f(x, dxdt, t). EvOrSpeeds: the evaluator, or
// the speed set (none: u = q') of the system's own evaluator.
template <class Sys, class EvOrSpeeds = void>
class motion {
  using Ev = detail::evaluator_or_own_t<Sys, EvOrSpeeds>;

 public:
  // the evaluator's state type
  using state_type = typename Ev::state_type;
  // the evaluator's scalar type
  using scalar = typename Ev::scalar;
  // nq, nu: the numbers of coordinates and speeds; size = nq + nu, the entries of x
  static constexpr std::size_t nq = state_type::nq, nu = Ev::nu, size = nq + nu;

  // parameters and inputs from s (each call's x gives q and u); u' and q'' set to 0
  explicit motion(const state_type& s) : s_(s) {
    s_.ud = {}, s_.qdd = {};
    if constexpr (std::is_void_v<typename Ev::speed_set>) s_.u = {};  // x's speeds go to q'
  }
  // A state of another type: refused with the type to use.
  template <class St>
  requires(!std::is_same_v<St, state_type>) explicit motion(const St&) {
    static_assert(std::is_same_v<St, state_type>,
                  "kane: motion takes the state of its evaluator; for kane::motion<System> declare it "
                  "kane::state_of<System> (with a speed set kane::state_of<System, Speeds>)");
  }

  // Numbers: one function body (the passes, the tables and Eigen's fixed-size loops inlined).
  // A container of a size known at compile time is checked then; others must hold size entries.
  template <class X, class DX>
  requires(detail::sizes_checked<size, X, DX>()) void operator()(const X& x, DX& dxdt, scalar time) {
    detail::flat<scalar>([&] { step(x, dxdt, time); });
  }

  // the status of the last call: ok, or why dxdt is NaN
  solve_status status() const { return status_; }
  // The inputs r of the calls from now on (a controller's torques), kept between calls.
  typename state_type::inputs_type& inputs() { return s_.r; }
  // An evaluator updated at the last call's state (before the first call, s's), u' = 0: energies,
  // positions, ... (each call evaluates in a local one, so that the compiler drops what its
  // equations do not read). After a step of several stages that state is the last stage's.
  Ev evaluator() const {
    Ev ev;
    ev.update(s_);
    return ev;
  }
  // An evaluator updated at x and the time t (the step's end), u' = 0, parameters and inputs as
  // now. A run-time size other than size gives NaN coordinates: status not_finite.
  template <class X>
  Ev evaluator(const X& x, scalar time) const {
    state_type s = s_;
    auto& u = [&]() -> auto& {
      if constexpr (std::is_void_v<typename Ev::speed_set>)
        return s.qd;
      else
        return s.u;
    }
    ();
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
  // The entry of q_I in x and dx/dt.
  template <std::size_t I>
  static constexpr std::size_t index(coordinate<I>) {
    static_assert(I >= 1 && I <= nq, "kane: q_i is not a coordinate of this x (q_1 .. q_nq)");
    return I - 1;
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
      status_ = solve_status::wrong_size;
      return;
    }
    auto& u = [&]() -> auto& {  // u = q' without a speed set: what such an evaluator reads
      if constexpr (std::is_void_v<typename Ev::speed_set>)
        return s_.qd;
      else
        return s_.u;
    }
    ();
    detail::copy_wide<nq>(s_.q.data(), x, 0);
    detail::copy_wide<nu>(u.data(), x, nq);
    s_.t = time;
    Ev ev;
    if constexpr (!detail::admitted<Sys, detail::speeds_of<Ev>>())
      return;
    else if constexpr (detail::recursive_form<Sys, Ev>)
      ev.template update_for<detail::every_read<Ev>>(s_);
    else  // Kane's sums read a few angular accelerations and q'' (evaluation/reads.hpp)
      ev.template update_for<equation_reads>(s_);
    const auto [ud, status] = detail::forward_at<Sys, true>(ev);
    status_ = status;
    detail::write_rates<nq, scalar>(dxdt, ev.coordinate_rates(), status == solve_status::ok);
    for (std::size_t i = 0; i < nu; ++i) dxdt[nq + i] = ud(Eigen::Index(i));
  }

  struct equation_reads {
    static constexpr auto reads = detail::acceleration_reads_of<Ev>(
        decltype(detail::system_terms<typename Ev::root, detail::speeds_of<Ev>>(typename Sys::items{})){});
    static constexpr auto alpha = reads.alpha;
    static constexpr auto qdd = reads.qdd;
    static constexpr bool rest = true;  // u' = 0
  };
  state_type s_;
  solve_status status_ = solve_status::ok;
};

}  // namespace kane
#pragma GCC diagnostic pop
