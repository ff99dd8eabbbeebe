// Evaluation of expression nodes from an evaluator's cache (evaluator.hpp):
// eval_scalar and eval_vector say once how each node kind becomes numbers;
// evaluate(x, ev) and express<A>(v, ev) are the entry points.
//
// Vectors are computed in the root's components (detail/v3.hpp); a dot or
// cross with a unit vector of the root picks or permutes components.
#pragma once

#include <cmath>
#include <type_traits>

#include "kane/detail/choices.hpp"
#include "kane/detail/tree.hpp"
#include "kane/detail/v3.hpp"
#include "kane/evaluation/edge_structure.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/frames/vec.hpp"
#include "kane/kinematics/derivative.hpp"
#include "kane/scalars/expr.hpp"
#include "kane/speeds/kinematic_weights.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {

// Specialised by evaluator.hpp.
template <class X>
struct is_evaluator : std::false_type {};
}  // namespace detail

// A kane::evaluator<State, frames<F...>, Level, Speeds>: what every entry point computes from.
template <class T>
concept Evaluator = detail::is_evaluator<T>::value;

namespace detail {

template <memo_use Memo = memo_use::recall, class Ev, class V>
KANE_ALWAYS_INLINE v3<typename Ev::scalar> eval_vector(const V& v, const Ev& ev);

// An evaluator that recalls repeated nodes (memo.hpp) answers for X itself.
template <class Ev, class X>
concept recalled = requires {
  Ev::template recalls<X>;
}
&&Ev::template recalls<X>;

// e_Ri of a root frame R (or a unit vector equal to one): components known at compile time.
template <class V>
struct root_unit : std::false_type {};
template <class F, int I>
struct root_unit<unit<F, I>> : std::bool_constant<std::is_void_v<typename lifted_t<F, I>::tree_parent>> {};

// The zeros of ^R w^F (D = 0) or ^R alpha^F (D = 1) in the root's components: each simple
// rotation above F adds theta' k (and theta'' k + theta' ^R w^P x k), k of pattern axis_pattern.
template <class F, int D>
constexpr pattern3 rate_zeros() {
  using P = typename F::tree_parent;
  if constexpr (std::is_void_v<P>)
    return {entry::zero, entry::zero, entry::zero};
  else if constexpr (spin_edge<F> || matrix_edge<F>)
    return unknown3;
  else {
    pattern3 k = axis_pattern<F>();
    for (entry& e : k)
      if (e != entry::zero) e = entry::other;
    const pattern3 z = common_zeros(rate_zeros<P, D>(), k);
    return D == 0 ? z : common_zeros(z, cross_zeros(rate_zeros<P, 0>(), k));
  }
}
// The components of v known to be zero at compile time (entry::zero; the others entry::other), in
// the root's components (A void) or in A's: a unit vector of that frame has two zeros, one of a
// frame below the root those of its column (column_pattern), and so do angular velocities and
// accelerations (rate_zeros); scaling, negation, sums and cross products keep what follows.
template <class A, class V>
constexpr pattern3 zeros_in() {
  using C = const V&;
  if constexpr (is_zero_vector_v<V>)
    return {entry::zero, entry::zero, entry::zero};
  else if constexpr (is_unit<V>::value) {
    using F = lifted_t<typename V::frame, V::index>;
    constexpr bool own = std::is_void_v<A> ? std::is_void_v<typename F::tree_parent>
                                           : std::is_same_v<typename V::frame, A> || std::is_same_v<F, A>;
    pattern3 z = unknown3;
    if (own) {
      for (std::size_t i = 0; i < 3; ++i)
        if (int(i) != V::index - 1) z[i] = entry::zero;
    } else if (std::is_void_v<A>) {
      constexpr auto c = column_pattern<F>();
      for (std::size_t i = 0; i < 3; ++i)
        if (c[std::size_t(3 * (V::index - 1)) + i] == entry::zero) z[i] = entry::zero;
    }
    return z;
  } else if constexpr (std::is_void_v<A> && (is_v<V, omega> || is_v<V, alpha>))
    return rate_zeros < typename V::frame, is_v<V, alpha> ? 1 : 0 > ();
  else if constexpr (is_v<V, scaled> || is_v<V, vneg> || Quantity<V>)
    return zeros_in<A, std::remove_cvref_t<decltype(std::declval<C>().v)>>();
  else if constexpr (is_v<V, vsum> || is_v<V, vdiff>)
    return common_zeros(zeros_in<A, std::remove_cvref_t<decltype(std::declval<C>().l)>>(),
                        zeros_in<A, std::remove_cvref_t<decltype(std::declval<C>().r)>>());
  else if constexpr (is_v<V, vcross>)
    return cross_zeros(zeros_in<A, std::remove_cvref_t<decltype(std::declval<C>().l)>>(),
                       zeros_in<A, std::remove_cvref_t<decltype(std::declval<C>().r)>>());
  else
    return unknown3;
}
template <class A, class X>
inline constexpr pattern3 zeros_in_v = zeros_in<A, std::remove_cvref_t<X>>();

template <memo_use Memo = memo_use::recall, class Ev, class X>
KANE_ALWAYS_INLINE typename Ev::scalar eval_scalar(const X& x, const Ev& ev) {
  using S = typename Ev::scalar;
  if constexpr (Memo == memo_use::recall && recalled<Ev, X>)
    return ev.recall_scalar(x);
  else if constexpr (coordinate_info<X>::value)
    return ev.template coordinate_value<X::index, X::order>();
  else if constexpr (speed_info<X>::value) {
    static_assert(check<!std::is_void_v<typename Ev::speed_set>,
                        error::evaluator_without_speed_set_reads_no_u_declare_the_speed_set<X>>);
    return ev.state()[x];
  } else if constexpr (Parameter<X>)
    return ev.state()[parameter<X::index>{}];
  else if constexpr (Input<X>)
    return ev.state()[x];
  else if constexpr (std::is_same_v<X, time_variable>)
    return ev.state().t;
  else if constexpr (is_constant<X>::value)
    return S(X::num) / S(X::den);
  else if constexpr (BoundOne<X>) {
    static_assert(check<std::is_same_v<typename X::speed_set, typename Ev::speed_set>,
                        error::partial_velocity_of_another_speed_set_build_it_for_the_evaluators<
                            typename Ev::speed_set, typename X::speed_set>>);
    return S(1);
  } else if constexpr (kde_info<X>::value) {
    static_assert(check<std::is_same_v<typename X::speed_set, typename Ev::speed_set>,
                        error::partial_velocity_of_another_speed_set_build_it_for_the_evaluators<
                            typename Ev::speed_set, typename X::speed_set>>);
    if constexpr (requires { X::column; })
      return ev.template stored_weight<X::row - 1, X::column - 1>();
    else
      return ev.template stored_offset<X::row - 1>();
  } else if constexpr (std::is_same_v<X, literal>)
    return S(x.value);
  else if constexpr (is_fixed<X>::value)
    return S(X::value);
  else if constexpr (is_v<X, add>)
    return eval_scalar(x.l, ev) + eval_scalar(x.r, ev);
  else if constexpr (is_v<X, sub>)
    return eval_scalar(x.l, ev) - eval_scalar(x.r, ev);
  else if constexpr (is_v<X, mul>)
    return eval_scalar(x.l, ev) * eval_scalar(x.r, ev);
  else if constexpr (is_v<X, quot>)
    return eval_scalar(x.l, ev) / eval_scalar(x.r, ev);
  else if constexpr (is_v<X, neg>)
    return -eval_scalar(x.x, ev);
  else if constexpr (is_v<X, unary>) {
    using Fn = typename unary_info<X>::fn;
    using Arg = decltype(x.x);
    if constexpr (!std::is_same_v<Fn, sqrt_fn> && Coordinate<Arg>) {
      if constexpr (std::is_same_v<Fn, sin_fn>)
        return ev.template sin_q<Arg::index>();
      else
        return ev.template cos_q<Arg::index>();
    } else
      return Fn::apply(eval_scalar(x.x, ev));
  } else if constexpr (power_info<X>::value) {
    const S a = eval_scalar(x.x, ev);
    constexpr int n = power_info<X>::n;
    S r = a;
    for (int k = 1; k < (n < 0 ? -n : n); ++k) r *= a;
    return n < 0 ? S(1) / r : r;
  } else if constexpr (is_v<X, call>)
    return x.f(eval_scalar(x.x, ev));
  else if constexpr (is_v<X, vdot>) {
    if constexpr (root_unit<decltype(x.r)>::value) {  // v . e_Ri: a component
      const v3<S> v = eval_vector(x.l, ev);
      return comp<std::size_t(decltype(x.r)::index - 1)>(v);
    } else if constexpr (root_unit<decltype(x.l)>::value) {
      const v3<S> v = eval_vector(x.r, ev);
      return comp<std::size_t(decltype(x.l)::index - 1)>(v);
    } else
      return dot3(eval_vector(x.l, ev), eval_vector(x.r, ev));
  } else
    static_assert(!sizeof(X), "kane: evaluation of an unknown scalar node");
}

// Components in the root frame.
template <memo_use Memo, class Ev, class V>
KANE_ALWAYS_INLINE v3<typename Ev::scalar> eval_vector(const V& v, const Ev& ev) {
  using S = typename Ev::scalar;
  if constexpr (Memo == memo_use::recall && recalled<Ev, V>)
    return ev.recall_vector(v);
  else if constexpr (is_zero_vector_v<V>)
    return {S(0), S(0), S(0)};
  else if constexpr (is_unit<V>::value) {
    using F = lifted_t<typename V::frame, V::index>;  // the highest frame it is a unit vector of
    if constexpr (std::is_void_v<typename F::tree_parent>)
      return {S(V::index == 1), S(V::index == 2), S(V::index == 3)};
    else
      return load3(ev.template axes<F>().data() + 3 * (V::index - 1));
  } else if constexpr (is_v<V, scaled>) {
    const S s = eval_scalar(v.s, ev);
    return scale_known<zeros_in_v<void, decltype(v.v)>>(s, eval_vector(v.v, ev));
  } else if constexpr (is_v<V, vsum>)
    return add_known<zeros_in_v<void, decltype(v.l)>, zeros_in_v<void, decltype(v.r)>>(eval_vector(v.l, ev),
                                                                                       eval_vector(v.r, ev));
  else if constexpr (is_v<V, vdiff>)
    return subtract_known<zeros_in_v<void, decltype(v.l)>, zeros_in_v<void, decltype(v.r)>>(
        eval_vector(v.l, ev), eval_vector(v.r, ev));
  else if constexpr (is_v<V, vneg>)
    return -eval_vector(v.v, ev);
  else if constexpr (is_v<V, vcross>)  // a root's unit vector: two of a x e_Ri's products, no zero formed
    return cross_known<zeros_in_v<void, decltype(v.l)>, zeros_in_v<void, decltype(v.r)>>(
        eval_vector(v.l, ev), eval_vector(v.r, ev));
  else if constexpr (is_v<V, omega>)
    return ev.template omega_value<typename V::frame>(ev);
  else if constexpr (is_v<V, alpha>)
    return ev.template alpha_value<typename V::frame>(ev);
  else if constexpr (is_v<V, angular_velocity_of> || is_v<V, angular_acceleration_of>)
    return eval_vector(expand(v), ev);
  else if constexpr (Quantity<V>)
    return eval_vector(v.v, ev);
  else
    static_assert(!sizeof(V), "kane: evaluation of an unknown vector node");
}

// ^A components of the root components r.
template <class A, class Ev>
KANE_ALWAYS_INLINE v3<typename Ev::scalar> in_frame(const v3<typename Ev::scalar>& r, const Ev& ev) {
  if constexpr (std::is_same_v<A, root_of<A>>)
    return r;
  else {
    const auto* c = ev.template axes<A>().data();
    return {dot3(load3(c), r), dot3(load3(c + 3), r), dot3(load3(c + 6), r)};
  }
}

}  // namespace detail

