// Lanes: W states in one number. kane::lanes<double, 8> is the scalar of a state that holds eight
// states at once; every operation acts lane by lane in vector registers, and comparisons give a
// mask of W truth values. Statuses come per lane (kane::lane_status), so a lane that is singular
// or not finite reports its own status and NaN while the other lanes go on.
//
//   using L = kane::lanes<double, 8>;
//   L x = 0.5;                 // every lane 0.5
//   x.set(3, 1.0);             // lane 3
//   double y = x[3];           // 1.0
//
// The arithmetic is GCC's and Clang's vector types; sine and cosine are evaluated in vector
// registers, the other functions lane by lane. Optional: kane.hpp does not include this header.
#pragma once

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "kane/detail/lane_invert.hpp"
#include "kane/detail/lane_math.hpp"
#include "kane/detail/lane_transpose.hpp"
#include "kane/detail/packet.hpp"
#include "kane/scalars/scalar.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wpsabi"
namespace kane {

// The lanes of S that one vector register of the target holds: for double 8 with AVX-512, 4 with
// AVX, 2 with SSE2.
template <std::floating_point S>
inline constexpr std::size_t native_lanes = detail::register_bytes / sizeof(S);

// W truth values: what comparisons of kane::lanes give.
template <std::floating_point S, std::size_t W>
struct lane_mask {
  // an integer of S's size per lane: all bits set where true
  using bits_type = std::conditional_t<sizeof(S) == 8, long long, int>;
  typedef bits_type vector __attribute__((vector_size(sizeof(S) * W)));
  vector bits;

  // lane i
  bool operator[](std::size_t i) const { return bits[i] != 0; }
  friend lane_mask operator&(const lane_mask& a, const lane_mask& b) { return {a.bits & b.bits}; }
  friend lane_mask operator|(const lane_mask& a, const lane_mask& b) { return {a.bits | b.bits}; }
  friend lane_mask operator!(const lane_mask& a) { return {~a.bits}; }
  // both operands evaluated: && and || of masks do not short-circuit
  friend lane_mask operator&&(const lane_mask& a, const lane_mask& b) { return a & b; }
  friend lane_mask operator||(const lane_mask& a, const lane_mask& b) { return a | b; }
  // every lane true
  friend bool all_of(const lane_mask& m) { return detail::all_lanes(m.bits); }
  // some lane true
  friend bool any_of(const lane_mask& m) { return !detail::all_lanes(~m.bits); }
};

// W numbers of S, one per state, computed together.
template <std::floating_point S, std::size_t W>
struct lanes {
  static_assert(W >= 2 && (W & (W - 1)) == 0, "kane: lanes<S, W> takes W a power of two, 2 or more");
#if defined(__GNUC__) && !defined(__clang__) && defined(__OPTIMIZE__) && !defined(KANE_ALLOW_WIDE_LANES)
  // g++'s scalar replacement of aggregates (-ftree-sra) computes wrong numbers with vectors wider
  // than a register (the spacecraft of tests/test_lanes.cpp at -O2, 8 doubles without AVX-512)
  static_assert(W <= native_lanes<S>,
                "kane: lanes<S, W> wider than a vector register (W > kane::native_lanes<S>) are "
                "miscompiled by optimizing g++: take W = kane::native_lanes<S>, build for wider "
                "registers (-march=native), or build with -fno-tree-sra and define KANE_ALLOW_WIDE_LANES");
#endif
  // the vector register (or registers) of W numbers
  typedef S vector __attribute__((vector_size(sizeof(S) * W)));
  static constexpr std::size_t width = W;
  vector v;

  lanes() = default;  // like a double: uninitialised; lanes x{}; is zero
  // every lane x
  template <class T>
  requires std::is_arithmetic_v<T> lanes(T x) : v(vector{} + S(x)) {}  // NOLINT: numbers convert
  explicit lanes(const vector& x) : v(x) {}

  // Lane i f(i), built in registers (one wide value, where W stores of one lane each and a wide
  // load of them would wait on the stores).
  template <class F>
  static lanes generate(F f) {
    return [&]<std::size_t... I>(std::index_sequence<I...>) { return lanes(vector{S(f(I))...}); }
    (std::make_index_sequence<W>{});
  }
  // The W numbers at p, one after the other (a structure-of-arrays buffer), at any alignment
  static lanes load(const S* p) {
    lanes x;
    detail::load_first<W>(p, x.v);
    return x;
  }
  // the W numbers to p
  void store(S* p) const { detail::store_first<W>(p, v); }
  // lane i
  S operator[](std::size_t i) const { return v[i]; }
  // lane i set to x
  void set(std::size_t i, S x) { v[i] = x; }

