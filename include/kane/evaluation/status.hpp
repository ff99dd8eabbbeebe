// What a numeric solve found: ok, a singular matrix (a pivot at or below the
// rank threshold), numbers that are not finite (NaN or inf in or out), an
// iteration that did not reach its tolerance (configuration.hpp), an
// attitude read from the state that is not a rotation (kane::attitude), or a
// container of another size than the call needs (kane::motion), or q' and u
// (q'' and u') given as different numbers where u is q' (no speed set).
// ok promises finite numbers: the promise rests on IEEE comparisons with NaN,
// which -ffast-math and -ffinite-math-only let the compiler fold away, so
// those flags are an error here unless KANE_ALLOW_FAST_MATH is defined (then
// status() may say ok for NaN or infinite numbers).
#pragma once

#include <array>
#include <cstddef>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include "kane/detail/inline.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/v3.hpp"
#include "kane/detail/wide_stores.hpp"
#include "kane/evaluation/finite.hpp"
#include "kane/scalars/scalar.hpp"

#if (defined(__FAST_MATH__) || (defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__)) && \
    !defined(KANE_ALLOW_FAST_MATH)
#error "kane: finite math only (-ffast-math) voids solve_status: build without or define KANE_ALLOW_FAST_MATH"
#endif

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// ok, a singular matrix, numbers not finite, no convergence, an attitude not a rotation, a
// container of the wrong size, or q' and u that disagree where u is q'
enum class solve_status {
  ok,
  singular,
  not_finite,
  not_converged,
  not_a_rotation,
  wrong_size,
  conflicting_rates
};
// The name of a status ("ok", "singular", ...).
constexpr const char* to_string(solve_status s) {
  switch (s) {
    case solve_status::ok:
      return "ok";
    case solve_status::singular:
      return "singular";
    case solve_status::not_finite:
      return "not_finite";
    case solve_status::not_converged:
      return "not_converged";
    case solve_status::not_a_rotation:
      return "not_a_rotation";
    case solve_status::wrong_size:
      return "wrong_size";
    case solve_status::conflicting_rates:
      return "conflicting_rates";
  }
  return "unknown";
}

// The statuses of one call over kane::lanes (kane/scalars/lanes.hpp): one per lane.
template <std::size_t W>
struct lane_status {
  // the statuses' codes in one vector, 64 bits a lane as the masks of doubles (named through W:
  // g++ drops a vector size that depends on W from a type that does not)
  using code_type = std::conditional_t<W != 0, long long, long>;
  typedef code_type codes __attribute__((vector_size(sizeof(long long) * W)));
  codes code{};
  constexpr lane_status() = default;
  // s in every lane
  constexpr explicit lane_status(solve_status s) : code(codes{} + static_cast<long long>(s)) {}
  // lane i's
  constexpr solve_status operator[](std::size_t i) const { return solve_status(code[i]); }
  // every lane ok
  constexpr bool all_ok() const {
    bool ok = true;
    for (std::size_t i = 0; i < W; ++i) ok = ok && code[i] == 0;
    return ok;
  }
  friend constexpr bool operator==(const lane_status& a, const lane_status& b) {
    bool same = true;
    for (std::size_t i = 0; i < W; ++i) same = same && a.code[i] == b.code[i];
    return same;
  }
};
// The status of a call over S: one solve_status, or one per lane
template <class S>
using status_of =
    std::conditional_t<lane_traits<S>::width == 1, solve_status, lane_status<lane_traits<S>::width>>;

