// Type lists and the few operations kane needs on them (plain C++20), and a loop
// unrolled at compile time.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "kane/detail/inline.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <std::size_t I>
using index_c = std::integral_constant<std::size_t, I>;

// Folds of at most this many terms: clang stops at 256 (-fbracket-depth), so longer loops go in chunks.
inline constexpr std::size_t fold_chunk = 128;
template <std::size_t N, std::size_t C>
inline constexpr std::size_t chunk_size = N - C* fold_chunk < fold_chunk ? N - C* fold_chunk : fold_chunk;
template <std::size_t From, class F, std::size_t... I>
constexpr void static_for_from(F& f, std::index_sequence<I...>) {
  (f(index_c<From + I>{}), ...);
}
template <std::size_t N, class F, std::size_t... C>
constexpr void static_for_chunks(F& f, std::index_sequence<C...>) {
  (static_for_from<C * fold_chunk>(f, std::make_index_sequence<chunk_size<N, C>>{}), ...);
}
template <std::size_t From, class F, std::size_t... I>
KANE_ALWAYS_INLINE constexpr void static_for_inline_from(F& f, std::index_sequence<I...>) {
  (f(index_c<From + I>{}), ...);
}
template <std::size_t N, class F, std::size_t... C>
KANE_ALWAYS_INLINE constexpr void static_for_inline_chunks(F& f, std::index_sequence<C...>) {
  (static_for_inline_from<C * fold_chunk>(f, std::make_index_sequence<chunk_size<N, C>>{}), ...);
}

// f(index_c<0>{}), ..., f(index_c<N - 1>{})
template <std::size_t N, class F>
constexpr void static_for(F&& f) {
  if constexpr (N <= fold_chunk)
    static_for_from<0>(f, std::make_index_sequence<N>{});
  else
    static_for_chunks<N>(f, std::make_index_sequence<(N + fold_chunk - 1) / fold_chunk>{});
}
// The same inside always-inline code (inline.hpp), f an always-inline lambda: the loop is part of
// its caller before any optimization (a plain call there could stay a call).
template <std::size_t N, class F>
KANE_ALWAYS_INLINE constexpr void static_for_inline(F&& f) {
  if constexpr (N <= fold_chunk)
    static_for_inline_from<0>(f, std::make_index_sequence<N>{});
  else
    static_for_inline_chunks<N>(f, std::make_index_sequence<(N + fold_chunk - 1) / fold_chunk>{});
}
// f(index_c<i>{}) for the i where Mask[i] is true, in order: a sparse loop instantiates f only
// where it has work (Mask a constexpr std::array<bool, N>).
template <auto Mask>
inline constexpr std::size_t count_true = [] {
  std::size_t k = 0;
  for (bool b : Mask) k += b ? 1 : 0;
  return k;
}();
template <auto Mask>
inline constexpr auto true_indices = [] {
  std::array<std::size_t, count_true<Mask>> at{};
  std::size_t k = 0;
  for (std::size_t i = 0; i < Mask.size(); ++i)
    if (Mask[i]) at[k++] = i;
  return at;
}();
template <auto Mask, class F>
constexpr void static_for_where(F&& f) {
  static_for<count_true<Mask>>([&](auto k) { f(index_c<true_indices<Mask>[k]> {}); });
}
// N trues (a computation that reads every frame or coordinate)
template <std::size_t N>
constexpr std::array<bool, N> every() {
  std::array<bool, N> a{};
  a.fill(true);
  return a;
}

template <class... T>
struct list {};

template <class T, class L>
struct push_front;
template <class T, class... Ts>
struct push_front<T, list<Ts...>> {
  using type = list<T, Ts...>;
};

template <class L>
struct size;
template <class... Ts>
struct size<list<Ts...>> : std::integral_constant<std::size_t, sizeof...(Ts)> {};

template <class L, std::size_t I>
struct at;
template <class H, class... T>
struct at<list<H, T...>, 0> {
  using type = H;
};
template <class H, class... T, std::size_t I>
struct at<list<H, T...>, I> : at<list<T...>, I - 1> {};

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

template <class... L>
struct concat {
  using type = list<>;
};
template <class... A>
struct concat<list<A...>> {
  using type = list<A...>;
};
template <class... A, class... B, class... Rest>
struct concat<list<A...>, list<B...>, Rest...> {
  using type = typename concat<list<A..., B...>, Rest...>::type;
};

// L without repeats, first occurrences kept in order.
template <class L, class Seen = list<>>
struct unique {
  using type = Seen;
};
template <class H, class... T, class... Seen>
struct unique<list<H, T...>, list<Seen...>> {
  using type = typename unique<list<T...>, std::conditional_t<contains<H, list<Seen...>>::value,
                                                              list<Seen...>, list<Seen..., H>>>::type;
};

template <class T, class L>
struct index_of;
template <class T, class... Ts>
struct index_of<T, list<T, Ts...>> : std::integral_constant<std::size_t, 0> {};
template <class T, class H, class... Ts>
struct index_of<T, list<H, Ts...>>
    : std::integral_constant<std::size_t, 1 + index_of<T, list<Ts...>>::value> {};

// M<T>::type of each T of a list; M<T...> of a list; a list without void.
template <template <class> class M, class L>
struct map_items;
template <template <class> class M, class... T>
struct map_items<M, list<T...>> {
  using type = list<typename M<T>::type...>;
};
template <template <class...> class M, class L>
struct apply_list;
template <template <class...> class M, class... T>
struct apply_list<M, list<T...>> : M<T...> {};
template <class L>
struct not_void;
template <class... T>
struct not_void<list<T...>> {
  using type = typename concat<std::conditional_t<std::is_void_v<T>, list<>, list<T>>...>::type;
};

}  // namespace kane::detail
#pragma GCC diagnostic pop