  friend lanes operator+(const lanes& a, const lanes& b) { return lanes(a.v + b.v); }
  friend lanes operator-(const lanes& a, const lanes& b) { return lanes(a.v - b.v); }
  friend lanes operator*(const lanes& a, const lanes& b) { return lanes(a.v * b.v); }
  friend lanes operator/(const lanes& a, const lanes& b) { return lanes(a.v / b.v); }
  friend lanes operator+(const lanes& a) { return a; }
  friend lanes operator-(const lanes& a) { return lanes(-a.v); }
  lanes& operator+=(const lanes& b) { return v += b.v, *this; }
  lanes& operator-=(const lanes& b) { return v -= b.v, *this; }
  lanes& operator*=(const lanes& b) { return v *= b.v, *this; }
  lanes& operator/=(const lanes& b) { return v /= b.v, *this; }

  friend lane_mask<S, W> operator==(const lanes& a, const lanes& b) { return {a.v == b.v}; }
  friend lane_mask<S, W> operator!=(const lanes& a, const lanes& b) { return {a.v != b.v}; }
  friend lane_mask<S, W> operator<(const lanes& a, const lanes& b) { return {a.v < b.v}; }
  friend lane_mask<S, W> operator>(const lanes& a, const lanes& b) { return {a.v > b.v}; }
  friend lane_mask<S, W> operator<=(const lanes& a, const lanes& b) { return {a.v <= b.v}; }
  friend lane_mask<S, W> operator>=(const lanes& a, const lanes& b) { return {a.v >= b.v}; }

  // m ? a : b, lane by lane
  friend lanes select(const lane_mask<S, W>& m, const lanes& a, const lanes& b) {
    return lanes(m.bits ? a.v : b.v);
  }

  friend lanes sin(const lanes& a) {
    vector s, c;
    detail::lane_sincos<S, W>(a.v, s, c);
    return lanes(s);
  }
  friend lanes cos(const lanes& a) {
    vector s, c;
    detail::lane_sincos<S, W>(a.v, s, c);
    return lanes(c);
  }
  friend lanes sqrt(const lanes& a) { return lanes(detail::lane_sqrt<S, W>(a.v)); }

  friend lanes tan(const lanes& a) {
    return each(a, [](S x) { return std::tan(x); });
  }
  friend lanes exp(const lanes& a) {
    return each(a, [](S x) { return std::exp(x); });
  }
  friend lanes log(const lanes& a) {
    return each(a, [](S x) { return std::log(x); });
  }
  friend lanes atan(const lanes& a) {
    return each(a, [](S x) { return std::atan(x); });
  }
  friend lanes atan2(const lanes& y, const lanes& x) {
    lanes r;
    for (std::size_t i = 0; i < W; ++i) r.v[i] = std::atan2(y.v[i], x.v[i]);
    return r;
  }
  friend lanes abs(const lanes& a) { return select(a < lanes(S(0)), -a, a); }

