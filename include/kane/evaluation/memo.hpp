// Common subexpressions of a group of expressions evaluated at one state: a
// compound node without runtime data (its leaves empty types: nodes of one type
// have one value at a state) that occurs more than once in the group is computed
// at its first use and read after. Compilers find these on numbers; on jets, whose
// operations stay calls, nothing else does (the time derivatives of constraints
// repeat whole subtrees: the product and quotient rules).
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "kane/detail/inline.hpp"
#include "kane/detail/lane_traits.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/v3.hpp"
#include "kane/evaluation/evaluate.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <class X>
struct node_key {
  static constexpr char id = 0;
};
// Whether addresses of two variables compare in a constant expression. g++ 12: with
// -fsanitize=null it does not fold them; then no node is recalled.
template <class A>
inline constexpr bool keys_compare_for = requires {
  typename std::integral_constant<bool, (&node_key<A>::id != &node_key<A*>::id)>;
};
inline constexpr bool keys_compare = keys_compare_for<int>;

// The children of a node kind that computes (a quantity is its vector v), as a list.
template <class X>
constexpr auto children_of() {
  using C = const X&;
  if constexpr (is_v<X, add> || is_v<X, sub> || is_v<X, mul> || is_v<X, quot> || is_v<X, vdot> ||
                is_v<X, vsum> || is_v<X, vdiff> || is_v<X, vcross>)
    return list<std::remove_cvref_t<decltype(std::declval<C>().l)>,
                std::remove_cvref_t<decltype(std::declval<C>().r)>>{};
  else if constexpr (is_v<X, neg> || is_v<X, unary> || power_info<X>::value || is_v<X, call>)
    return list<std::remove_cvref_t<decltype(std::declval<C>().x)>>{};
  else if constexpr (is_v<X, scaled>)
    return list<std::remove_cvref_t<decltype(std::declval<C>().s)>,
                std::remove_cvref_t<decltype(std::declval<C>().v)>>{};
  else if constexpr (is_v<X, vneg> || Quantity<X>)
    return list<std::remove_cvref_t<decltype(std::declval<C>().v)>>{};
  else
    return list<>{};
}
template <class X>
using children_t = decltype(children_of<X>());
// No runtime data: an empty leaf, or a node of such children alone (a * a holds two
// members of one empty type, which a compiler need not lay out as an empty type).
template <class X, class Children = children_t<X>>
inline constexpr bool stateless = false;
template <class X, class... C>
inline constexpr bool stateless<X, list<C...>> = is_v<X, call> || sizeof...(C) == 0
                                                     ? std::is_empty_v<X>
                                                     : (true && ... && stateless<C>);
// Recalled: computes (has children), holds no runtime data, is not a quantity (its v is).
template <class X>
inline constexpr bool recallable = !Quantity<X> && !std::is_same_v<children_t<X>, list<>> && stateless<X>;

// An upper bound of the distinct recallable node kinds of X.
template <class X, class Children = children_t<X>>
inline constexpr std::size_t recallable_types = 0;
template <class X, class... C>
inline constexpr std::size_t recallable_types<X, list<C...>> = (recallable<X> ? 1 : 0) +
                                                               (recallable_types<C> + ... + 0);
template <std::size_t N>
struct node_set {
  std::array<const void*, N> key{};
  std::array<bool, N> vector{}, repeated{};
  std::size_t n = 0;
};
// Pre-order; a subtree seen before is not entered again (its nodes are recalled with it).
template <class X, class Set>
constexpr void collect_nodes(Set& set) {
  if constexpr (recallable<X>) {
    for (std::size_t i = 0; i < set.n; ++i)
      if (set.key[i] == &node_key<X>::id) {
        set.repeated[i] = true;
        return;
      }
    set.key[set.n] = &node_key<X>::id, set.vector[set.n] = VectorExpr<X>, ++set.n;
  }
  [&]<class... C>(list<C...>) { (collect_nodes<C>(set), ...); }(children_t<X>{});
}

