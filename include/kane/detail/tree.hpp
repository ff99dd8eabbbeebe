// The path between two frames of a tree, found at compile time.
//
// Plain C++20 (type lists and partial specialisation), not Boost.Hana: a path
// is a few list operations, and without Hana's layers the diagnostics show
// the frames and the compile stays cheap.
#pragma once

#include <type_traits>

namespace kane::detail {

template <class... T>
struct list {};

template <class T, class L>
struct push_front;
template <class T, class... Ts>
struct push_front<T, list<Ts...>> {
  using type = list<T, Ts...>;
};

// list<F, parent of F, ..., root>
template <class F, class P = typename F::parent>
struct ancestors {
  using type = typename push_front<F, typename ancestors<P>::type>::type;
};
template <class F>
struct ancestors<F, void> {
  using type = list<F>;
};

template <class T, class L>
struct contains;
template <class T, class... Ts>
struct contains<T, list<Ts...>> : std::bool_constant<(std::is_same_v<T, Ts> || ...)> {};

// The first element of L that is also in M (void if none).
template <class L, class M>
struct first_common {
  using type = void;
};
template <class H, class... T, class M>
struct first_common<list<H, T...>, M> {
  using type = std::conditional_t<contains<H, M>::value, H, typename first_common<list<T...>, M>::type>;
};

// The elements of L before Stop.
template <class L, class Stop>
struct before;
template <class Stop>
struct before<list<>, Stop> {
  using type = list<>;
};
template <class H, class... T, class Stop>
struct before<list<H, T...>, Stop> {
  using type = std::conditional_t<std::is_same_v<H, Stop>, list<>,
                                  typename push_front<H, typename before<list<T...>, Stop>::type>::type>;
};

template <class L, class R = list<>>
struct reverse {
  using type = R;
};
template <class H, class... T, class... R>
struct reverse<list<H, T...>, list<R...>> {
  using type = typename reverse<list<T...>, list<H, R...>>::type;
};

// From A up to the common ancestor (up: A, ..., excluding it), then down to B
// (down: from below the common ancestor to B). Each listed frame stands for
// the edge to its parent.
template <class A, class B>
struct path {
  using common = typename first_common<typename ancestors<A>::type, typename ancestors<B>::type>::type;
  static constexpr bool joined = !std::is_void_v<common>;
  using up = typename before<typename ancestors<A>::type, common>::type;
  using down = typename reverse<typename before<typename ancestors<B>::type, common>::type>::type;
};

}  // namespace kane::detail
