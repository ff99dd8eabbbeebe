// Derivatives, built at compile time.
//
//   dt(s)            total time derivative of a scalar (eq. 7)
//   diff(s, x)       partial derivative of a scalar by x = q_i, dt(q_i), u_i, t
//   dt<A>(v)         time derivative of a vector in frame A, by the transport
//                    theorem: the A-derivative of e_Fi is ^A w^F x e_Fi (eq. 12)
//   diff<A>(v, q_i)  partial derivative of a vector in A by q_i (eq. 6): the
//                    A-derivative of e_Fi by q_i is w_i x e_Fi with w_i the
//                    coefficient of q_i' in ^A w^F
// A vector has no derivative without a frame: dt(v) does not compile.
#pragma once

#include <cstddef>
#include <type_traits>

#include "kane/detail/frame_check.hpp"
#include "kane/detail/tree.hpp"
#include "kane/expressions/derived_products.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/kinematics/angular_velocity.hpp"
#include "kane/kinematics/derivative_traits.hpp"
#include "kane/scalars/coordinate.hpp"
#include "kane/scalars/expr.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {

template <class X>
constexpr auto outer_derivative(X x);
template <class A, class V>
constexpr auto ddt_in(V v);
template <class A, class Leaf, class V>
constexpr auto partial_in(V v);

// Total time derivative of a scalar (eq. 7).
template <class X>
constexpr auto ddt(X x) {
  if constexpr (coordinate_info<X>::value)
    return coordinate<X::index, X::order + 1>{};
  else if constexpr (speed_info<X>::value)
    return speed<X::index, X::order + 1>{};
  else if constexpr (std::is_same_v<X, time_variable>)
    return one_t{};
  else if constexpr (LeafConstant<X>)
    return zero_t{};
  else if constexpr (is_v<X, add>)
    return ddt(x.l) + ddt(x.r);
  else if constexpr (is_v<X, sub>)
    return ddt(x.l) - ddt(x.r);
  else if constexpr (is_v<X, neg>)
    return -ddt(x.x);
  else if constexpr (is_v<X, mul>)
    return ddt(x.l) * x.r + x.l * ddt(x.r);
  else if constexpr (is_v<X, quot>)
    return (ddt(x.l) * x.r - x.l * ddt(x.r)) / pow<2>(x.r);
  else if constexpr (is_v<X, unary> || power_info<X>::value || is_v<X, call>)
    return outer_derivative(x) * ddt(x.x);
  else if constexpr (is_v<X, vdot>) {
    using R = root_frame_of_t<vsum<decltype(x.l), decltype(x.r)>>;
    return derived_dot(ddt_in<R>(x.l), x.r) + derived_dot(x.l, ddt_in<R>(x.r));
  } else if constexpr (PoseNumber<X>)
    return X::time_derivative();
  else
    static_assert(!sizeof(X), "kane: dt of an unknown scalar node");
}

// X is the leaf Leaf: the same type, or an input r_i of the same i (kane::named_input is r_i).
template <class X, class Leaf>
constexpr bool same_leaf() {
  if constexpr (Input<X> && Input<Leaf>)
    return X::index == Leaf::index;
  else
    return std::is_same_v<X, Leaf>;
}

// d of a leaf q_i^(d) (Info = coordinate_info) or u_i^(d) (speed_info); -1 for any other node.
template <template <class> class Info, class Leaf>
constexpr int leaf_order() {
  if constexpr (Info<Leaf>::value)
    return int(Leaf::order);
  else
    return -1;
}

