// ^F p: the components of a vector p expressed in frame F.
#pragma once

#include <cmath>
#include <type_traits>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "kane/detail/frame_check.hpp"
#include "kane/frames/frame.hpp"
#include "kane/fwd.hpp"
#include "kane/scalars/scalar.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// p = a1 e_F1 + a2 e_F2 + a3 e_F3 held as (a1, a2, a3); index 0..2.
// Default construction gives the zero vector. Frames never convert implicitly.
// Stored as S[3] (trivially copyable), viewed by Eigen through a Map.
template <class F, class S = double>
class vec {
  static_assert(Frame<F>,
                "kane: vec<F> needs a frame F (a struct derived from kane::root_frame or kane::frame)");
  static_assert(Scalar<S>,
                "kane: vec<F, S> needs a scalar type S (float, double, or one admitted by kane::is_scalar)");

 public:
  // F, the frame of the components
  using frame = F;
  // the scalar type S
  using scalar = S;
  // the 3x1 matrix of S
  using eigen_type = Eigen::Matrix<S, 3, 1>;

  vec() = default;
  // a1 e_F1 + a2 e_F2 + a3 e_F3
  vec(S a1, S a2, S a3) : c_{a1, a2, a3} {}
  // From any Eigen 3x1 expression, evaluated straight into the storage.
  template <class Derived>
  explicit vec(const Eigen::MatrixBase<Derived>& m) {
    eigen() = m;
  }

  // from another frame: an error (change frames with express)
  template <class G>
  requires DifferentFrames<G, F> vec(const vec<G, S>&) {
    static_assert(detail::refused<error::frames_differ_use_express_to_change_frame<G, F>>);
  }

  // e_F1 = (1, 0, 0)
  static vec e1() { return vec(S(1), S(0), S(0)); }
  // e_F2 = (0, 1, 0)
  static vec e2() { return vec(S(0), S(1), S(0)); }
  // e_F3 = (0, 0, 1)
  static vec e3() { return vec(S(0), S(0), S(1)); }

  // a_(i+1), i = 0..2
  S operator[](int i) const { return c_[i]; }
  // a_(i+1), writable
  S& operator[](int i) { return c_[i]; }

  // The components as an Eigen vector (a view: no copy).
  // On a temporary it is a copy, so that no view outlives its vector.
  Eigen::Map<const eigen_type> eigen() const& { return Eigen::Map<const eigen_type>(c_); }
  // the components as a writable view
  Eigen::Map<eigen_type> eigen() & { return Eigen::Map<eigen_type>(c_); }
  // the components, copied: no view of a temporary
  eigen_type eigen() && { return Eigen::Map<const eigen_type>(c_); }
  // the components of a const temporary, copied
  eigen_type eigen() const&& { return Eigen::Map<const eigen_type>(c_); }  // a copy: no view of a temporary

  // p = p + q
  vec& operator+=(const vec& o) {
    eigen() += o.eigen();
    return *this;
  }
  // p = p - q
  vec& operator-=(const vec& o) {
    eigen() -= o.eigen();
    return *this;
  }
  // p = k p
  vec& operator*=(S k) {
    eigen() *= k;
    return *this;
  }
  // p = p / k
  vec& operator/=(S k) {
    eigen() /= k;
    return *this;
  }

 private:
  S c_[3] = {};  // trivially copyable; the zero vector by default
};

template <class T, class S>
concept ScalarFactor = std::is_arithmetic_v<T> || std::is_same_v<T, S>;

