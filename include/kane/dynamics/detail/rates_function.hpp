// What kane::motion and kane::constrained_motion share: a right-hand side x -> dx/dt with the
// state of its calls (parameters, inputs, time), their status, the entries of q in x, and an
// evaluator at the last call's state. Derived::step computes one call.
#pragma once

#include <array>
#include <cstddef>
#include <iterator>
#include <limits>
#include <tuple>
#include <type_traits>

#include "kane/detail/inline.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/wide_stores.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/scalars/coordinate.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {
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
// Where x's speeds go in a state: u, or q' without a speed set (what such an evaluator reads).
template <class Ev, class St>
auto& speeds_of_state(St& s) {
  if constexpr (std::is_void_v<typename Ev::speed_set>)
    return s.qd;
  else
    return s.u;
}
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
// to[i] = x[from + i], i < N: for contiguous doubles in blocks (detail/wide_stores.hpp), whose
// later wide reads (the evaluator's copies) find them whole in the store buffer.
template <std::size_t N, class S, class X>
KANE_ALWAYS_INLINE void copy_wide(S* to, const X& x, std::size_t from) {
  if constexpr (std::is_same_v<S, double> && contiguous<X>()) {
    const double* in = &x[0] + from;
    store_in_blocks<N>(to, [&](auto i) KANE_ALWAYS_INLINE_LAMBDA { return in[i]; });
  } else if constexpr (lane_traits<S>::width > 1)  // no memmove (detail/lane_copy.hpp)
    static_for_inline<N>([&](auto i) KANE_ALWAYS_INLINE_LAMBDA { to[i] = x[from + i]; });
  else
    for (std::size_t i = 0; i < N; ++i) to[i] = x[from + i];
}
// Reads of a state whose arrays copy_wide stored from X: in blocks where X's are contiguous doubles
template <class Reads>
struct read_in_blocks : Reads {
  static constexpr bool in_blocks = true;
};
template <class Reads, class S, class X>
using reads_of_copy =
    std::conditional_t<std::is_same_v<S, double> && contiguous<X>(), read_in_blocks<Reads>, Reads>;
// dxdt = (q', u') (N numbers of q'), NaN unless ok. The status is not_finite where u' (and q' where
// Check is checking::at_end) is not: for one double state by their bits (finite_bits), else where r,
// the sum of u'_i - u'_i (and q'_i - q'_i), is NaN. Over lanes each number
// x is x (NaN unless the status given is ok) - r: the results wait on that one sum, not on the statuses
// it sets. The products by 1 or NaN take a flag the optimizer cannot thread: a branch here keeps the
// local evaluator's dead stores, and the work behind them such as sin and cos, alive.
template <std::size_t N, checking Check, class S, class Q, class Ud, class DX>
KANE_ALWAYS_INLINE status_of<S> write_checked_rates(DX& dxdt, const Q& qd, const Ud& ud,
                                                    status_of<S> status) {
  constexpr bool lanes = lane_traits<S>::width > 1, at_end = Check == checking::at_end;
  S r = -S(0);
  if constexpr (std::is_same_v<S, double>)  // one flag for one state, by its bits
    fail_unless(status, at_end ? finite_bits(ud, qd) : finite_bits(ud), solve_status::not_finite);
  else {
    r = matrix_residue(ud);
    if constexpr (at_end) r += nonfinite_residue(qd);
    if constexpr (!lanes) fail_unless(status, r == S(0), solve_status::not_finite);
  }
  const auto spoil = nan_unless<S>(opaque_ok<S>(status));
  if constexpr (lanes) fail_unless(status, r == S(0), solve_status::not_finite);
  static_for<N + std::size_t(Ud::SizeAtCompileTime)>([&](auto i) {
    S v;
    if constexpr (i < N)
      v = qd[i];
    else
      v = ud(Eigen::Index(i - N));
    spoil(v);
    dxdt[i] = lanes ? v - r : v;
  });
  return status;
}

// The members both right-hand sides keep; Size entries of x and dx/dt.
template <class Derived, class Ev, std::size_t Size>
class rates_function {
 public:
  // the evaluator's state type
  using state_type = typename Ev::state_type;
  // the evaluator's scalar type
  using scalar = typename Ev::scalar;
  // nq: the number of coordinates; size: the entries of x and dx/dt
  static constexpr std::size_t nq = state_type::nq, size = Size;

  // A state of another type: refused with the type to use.
  template <class St>
  requires(!std::is_same_v<St, state_type>) explicit rates_function(const St&) {
    static_assert(std::is_same_v<St, state_type>,
                  "kane: motion takes the state of its evaluator; for kane::motion<System> declare it "
                  "kane::state_of<System> (with a speed set kane::state_of<System, Speeds>)");
  }

  // Numbers: one function body (the passes, the tables and Eigen's fixed-size loops inlined).
  // A container of a size known at compile time is checked then; others must hold size entries.
  template <class X, class DX>
  requires(sizes_checked<Size, X, DX>()) void operator()(const X& x, DX& dxdt, scalar time) {
    flat<scalar>([&] { static_cast<Derived*>(this)->step(x, dxdt, time); });
  }
  // dxdt a view that writes through its copies (kane::soa_block): a temporary too
  template <class X, class DX>
  requires(std::remove_cvref_t<DX>::writes_through && !std::is_lvalue_reference_v<DX>) void operator()(
      const X& x, DX&& dxdt, scalar time) {
    (*this)(x, dxdt, time);
  }
  // the status of the last call: ok, or why dxdt is NaN
  status_of<scalar> status() const { return status_; }
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
  // The entry of q_I in x and dx/dt.
  template <std::size_t I>
  static constexpr std::size_t index(coordinate<I>) {
    static_assert(I >= 1 && I <= nq, "kane: q_i is not a coordinate of this x (q_1 .. q_nq)");
    return I - 1;
  }

 protected:
  explicit rates_function(const state_type& s) : s_(s) {}
  // the state of the last call (before the first, the constructor's)
  state_type s_;
  status_of<scalar> status_{};
};

}  // namespace kane::detail
#pragma GCC diagnostic pop
