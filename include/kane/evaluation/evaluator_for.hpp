// The values of a list of expressions at a state: one outward pass over the frames they read
// (expression_reads.hpp) at each update, and nothing kept but their values in the root's components.
//
//   constexpr auto v = kane::velocity<N, P>(), a = kane::acceleration<N, P>();
//   kane::evaluator_for<State, kane::reads<v, a>> ev;             // holds ^N v and ^N a
//   ev.update(s);
//   kane::vec<N> vn = kane::express<N>(v, ev);
//   kane::evaluator_for<State, kane::reads<kane::partials_of(v)>, Speeds> ev2;
//   auto V = kane::partial_velocities<N>(v, ev2);                 // [v_1 ... v_n] in N
//
// update computes only what the reads need, whether the evaluator is a local or kept across calls:
// the pass runs on a local evaluator, and only the values are stored. Other frames, other expressions,
// constraints and dynamics take a kane::evaluator of the frames (evaluator.hpp).
#pragma once

#include <cstddef>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kane/detail/frame_check.hpp"
#include "kane/detail/inline.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/evaluator.hpp"
#include "kane/evaluation/expression_reads.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/evaluation/tables.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
// The value of one read in the root R's components, into v: a vec, a number, or a table of partials
// (by column, as a copy into rows of a taller matrix reads it).
template <class R, class X, class Ev, class V>
KANE_ALWAYS_INLINE void read_into(const X& x, const Ev& ev, V& v) {
  if constexpr (is_v<X, partials_of_t>)
    table_into<R, true>(x.x, ev, v);
  else if constexpr (VectorExpr<X>) {
    const auto r = eval_vector(x, ev);
    v = V(r.x, r.y, r.z);
  } else
    v = eval_scalar(x, ev);
}
// The type of that value
template <class R, class X, class Ev>
struct read_type {
  using type = std::conditional_t<VectorExpr<X>, vec<R, typename Ev::scalar>, typename Ev::scalar>;
};
template <class R, class Y, class Ev>
struct read_type<R, partials_of_t<Y>, Ev> {
  using type = Eigen::Matrix<typename Ev::scalar, VectorExpr<Y> ? 3 : 1, int(speeds_of<Ev>::n)>;
};
// Every number of x NaN (before the first update, and for a read of another value).
template <class T>
KANE_ALWAYS_INLINE void make_nan(T& x) {
  if constexpr (requires { x.eigen(); })
    x.eigen().setConstant(std::numeric_limits<typename T::scalar>::quiet_NaN());
  else if constexpr (requires { x.rows(); })
    x.setConstant(std::numeric_limits<typename T::Scalar>::quiet_NaN());
  else
    x = std::numeric_limits<T>::quiet_NaN();
}
// V holds no numbers: its type says all (partials_of of an empty type, or an empty type).
template <class V>
constexpr bool numberless_read() {
  if constexpr (is_v<V, partials_of_t>)
    return std::is_empty_v<decltype(V::x)>;
  else
    return std::is_empty_v<V>;
}
template <class V>
inline constexpr bool numberless = numberless_read<V>();
// x and y of one type hold the same numbers (an empty type holds none).
template <class V>
KANE_ALWAYS_INLINE bool same_read(const V& x, const V& y) {
  if constexpr (is_v<V, partials_of_t>)
    return same_read(x.x, y.x);
  else if constexpr (std::is_empty_v<V>)
    return true;
  else
    return __builtin_memcmp(&x, &y, sizeof(V)) == 0;
}
// The place of V among Xs... (sizeof...(Xs) if it is not there).
template <class V, class... Xs>
inline constexpr std::size_t place_of = [] {
  constexpr bool same[] = {std::is_same_v<V, Xs>..., false};
  std::size_t k = 0;
  while (!same[k] && k < sizeof...(Xs)) ++k;
  return k;
}();
template <class... Xs>
inline constexpr bool distinct_types = [] {
  constexpr std::size_t places[] = {place_of<Xs, Xs...>..., 0};
  for (std::size_t k = 0; k < sizeof...(Xs); ++k)
    if (places[k] != k) return false;
  return true;
}();
}  // namespace detail

template <State St, class Reads, class Speeds = void>
class evaluator_for;

// The values of X... at the state of the last update, in the components of the tree's root.
template <State St, auto... X, class Speeds>
class evaluator_for<St, reads<X...>, Speeds> {
  static_assert(detail::distinct_types<std::remove_cvref_t<decltype(X)>...>,
                "kane: two reads of evaluator_for have one type; read each quantity once");