// p + q componentwise
template <class F, class S>
vec<F, S> operator+(const vec<F, S>& a, const vec<F, S>& b) {
  return vec<F, S>(a.eigen() + b.eigen());
}
// p - q componentwise
template <class F, class S>
vec<F, S> operator-(const vec<F, S>& a, const vec<F, S>& b) {
  return vec<F, S>(a.eigen() - b.eigen());
}
// -p
template <class F, class S>
vec<F, S> operator-(const vec<F, S>& a) {
  return vec<F, S>(-a.eigen());
}
// k p for a number k
template <class F, class S, ScalarFactor<S> T>
vec<F, S> operator*(T k, const vec<F, S>& a) {
  return vec<F, S>(S(k) * a.eigen());
}
// p k = k p
template <class F, class S, ScalarFactor<S> T>
vec<F, S> operator*(const vec<F, S>& a, T k) {
  return vec<F, S>(a.eigen() * S(k));
}
// p / k = (1/k) p
template <class F, class S, ScalarFactor<S> T>
vec<F, S> operator/(const vec<F, S>& a, T k) {
  return vec<F, S>(a.eigen() / S(k));
}
// Exact equality of components; NaN compares unequal.
template <class F, class S>
bool operator==(const vec<F, S>& a, const vec<F, S>& b) {
  return a.eigen() == b.eigen();
}
// p . q and p x q, both expressed in F.
template <class F, class S>
S dot(const vec<F, S>& a, const vec<F, S>& b) {
  return a.eigen().dot(b.eigen());
}
// p x q in F
template <class F, class S>
vec<F, S> cross(const vec<F, S>& a, const vec<F, S>& b) {
  return vec<F, S>(a.eigen().cross(b.eigen()));
}
// |p|
template <class F, class S>
S norm(const vec<F, S>& a) {
  return a.eigen().norm();
}
// |a_i - b_i| <= tol for every component; false if any is NaN.
template <class F, class S>
bool is_approx(const vec<F, S>& a, const vec<F, S>& b, S tol) {
  return ((a.eigen() - b.eigen()).cwiseAbs().array() <= tol).all();
}

// Mixing frames: the first error names the rule, the fix and both frames.
template <class LeftFrame, class RightFrame>
inline constexpr bool same_frame_v =
    detail::check<std::is_same_v<LeftFrame, RightFrame>,
                  error::frames_differ_express_one_in_the_others_frame_first<LeftFrame, RightFrame>,
                  fix::call_kane_express<LeftFrame>>;
// p + q with p, q in different frames: an error
template <class LeftFrame, class RightFrame, class S>
requires DifferentFrames<LeftFrame, RightFrame> vec<LeftFrame, S>
operator+(const vec<LeftFrame, S>&, const vec<RightFrame, S>&) {
  static_assert(same_frame_v<LeftFrame, RightFrame>);
  return {};
}
// p - q in different frames: an error
template <class LeftFrame, class RightFrame, class S>
requires DifferentFrames<LeftFrame, RightFrame> vec<LeftFrame, S>
operator-(const vec<LeftFrame, S>&, const vec<RightFrame, S>&) {
  static_assert(same_frame_v<LeftFrame, RightFrame>);
  return {};
}
// p == q in different frames: an error
template <class LeftFrame, class RightFrame, class S>
requires DifferentFrames<LeftFrame, RightFrame>
bool operator==(const vec<LeftFrame, S>&, const vec<RightFrame, S>&) {
  static_assert(same_frame_v<LeftFrame, RightFrame>);
  return {};
}
// p . q in different frames: an error
template <class LeftFrame, class RightFrame, class S>
requires DifferentFrames<LeftFrame, RightFrame> S dot(const vec<LeftFrame, S>&, const vec<RightFrame, S>&) {
  static_assert(same_frame_v<LeftFrame, RightFrame>);
  return {};
}
// p x q in different frames: an error
template <class LeftFrame, class RightFrame, class S>
requires DifferentFrames<LeftFrame, RightFrame> vec<LeftFrame, S> cross(const vec<LeftFrame, S>&,
                                                                        const vec<RightFrame, S>&) {
  static_assert(same_frame_v<LeftFrame, RightFrame>);
  return {};
}
// is_approx of vectors in different frames: an error
template <class LeftFrame, class RightFrame, class S>
requires DifferentFrames<LeftFrame, RightFrame>
bool is_approx(const vec<LeftFrame, S>&, const vec<RightFrame, S>&, S) {
  static_assert(same_frame_v<LeftFrame, RightFrame>);
  return {};
}

}  // namespace kane
#pragma GCC diagnostic pop