// Partial derivative of a scalar by a leaf (q_i, q_i', u_i, t, r_i, ...).
template <class Leaf, class X>
constexpr auto partial(X x) {
  if constexpr (!overlaps(leaves_of<X>, leaf_query<Leaf>()))
    return zero_t{};
  else if constexpr (same_leaf<X, Leaf>())
    return one_t{};
  else if constexpr (coordinate_info<X>::value || speed_info<X>::value || std::is_same_v<X, time_variable> ||
                     LeafConstant<X>)
    return zero_t{};
  else if constexpr (is_v<X, add>)
    return partial<Leaf>(x.l) + partial<Leaf>(x.r);
  else if constexpr (is_v<X, sub>)
    return partial<Leaf>(x.l) - partial<Leaf>(x.r);
  else if constexpr (is_v<X, neg>)
    return -partial<Leaf>(x.x);
  else if constexpr (is_v<X, mul>)
    return partial<Leaf>(x.l) * x.r + x.l * partial<Leaf>(x.r);
  else if constexpr (is_v<X, quot>)
    return (partial<Leaf>(x.l) * x.r - x.l * partial<Leaf>(x.r)) / pow<2>(x.r);
  else if constexpr (is_v<X, unary> || power_info<X>::value || is_v<X, call>)
    return outer_derivative(x) * partial<Leaf>(x.x);
  else if constexpr (is_v<X, vdot>) {
    using R = root_frame_of_t<vsum<decltype(x.l), decltype(x.r)>>;
    return derived_dot(partial_in<R, Leaf>(x.l), x.r) + derived_dot(x.l, partial_in<R, Leaf>(x.r));
  } else
    static_assert(!sizeof(X), "kane: diff of an unknown scalar node");
}

// f'(x) of an elementary or opaque function node f(x).
template <class X>
constexpr auto outer_derivative(X x) {
  if constexpr (is_v<X, unary>)
    return unary_info<X>::fn::derivative(x.x);
  else if constexpr (power_info<X>::value)
    return constant<power_info<X>::n>{} * pow<power_info<X>::n - 1>(x.x);
  else
    return call<derivative_of<decltype(x.f)>, decltype(x.x)>(derivative_of<decltype(x.f)>{x.f}, x.x);
}

// ^A d v/dt by the transport theorem.
template <class A, class V>
constexpr auto ddt_in(V v) {
  if constexpr (is_zero_vector_v<V>)
    return v;
  else if constexpr (is_unit<V>::value)
    return derived_cross(angular_velocity<A, typename V::frame>(), v);
  else if constexpr (is_v<V, scaled>)
    return ddt(v.s) * v.v + v.s * ddt_in<A>(v.v);
  else if constexpr (is_v<V, vsum>)
    return ddt_in<A>(v.l) + ddt_in<A>(v.r);
  else if constexpr (is_v<V, vdiff>)
    return ddt_in<A>(v.l) - ddt_in<A>(v.r);
  else if constexpr (is_v<V, vneg>)
    return -ddt_in<A>(v.v);
  else if constexpr (is_v<V, vcross>)
    return derived_cross(ddt_in<A>(v.l), v.r) + derived_cross(v.l, ddt_in<A>(v.r));
  else if constexpr (is_v<V, omega>) {
    // ^A d(^R w^F)/dt = ^R alpha^F - ^R w^A x ^R w^F
    static_assert(joined_frames<A, typename V::frame>::joined);
    return alpha<typename V::frame>{} - derived_cross(omega_of<A>(), v);
  } else if constexpr (is_v<V, angular_velocity_of> || is_v<V, angular_acceleration_of>)
    return ddt_in<A>(expand(v));
  else if constexpr (is_v<V, alpha>)
    static_assert(
        !sizeof(V),
        "kane: the time derivative of an angular acceleration (a third derivative) is not available");
  else if constexpr (Quantity<V>)
    return ddt_in<A>(v.v);
  else
    static_assert(!sizeof(V), "kane: dt of an unknown vector node");
}