// The recallable nodes of X... that occur twice or more outside the repeats of
// a larger such node; a scalar slot or a vector slot each.
template <class... X>
struct memo_plan {
  static constexpr std::size_t bound = (recallable_types<std::remove_cvref_t<X>> + ... + 0);
  struct nodes {
    std::array<const void*, bound> key{};
    std::array<std::size_t, bound> slot{};
    std::size_t n = 0, scalars = 0, vectors = 0;
  };
  static constexpr nodes repeated = [] {
    node_set<bound> all;
    if constexpr (keys_compare) (collect_nodes<std::remove_cvref_t<X>>(all), ...);
    nodes out;
    for (std::size_t i = 0; i < all.n; ++i)
      if (all.repeated[i])
        out.slot[out.n] = all.vector[i] ? out.vectors++ : out.scalars++, out.key[out.n++] = all.key[i];
    return out;
  }();
  template <class Y>
  static constexpr std::size_t index() {  // repeated.n: not recalled
    if constexpr (!keys_compare) return 0;
    for (std::size_t i = 0; i < repeated.n; ++i)
      if (repeated.key[i] == &node_key<Y>::id) return i;
    return repeated.n;
  }
};

// A value not constructed until assigned (a scalar type may fill what it constructs).
template <class T>
union cell {
  T value;
  constexpr cell() {}
};

// Ev with the slots of a plan: evaluation reads a repeated node from its slot
// after its first use (evaluate.hpp asks recalls<X>).
template <class Ev, class Plan>
class recalling {
 public:
  using scalar = typename Ev::scalar;
  using state_type = typename Ev::state_type;
  using speed_set = typename Ev::speed_set;
  using root = typename Ev::root;
  template <class X>
  static constexpr bool recalls = Plan::template index<X>() < Plan::repeated.n;

  explicit recalling(const Ev& ev) : ev_(ev) {}
  // The evaluator without the slots, for evaluation in an order the plan does not know.
  const Ev& base() const { return ev_; }

  template <class X>
  scalar recall_scalar(const X& x) const {
    constexpr std::size_t i = Plan::template index<X>(), s = Plan::repeated.slot[i];
    if (!done_[i]) scalars_[s].value = eval_scalar<memo_use::fresh>(x, *this), done_[i] = true;
    return scalars_[s].value;
  }
  template <class X>
  v3<scalar> recall_vector(const X& x) const {
    constexpr std::size_t i = Plan::template index<X>(), s = Plan::repeated.slot[i];
    if (!done_[i]) vectors_[s].value = eval_vector<memo_use::fresh>(x, *this), done_[i] = true;
    return vectors_[s].value;
  }

  // What evaluation reads of an evaluator.
  const state_type& state() const { return ev_.state(); }
  template <std::size_t I, std::size_t D>
  scalar coordinate_value() const {
    return ev_.template coordinate_value<I, D>();
  }
  template <std::size_t I>
  scalar sin_q() const {
    return ev_.template sin_q<I>();
  }
  template <std::size_t I>
  scalar cos_q() const {
    return ev_.template cos_q<I>();
  }
  template <std::size_t R, std::size_t C>
  scalar stored_weight() const {
    return ev_.template stored_weight<R, C>();
  }
  template <std::size_t R>
  scalar stored_offset() const {
    return ev_.template stored_offset<R>();
  }
  template <class F>
  auto axes() const {
    return ev_.template axes<F>();
  }
  template <class F, class Rates>
  v3<scalar> omega_value(const Rates&) const {
    return ev_.template omega_value<F>(ev_);
  }
  template <class F, class Rates>
  v3<scalar> alpha_value(const Rates&) const {
    return ev_.template alpha_value<F>(ev_);
  }

 private:
  const Ev& ev_;
  mutable std::array<bool, Plan::repeated.n> done_{};
  mutable std::array<cell<scalar>, Plan::repeated.scalars> scalars_;
  mutable std::array<cell<v3<scalar>>, Plan::repeated.vectors> vectors_;
};

template <class T>
inline constexpr bool is_recalling = false;
template <class Ev, class Plan>
inline constexpr bool is_recalling<recalling<Ev, Plan>> = true;

// f(ev), or f of ev recalling the repeated nodes of X... where the scalar is neither a number
// nor lanes of numbers (there the compiler finds common subexpressions itself).
template <class... X, class Ev, class F>
inline decltype(auto) with_common_subexpressions(const Ev& ev, F&& f) {
  if constexpr (std::is_arithmetic_v<typename Ev::scalar> || lane_traits<typename Ev::scalar>::width > 1)
    return f(ev);
  else if constexpr (memo_plan<X...>::repeated.n == 0)
    return f(ev);
  else
    return f(recalling<Ev, memo_plan<X...>>(ev));
}
template <class... X, class Ev, class F>
inline decltype(auto) with_common_subexpressions(list<X...>, const Ev& ev, F&& f) {
  return with_common_subexpressions<X...>(ev, f);
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
