// ^A w^B and ^A alpha^B between any two frames of a tree.
//
// Both are atomic: the evaluator's outward pass gives each frame F its
// ^R w^F and ^R alpha^F relative to the root R, and
//   ^A w^B = ^R w^B - ^R w^A                         (addition theorem, eq. 10)
//   ^A alpha^B = ^R alpha^B - ^R alpha^A - ^R w^A x ^A w^B   (eq. 13)
// Sums follow the addition theorem at compile time: ^A w^B + ^B w^C is ^A w^C;
// angular velocities that do not chain do not add.
#pragma once

#include <type_traits>

#include "kane/detail/frame_check.hpp"
#include "kane/detail/tree.hpp"
#include "kane/expressions/vector.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// ^A w^B as a vector expression that remembers its observer and body.
template <class A, class B>
struct angular_velocity_of : detail::vector_tag {
  // A, the frame it is measured in
  using observer = A;
  // B, the frame that turns
  using body = B;
};
// ^A alpha^B as a vector expression that remembers its observer and body.
template <class A, class B>
struct angular_acceleration_of : detail::vector_tag {
  // A, the frame it is measured in
  using observer = A;
  // B, the frame that turns
  using body = B;
};

namespace detail {
template <class F>
inline constexpr bool is_root_v = std::is_void_v<typename F::tree_parent>;

// ^R w^F as a vector expression: zero for a root.
template <class F>
constexpr auto omega_of() {
  if constexpr (is_root_v<F>)
    return zero_vector{};
  else
    return omega<F>{};
}
template <class F>
constexpr auto alpha_of() {
  if constexpr (is_root_v<F>)
    return zero_vector{};
  else
    return alpha<F>{};
}
// The expansions above, in terms of the atomic nodes.
template <class A, class B>
constexpr auto expand(angular_velocity_of<A, B>) {
  return omega_of<B>() - omega_of<A>();
}
template <class A, class B>
constexpr auto expand(angular_acceleration_of<A, B>) {
  return alpha_of<B>() - alpha_of<A>() - cross(omega_of<A>(), omega_of<B>() - omega_of<A>());
}
}  // namespace detail

// ^A w^B; the zero vector for A = B.
template <Frame A, Frame B>
constexpr auto angular_velocity() {
  static_assert(detail::joined_frames<A, B>::joined);
  if constexpr (std::is_same_v<A, B>)
    return zero_vector{};
  else
    return angular_velocity_of<A, B>{};
}
// ^A alpha^B; the zero vector for A = B.
template <Frame A, Frame B>
constexpr auto angular_acceleration() {
  static_assert(detail::joined_frames<A, B>::joined);
  if constexpr (std::is_same_v<A, B>)
    return zero_vector{};
  else
    return angular_acceleration_of<A, B>{};
}

// ^B w^A = -^A w^B
template <class A, class B>
constexpr auto operator-(angular_velocity_of<A, B>) {
  return angular_velocity_of<B, A>{};
}

// ^A w^B + ^B w^C = ^A w^C (eq. 10), in either order; other sums do not compile.
template <class A, class B, class C, class D>
constexpr auto operator+(angular_velocity_of<A, B>, angular_velocity_of<C, D>) {
  if constexpr (std::is_same_v<B, C>)
    return angular_velocity<A, D>();
  else if constexpr (std::is_same_v<D, A>)
    return angular_velocity<C, B>();
  else {
    static_assert(
        detail::check<
            false, error::angular_velocities_do_not_chain_the_first_body_must_be_the_second_observer<B, C>>);
    return zero_vector{};
  }
}
// ^A w^B - ^C w^B = ^A w^C and ^A w^B - ^A w^D = ^D w^B; other differences do not compile.
template <class A, class B, class C, class D>
constexpr auto operator-(angular_velocity_of<A, B>, angular_velocity_of<C, D>) {
  if constexpr (std::is_same_v<B, D>)
    return angular_velocity<A, C>();
  else if constexpr (std::is_same_v<A, C>)
    return angular_velocity<D, B>();
  else {
    static_assert(detail::check<
                  false,
                  error::angular_velocities_differ_only_with_one_observer_or_one_body_in_common<A, B, C, D>>);
    return zero_vector{};
  }
}

}  // namespace kane
#pragma GCC diagnostic pop