 private:
  template <class F>
  static lanes each(const lanes& a, F f) {
    lanes r;
    for (std::size_t i = 0; i < W; ++i) r.v[i] = f(a.v[i]);
    return r;
  }
};

template <class S, std::size_t W>
struct is_scalar<lanes<S, W>> : std::true_type {};
// S, the real numbers of every lane
template <class S, std::size_t W>
struct real_type<lanes<S, W>> {
  // S
  using type = S;
};
// W states, masks of W truth values
template <class S, std::size_t W>
struct lane_traits<lanes<S, W>> {
  static constexpr std::size_t width = W;
  using mask = lane_mask<S, W>;
  static bool lane(const mask& m, std::size_t i) { return m[i]; }
  static lanes<S, W> select(const mask& m, const lanes<S, W>& a, const lanes<S, W>& b) {
    return lanes<S, W>(m.bits ? a.v : b.v);
  }
  static mask truth(bool b) {
    mask m;
    m.bits = typename mask::vector{} + (b ? -1 : 0);
    return m;
  }
};

// count states (count <= W) of N numbers as N lanes of W: lane l holds the N numbers at row(l), a
// pointer; lanes past count repeat the first state, so that no empty lane reports a status of its own.
// Transposed in vector registers (detail/lane_transpose.hpp).
template <std::size_t W, std::size_t N, class Row>
requires std::is_pointer_v<std::invoke_result_t<const Row&, std::size_t>> KANE_ALWAYS_INLINE auto to_lanes(
    const Row& row, std::size_t count) {
  using S = std::remove_cv_t<std::remove_pointer_t<std::invoke_result_t<const Row&, std::size_t>>>;
  static_assert(std::is_floating_point_v<S>, "kane: to_lanes reads float or double: row(l) points to them");
  std::array<lanes<S, W>, N> x;
  detail::rows_to_lanes<W>(
      x, [&](std::size_t l) { return row(l < count ? l : 0); }, std::make_index_sequence<(N + W - 1) / W>{});
  return x;
}
// count states of N numbers each, as above
template <std::size_t W, class S, std::size_t N>
KANE_ALWAYS_INLINE std::array<lanes<S, W>, N> to_lanes(const std::array<S, N>* states, std::size_t count) {
  return to_lanes<W, N>([&](std::size_t l) { return states[l].data(); }, count);
}
// The first count lanes of x (N lanes of W) into count states of N numbers, state l at row(l)
template <class S, std::size_t W, std::size_t N, class Row>
requires std::is_pointer_v<std::invoke_result_t<const Row&, std::size_t>> KANE_ALWAYS_INLINE void from_lanes(
    const std::array<lanes<S, W>, N>& x, const Row& row, std::size_t count) {
  static_assert(std::is_same_v<std::invoke_result_t<const Row&, std::size_t>, S*>,
                "kane: from_lanes writes the lanes' numbers: row(l) gives an S* for lanes<S, W>");
  detail::lanes_to_rows<W>(x, row, count, std::make_index_sequence<(N + W - 1) / W>{});
}
// into count states, as above
template <class S, std::size_t W, std::size_t N>
KANE_ALWAYS_INLINE void from_lanes(const std::array<lanes<S, W>, N>& x, std::array<S, N>* states,
                                   std::size_t count) {
  from_lanes(
      x, [&](std::size_t l) { return states[l].data(); }, count);
}

// A coupled block of a structured solve (evaluation/block_solve.hpp) in every lane: full pivoting
// picks its pivots per state (detail/lane_invert.hpp). The mask is false in the lanes whose pivot
// fails; their inv is no inverse, and the solve's status makes what it gives there NaN.
template <class S, std::size_t W, int N>
lane_mask<S, W> factor_block(const Eigen::Matrix<lanes<S, W>, N, N>& b, Eigen::Matrix<lanes<S, W>, N, N>& inv,
                             const lanes<S, W>& tol) {
  using L = lanes<S, W>;
  if constexpr (N == 2) {  // detail::invert's closed form, its rule in every lane
    const L a = b(0, 0), c01 = b(0, 1), c10 = b(1, 0), d = b(1, 1);
    const L ab = select(abs(a) > abs(c01), abs(a), abs(c01)),
            cd = select(abs(c10) > abs(d), abs(c10), abs(d));
    const L best = select(ab > cd, ab, cd), det = a * d - c01 * c10;
    const L t = select(tol < L(S(0)), L(std::numeric_limits<S>::epsilon() * S(2)) * best, tol);
    const L r = L(S(1)) / det;  // not waiting on the rule: the caller spoils where it fails
    inv << d * r, -c01 * r, -c10 * r, a * r;
    return best > t && abs(det) > t * best && det - det == L(S(0));
  } else
    return detail::lane_invert(b, inv, tol);
}

}  // namespace kane
#pragma GCC diagnostic pop

// the limits of S in every lane
template <class S, std::size_t W>
class std::numeric_limits<kane::lanes<S, W>> : public std::numeric_limits<S> {
 public:
  static kane::lanes<S, W> epsilon() noexcept { return std::numeric_limits<S>::epsilon(); }
  static kane::lanes<S, W> quiet_NaN() noexcept { return std::numeric_limits<S>::quiet_NaN(); }
  static kane::lanes<S, W> infinity() noexcept { return std::numeric_limits<S>::infinity(); }
  static kane::lanes<S, W> max() noexcept { return std::numeric_limits<S>::max(); }
  static kane::lanes<S, W> min() noexcept { return std::numeric_limits<S>::min(); }
  static kane::lanes<S, W> lowest() noexcept { return std::numeric_limits<S>::lowest(); }
};

// Eigen's traits of S for lanes: one vector operation per number
template <class S, std::size_t W>
struct Eigen::NumTraits<kane::lanes<S, W>> : Eigen::NumTraits<S> {
  using Real = kane::lanes<S, W>;
  using NonInteger = kane::lanes<S, W>;
  using Nested = kane::lanes<S, W>;
  using Literal = kane::lanes<S, W>;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 0,
    ReadCost = 1,
    AddCost = 1,
    MulCost = 1
  };
  static inline Real epsilon() { return Eigen::NumTraits<S>::epsilon(); }
  static inline Real dummy_precision() { return Eigen::NumTraits<S>::dummy_precision(); }
  static inline Real highest() { return Eigen::NumTraits<S>::highest(); }
  static inline Real lowest() { return Eigen::NumTraits<S>::lowest(); }
  static inline int digits10() { return Eigen::NumTraits<S>::digits10(); }
};

// Eigen's fixed-size storage of lanes: their own alignment (a vector's), above the alignment Eigen
// would request for the array's bytes (which Clang refuses to lower).
template <class S, std::size_t W, int Size>
requires(Size != Eigen::Dynamic) struct Eigen::internal::compute_default_alignment<kane::lanes<S, W>, Size> {
  enum { value = 0 };
};
