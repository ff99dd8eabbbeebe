// ^A P^B: direction cosines from A to B.
//
//   ^B p = ^A P^B . ^A p,   (^A P^B)_ij = e_Bi . e_Aj.
//
// Row i holds e_Bi expressed in A. In SymPy, ^A P^B is B.dcm(A) (and
// A.dcm(B) is ^B P^A, its transpose).
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/LU>

#include "kane/detail/frame_check.hpp"
#include "kane/frames/frame.hpp"
#include "kane/frames/vec.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// ^A P^B, direction cosines from A to B: ^B p = ^A P^B . ^A p.
template <class A, class B, class S = double>
class dcm {
  static_assert(Frame<A> && Frame<B>, "kane: dcm<A, B> needs two frames");
  static_assert(Scalar<S>, "kane: dcm<A, B, S> needs a scalar type S");

 public:
  // A: the frame the components come from
  using from_frame = A;
  // B: the frame the components go to
  using to_frame = B;
  // the scalar type S
  using scalar = S;
  // the 3x3 matrix of S
  using eigen_type = Eigen::Matrix<S, 3, 3>;

  // The identity (A and B aligned).
  dcm() = default;
  // From a matrix taken as is: no check; see is_rotation().
  template <class Derived>
  explicit dcm(const Eigen::MatrixBase<Derived>& m) {
    Eigen::Map<eigen_type>{m_} = m;
  }

  // (^A P^B)_ij = e_Bi . e_Aj, i and j from 0
  S operator()(int i, int j) const { return m_[i + 3 * j]; }
  // The matrix as an Eigen view (no copy).
  // On a temporary it is a copy, so that no view outlives its matrix.
  Eigen::Map<const eigen_type> eigen() const& { return Eigen::Map<const eigen_type>(m_); }
  // the matrix, copied: no view of a temporary
  eigen_type eigen() && { return Eigen::Map<const eigen_type>(m_); }
  // the matrix of a const temporary, copied
  eigen_type eigen() const&& { return Eigen::Map<const eigen_type>(m_); }  // a copy: no view of a temporary

  // ^B P^A = (^A P^B)^T.
  dcm<B, A, S> transpose() const { return dcm<B, A, S>(eigen().transpose()); }

  // |P P^T - I| <= tol entrywise and |det P - 1| <= tol; false on NaN.
  bool is_rotation(S tol) const {
    const auto m = eigen();
    const bool orthonormal = ((m * m.transpose() - eigen_type::Identity()).cwiseAbs().array() <= tol).all();
    using std::abs;
    return orthonormal && abs(m.determinant() - S(1)) <= tol;
  }

 private:
  S m_[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  // column-major, trivially copyable
};

// ^B p = ^A P^B . ^A p
template <class A, class B, class S>
vec<B, S> operator*(const dcm<A, B, S>& p, const vec<A, S>& v) {
  return vec<B, S>(p.eigen() * v.eigen());
}
// ^A P^C = ^B P^C . ^A P^B
template <class A, class B, class C, class S>
dcm<A, C, S> operator*(const dcm<B, C, S>& l, const dcm<A, B, S>& r) {
  return dcm<A, C, S>(l.eigen() * r.eigen());
}

// Frames that do not match: the first error names the rule and the frames.
template <class DcmFrom, class To, class VecFrame, class S>
requires DifferentFrames<DcmFrom, VecFrame> vec<To, S>
operator*(const dcm<DcmFrom, To, S>&, const vec<VecFrame, S>&) {
  static_assert(detail::refused<error::dcm_applies_only_to_components_in_its_from_frame<DcmFrom, VecFrame>>);
  return {};
}
// ^B P^C . ^A P^B with frames that do not chain: an error naming them
template <class LeftFrom, class LeftTo, class RightFrom, class RightTo, class S>
requires DifferentFrames<LeftFrom, RightTo> dcm<RightFrom, LeftTo, S>
operator*(const dcm<LeftFrom, LeftTo, S>&, const dcm<RightFrom, RightTo, S>&) {
  static_assert(
      detail::refused<error::dcm_product_needs_left_from_frame_equal_right_to_frame<LeftFrom, RightTo>>);
  return {};
}

}  // namespace kane
#pragma GCC diagnostic pop