// The value of a scalar expression.
template <ScalarExpr X, Evaluator Ev>
KANE_INLINE_FLATTEN typename Ev::scalar evaluate(const X& x, const Ev& ev) {
  return detail::eval_scalar(x, ev);
}

namespace detail {
// Entry points inline into their caller for evaluators of up to 8 frames; for
// larger trees each stays one flattened function (one body per entry point
// keeps the register allocation of a long chain in reach: g++ 12).
template <class Ev>
inline constexpr bool inlined_entry = Ev::size <= 8;

template <class A, class V, class Ev>
KANE_ALWAYS_INLINE vec<A, typename Ev::scalar> express_in(const V& v, const Ev& ev) {
  using R = root_of<A>;
  static_assert(one_tree_v<join_trees_t<tree_of_t<V>, R>>);
  static_assert(
      check < std::is_void_v<tree_of_t<V>> || std::is_same_v<tree_of_t<V>, root_of<typename Ev::root>>,
      error::expression_and_evaluator_in_two_trees_build_the_evaluator_on_the_expression_tree < tree_of_t<V>,
      typename Ev::root >>);
  const auto r = in_frame<A>(eval_vector(v, ev), ev);
  return vec<A, typename Ev::scalar>(r.x, r.y, r.z);
}
}  // namespace detail

// ^A v: the components of the vector expression v in A.
template <Frame A, VectorExpr V, class Ev>
requires(Evaluator<Ev>&& detail::inlined_entry<Ev>)
    KANE_INLINE_FLATTEN vec<A, typename Ev::scalar> express(const V& v, const Ev& ev) {
  return detail::express_in<A>(v, ev);
}
// ^A v, for an evaluator of more than 8 frames (one flattened function)
template <Frame A, VectorExpr V, class Ev>
requires(Evaluator<Ev> &&
         !detail::inlined_entry<Ev>) KANE_FLATTEN vec<A, typename Ev::scalar> express(const V& v,
                                                                                      const Ev& ev) {
  return detail::express_in<A>(v, ev);
}

}  // namespace kane
#pragma GCC diagnostic pop