 public:
  // the evaluator whose pass update runs: the frames and the level that X... read
  using evaluator_type = evaluator<St, typename reads<X...>::frames, reads<X...>::needed, Speeds>;
  using state_type = St;
  using scalar = typename St::scalar;
  // the root of the tree: the values are in its components
  using root = detail::root_of<typename evaluator_type::root>;

  KANE_ALWAYS_INLINE evaluator_for() {  // NaN until the first update
    std::apply([](auto&... v) { (detail::make_nan(v), ...); }, values_);
  }

  // The values of X... at s (s is copied by the pass; a later change of s is not seen).
  // status() is the evaluator's (evaluator.hpp): ok only if the numbers of s the pass reads are finite.
  KANE_INLINE_FLATTEN void update(const St& s) requires(detail::inlined_entry<evaluator_type>) {
    update_at(s);
  }
  // update(s) for more than 8 frames: one flattened function
  KANE_FLATTEN void update(const St& s) requires(!detail::inlined_entry<evaluator_type>) { update_at(s); }

  // ok, or why the values of the last update are NaN
  status_of<scalar> status() const { return status_; }
  // there was an update: the values are of a state, not NaN
  bool updated() const { return updated_; }

  // the number of reads
  static constexpr std::size_t count = sizeof...(X);
  // The read V: place_of its type among X..., or sizeof...(X).
  template <class V>
  static constexpr std::size_t place = detail::place_of<V, std::remove_cvref_t<decltype(X)>...>;
  // The value held for the read x (express, evaluate and partial_velocities call it). A read of the
  // type of a held one but another value (other numbers in its type's members) is NaN.
  template <class V>
  decltype(auto) held(const V& x) const requires(place<V> < sizeof...(X)) {
    if constexpr (detail::numberless<V>)
      return (std::get<place<V>>(values_));
    else {
      auto value = std::get<place<V>>(values_);
      if (!detail::same_read(x, std::get<place<V>>(reads_))) detail::make_nan(value);
      return value;
    }
  }

 private:
  static constexpr std::tuple<std::remove_cvref_t<decltype(X)>...> reads_{X...};
  KANE_ALWAYS_INLINE void update_at(const St& s) {
    evaluator_type ev;  // a local: the optimiser drops what no read needs
    ev.update(s);
    status_ = ev.status();
    updated_ = true;
    [&]<std::size_t... K>(std::index_sequence<K...>) KANE_ALWAYS_INLINE_LAMBDA {
      (detail::read_into<root>(X, ev, std::get<K>(values_)), ...);
    }
    (std::make_index_sequence<sizeof...(X)>{});
  }

  std::tuple<typename detail::read_type<root, std::remove_cvref_t<decltype(X)>, evaluator_type>::type...>
      values_;
  status_of<scalar> status_{};
  bool updated_ = false;
};

namespace detail {
template <class T>
struct is_evaluator_for : std::false_type {};
template <class St, class Rd, class Sp>
struct is_evaluator_for<evaluator_for<St, Rd, Sp>> : std::true_type {};
// The rules of a read from an evaluator_for: V held, in the root's components.
template <class A, class V, class E>
inline constexpr bool held_read =
    check<(E::template place<V> < E::count), error::evaluator_for_holds_the_values_of_its_reads_only<V>,
          fix::add_it_to_kane_reads_or_use_kane_evaluator>&&
        check<std::is_same_v<A, typename E::root>,
              error::evaluator_for_holds_its_reads_in_the_root_frame<A, typename E::root>,
              fix::express_it_in_the_root_or_use_kane_evaluator<typename E::root>>;
}  // namespace detail

// ^R v for a read v of ev (R: the root).
template <Frame A, VectorExpr V, class E>
requires(detail::is_evaluator_for<E>::value) vec<A, typename E::scalar> express(const V& v, const E& ev) {
  if constexpr (detail::held_read<A, V, E>)
    return ev.held(v);
  else
    return {};
}
// The value of a scalar read x of ev.
template <ScalarExpr X, class E>
requires(detail::is_evaluator_for<E>::value) typename E::scalar evaluate(const X& x, const E& ev) {
  if constexpr (detail::held_read<typename E::root, X, E>)
    return ev.held(x);
  else
    return {};
}
// [v_1 ... v_n] in R for a read kane::partials_of(x) of ev.
template <Frame A, class X, class E>
requires(detail::is_evaluator_for<E>::value && (ScalarExpr<X> || VectorExpr<X>)) decltype(auto)
    partial_velocities(const X& x, const E& ev) {
  if constexpr (detail::held_read<A, partials_of_t<X>, E>)
    return ev.held(partials_of_t<X>{x});
  else
    return Eigen::Matrix < typename E::scalar, VectorExpr<X> ? 3 : 1, 1 > ();
}

}  // namespace kane
#pragma GCC diagnostic pop