// ^A d v/d x for a leaf x (eq. 6 for x = q_i).
template <class A, class Leaf, class V>
constexpr auto partial_in(V v) {
  if constexpr (!overlaps(leaves_of<V>, leaf_query<Leaf>()))
    return zero_vector{};
  else if constexpr (is_zero_vector_v<V>)
    return v;
  else if constexpr (is_unit<V>::value) {
    if constexpr (leaf_order<coordinate_info, Leaf>() == 0) {
      using F = typename V::frame;
      using p = joined_frames<A, F>;
      return derived_cross(partial_omega<Leaf::index>(typename p::up{}, typename p::down{}), v);
    } else
      return zero_vector{};
  } else if constexpr (is_v<V, scaled>)
    return partial<Leaf>(v.s) * v.v + v.s * partial_in<A, Leaf>(v.v);
  else if constexpr (is_v<V, vsum>)
    return partial_in<A, Leaf>(v.l) + partial_in<A, Leaf>(v.r);
  else if constexpr (is_v<V, vdiff>)
    return partial_in<A, Leaf>(v.l) - partial_in<A, Leaf>(v.r);
  else if constexpr (is_v<V, vneg>)
    return -partial_in<A, Leaf>(v.v);
  else if constexpr (is_v<V, vcross>)
    return derived_cross(partial_in<A, Leaf>(v.l), v.r) + derived_cross(v.l, partial_in<A, Leaf>(v.r));
  else if constexpr (is_v<V, omega> && leaf_order<coordinate_info, Leaf>() == 1) {
    // d(^R w^F)/dq_s': the axes of the edges from the root to F turned by q_s
    using p = path<root_of<typename V::frame>, typename V::frame>;
    return partial_omega<Leaf::index>(typename p::up{}, typename p::down{});
  } else if constexpr (is_v<V, omega> && leaf_order<speed_info, Leaf>() == 0) {
    // d(^R w^F)/du_r: the axes of the edges from the root to F spinning by u_r
    using p = path<root_of<typename V::frame>, typename V::frame>;
    return partial_omega<Leaf::index, wrt::speeds>(typename p::up{}, typename p::down{});
  } else if constexpr (is_v<V, omega> && leaf_order<coordinate_info, Leaf>() != 0)
    return zero_vector{};  // no t, q'' or u' in ^R w^F
  else if constexpr (is_v<V, angular_velocity_of> && leaf_order<coordinate_info, Leaf>() != 0)
    return partial_in<A, Leaf>(expand(v));
  else if constexpr (is_v<V, alpha> || is_v<V, angular_acceleration_of>)
    static_assert(
        !sizeof(V),
        "kane: an angular acceleration is not linear in the speeds and has no partial derivatives here; "
        "take partial velocities of velocities and angular velocities");
  else if constexpr (is_v<V, omega> || is_v<V, angular_velocity_of>)
    static_assert(!sizeof(V),
                  "kane: partial derivatives apply to vectors of unit vectors and scalars (positions); "
                  "an angular velocity or acceleration node has none here");
  else if constexpr (Quantity<V>)
    return partial_in<A, Leaf>(v.v);
  else
    static_assert(!sizeof(V), "kane: diff of an unknown vector node");
}

}  // namespace detail

// Total time derivative of a scalar (eq. 7).
template <ScalarExpr X>
constexpr auto dt(X x) {
  return detail::ddt(x);
}

// ^A d x/dt of a quantity x measured in A: measured in A too (dt<A>(^A v^P) + ^B a^Q does not compile).
template <class A, class V>
struct measured_in : detail::quantity_tag {
  // A, the frame it is measured in
  using observer = A;
  // the expression of ^A dx/dt
  [[no_unique_address]] V v;
  // ^A dx/dt given by x
  constexpr explicit measured_in(V x) : v(x) {}
};

// ^A dv/dt (eq. 7 and 12).
template <Frame A, VectorExpr V>
constexpr auto dt(V v) {
  auto d = detail::ddt_in<A>(v);
  if constexpr (std::is_same_v<detail::observer_of_t<V>, A> && !is_zero_vector_v<decltype(d)>)
    return measured_in<A, decltype(d)>(d);
  else
    return d;
}

// d v/dt without a frame: an error (write dt<N>(v) for a frame N)
template <VectorExpr V>
constexpr V dt(V v) {
  static_assert(detail::refused<error::a_vector_derivative_needs_a_frame_write_dt_A_of_v<V>>);
  return v;
}

// Partial derivative of a scalar by q_i, dt(q_i), u_i or t.
template <ScalarExpr X, ScalarExpr Leaf>
requires(detail::coordinate_info<Leaf>::value || detail::speed_info<Leaf>::value ||
         std::is_same_v<Leaf, time_variable>) constexpr auto diff(X x, Leaf) {
  return detail::partial<Leaf>(x);
}

// ^A dv/dq_i (eq. 6).
template <Frame A, VectorExpr V, ScalarExpr Leaf>
requires(detail::coordinate_info<Leaf>::value || detail::speed_info<Leaf>::value ||
         std::is_same_v<Leaf, time_variable>) constexpr auto diff(V v, Leaf) {
  return detail::partial_in<A, Leaf>(v);
}

// d v/dq without a frame: an error (write diff<N>(v, q) for a frame N)
template <VectorExpr V, ScalarExpr Leaf>
constexpr V diff(V v, Leaf) {
  static_assert(detail::refused<error::a_vector_derivative_needs_a_frame_write_diff_A_of_v_q<V>>);
  return v;
}

}  // namespace kane
#pragma GCC diagnostic pop