namespace detail {
// Where a computation checks its numbers: each stage its own results (each), or its inputs, its rank
// tests and its last results alone (at_end: one check a call, as kane::motion's).
enum class checking { each, at_end };
// The reads of an evaluator's update whose caller checks its last results (checking::at_end)
template <class Reads>
struct checked_at_end : Reads {
  static constexpr bool at_end = true;
};
template <class Reads>
inline constexpr checking checking_of = requires {
  Reads::at_end;
}
? checking::at_end : checking::each;
// st = why where st is ok and good is false (lane by lane where good is a mask).
template <class Status, class Mask>
KANE_ALWAYS_INLINE void fail_unless(Status& st, const Mask& good, solve_status why) {
  static_assert(int(solve_status::ok) == 0);
  if constexpr (std::is_same_v<Status, solve_status>) {
    if (st == solve_status::ok && !good) st = why;  // a branch: g++ threads it (a select keeps more)
  } else {
    using codes = typename Status::codes;
    codes bad;
    if constexpr (std::is_same_v<Mask, bool>)  // the same in every lane
      bad = codes{} - (!good ? 1 : 0);
    else
      bad = __builtin_convertvector(good.bits, codes) == 0;
    st.code = (st.code == 0) & bad ? codes{} + static_cast<long long>(why) : st.code;
  }
}
// The status of the first condition that fails, ok where all hold: checks<S>(c1, s1, c2, s2, ...);
// for one state the chain !c1 ? s1 : !c2 ? s2 : ... : ok.
template <class S, class C, class... A>
KANE_ALWAYS_INLINE status_of<S> checks(const C& c, solve_status why, const A&... rest) {
  if constexpr (lane_traits<S>::width == 1) {
    if constexpr (sizeof...(A) == 0)
      return !c ? why : solve_status::ok;
    else
      return !c ? why : checks<S>(rest...);
  } else {
    status_of<S> st{};
    fail_unless(st, c, why);
    if constexpr (sizeof...(A) > 0) {
      const status_of<S> later = checks<S>(rest...);
      st.code = st.code == 0 ? later.code : st.code;
    }
    return st;
  }
}
// st = next where st is ok (lane by lane)
template <class Status>
KANE_ALWAYS_INLINE void then(Status& st, const Status& next) {
  if constexpr (std::is_same_v<Status, solve_status>) {
    if (st == solve_status::ok) st = next;
  } else
    st.code = st.code == 0 ? next.code : st.code;
}
// a where a is not ok, else b (lane by lane): a select for one state
template <class Status>
KANE_ALWAYS_INLINE Status failed_first(const Status& a, const Status& b) {
  if constexpr (std::is_same_v<Status, solve_status>)
    return a != solve_status::ok ? a : b;
  else {
    Status st;
    st.code = a.code != 0 ? a.code : b.code;
    return st;
  }
}
// b in every lane, as S's truth values
template <class S>
KANE_ALWAYS_INLINE typename lane_traits<S>::mask truth(bool b) {
  return lane_traits<S>::truth(b);
}
// st ok, as S's truth values (one per lane for lanes)
template <class S>
KANE_ALWAYS_INLINE typename lane_traits<S>::mask ok_of(const status_of<S>& st) {
  if constexpr (lane_traits<S>::width == 1)
    return st == solve_status::ok;
  else {
    using mask = typename lane_traits<S>::mask;
    return mask{__builtin_convertvector(st.code == 0, typename mask::vector)};
  }
}
// spoil(x) makes x (an S or a matrix of S) NaN unless ok: for numbers a product
// by 1 or NaN (no branch, so the results need not merge), else a store.
template <class S, class Mask = bool>
KANE_ALWAYS_INLINE auto nan_unless(const Mask& ok) {
  if constexpr (std::is_floating_point_v<S>)
    return [factor = ok ? S(1) : std::numeric_limits<S>::quiet_NaN()](auto& x) { x *= factor; };
  else if constexpr (lane_traits<S>::width > 1)
    return [factor = lane_traits<S>::select(ok, S(1), std::numeric_limits<S>::quiet_NaN())](auto& x) {
      x *= factor;
    };
  else
    return [ok](auto& x) {
      if (ok) return;
      const S nan = std::numeric_limits<S>::quiet_NaN();
      if constexpr (requires { x.setConstant(nan); })
        x.setConstant(nan);
      else
        x = nan;
    };
}
// As nan_unless; for lanes a select behind a branch taken only where some lane failed, so that
// the results do not wait on the checks. Not for a call's last results: a branch there keeps
// a local evaluator's dead stores alive, and the work behind them (rates_function.hpp).
template <class S, class Mask = bool>
KANE_ALWAYS_INLINE auto nan_unless_rare(const Mask& ok) {
  if constexpr (lane_traits<S>::width > 1)
    return [ok, all = all_of(ok)](auto& x) KANE_ALWAYS_INLINE_LAMBDA {
      if (all) return;
      const S nan = S(std::numeric_limits<typename real_type<S>::type>::quiet_NaN());
      using X = std::remove_cvref_t<decltype(x)>;
      if constexpr (std::is_same_v<X, S>)
        x = lane_traits<S>::select(ok, x, nan);
      else if constexpr (requires { X::SizeAtCompileTime; })
        static_for_inline<std::size_t(X::SizeAtCompileTime)>([&](auto i) KANE_ALWAYS_INLINE_LAMBDA {
          x.coeffRef(Eigen::Index(i)) = lane_traits<S>::select(ok, x.coeff(Eigen::Index(i)), nan);
        });
      else
        static_for_inline<std::tuple_size<X>::value>(
            [&](auto i) KANE_ALWAYS_INLINE_LAMBDA { x[i] = lane_traits<S>::select(ok, x[i], nan); });
    };
  else
    return nan_unless<S>(ok);
}
// x (a fixed-size Eigen matrix) NaN unless ok, as nan_unless; doubles rewritten in blocks
// (detail/wide_stores.hpp), which a copy of x reads whole.
template <class M, class Mask = bool>
KANE_ALWAYS_INLINE void spoil_unless(M& x, const Mask& ok) {
  using S = typename M::Scalar;
  if constexpr (std::is_floating_point_v<S> && std::is_base_of_v<Eigen::PlainObjectBase<M>, M>) {
    const S factor = ok ? S(1) : std::numeric_limits<S>::quiet_NaN();
    store_in_blocks<std::size_t(M::SizeAtCompileTime)>(
        x.data(), [&](auto i) KANE_ALWAYS_INLINE_LAMBDA { return S(x.coeff(std::ptrdiff_t(i)) * factor); });
  } else
    nan_unless<S>(ok)(x);
}
// ok_of(st) hidden from the optimizer for one state (detail/inline.hpp: opaque)
template <class S>
KANE_ALWAYS_INLINE typename lane_traits<S>::mask opaque_ok(const status_of<S>& st) {
  if constexpr (lane_traits<S>::width == 1)
    return opaque(st == solve_status::ok);
  else
    return ok_of<S>(st);
}
// The numbers of x (a std::array) NaN where st is not ok: a branch for one state and for lanes.
template <class S, class X>
KANE_ALWAYS_INLINE void nan_where_failed(const status_of<S>& st, X& x) {
  if constexpr (lane_traits<S>::width == 1) {
    if (st != solve_status::ok) fill_nan(x);
  } else {
    nan_unless_rare<S>(ok_of<S>(st))(x);
  }
}
// The status of a result x computed at status: not_finite where x is not, and x NaN unless ok.
// For lanes x becomes x (NaN unless the status given is ok) - r, with r the sum of x_i - x_i: 0 if
// every x_i is finite, else NaN (x - 0 is x, also for x = -0). So x waits on its own sum, not on
// the status that the sum sets.
template <class M>
status_of<typename M::Scalar> finished(M& x, status_of<typename M::Scalar> status) {
  using S = typename M::Scalar;
  if constexpr (lane_traits<S>::width > 1) {
    const S r = matrix_residue(x);
    nan_unless<S>(ok_of<S>(status))(x);
    x.array() -= r;
    fail_unless(status, r == S(0), solve_status::not_finite);
  } else {
    fail_unless(status, all_finite_matrix(x), solve_status::not_finite);
    if (status != solve_status::ok) x.setConstant(std::numeric_limits<S>::quiet_NaN());
  }
  return status;
}
}  // namespace detail

}  // namespace kane
#pragma GCC diagnostic pop
