// The path between two frames of a tree, found at compile time.
//
// Plain C++20 (type lists and partial specialisation), not Boost.Hana: a path
// is a few list operations, and without Hana's layers the diagnostics show
// the frames and the compile stays cheap.
//
// The tree's edges are simple rotations: a rotation sequence contributes its
// auxiliary frames, so each frame F has one edge, F::step, to F::tree_parent.
#pragma once

#include <type_traits>

#include "kane/detail/frame_check.hpp"
#include "kane/detail/list.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// list<F, tree parent of F, ..., root>
template <class F, class P = typename F::tree_parent>
struct ancestors {
  using type = typename push_front<F, typename ancestors<P>::type>::type;
};
template <class F>
struct ancestors<F, void> {
  using type = list<F>;
};

template <class F>
using root_of = typename at<typename ancestors<F>::type, size<typename ancestors<F>::type>::value - 1>::type;

// From A up to the common ancestor (up: A, ..., excluding it), then down to B
// (down: from below the common ancestor to B). Each listed frame stands for
// the edge to its tree parent.
template <class A, class B>
struct path {
  using common = typename first_common<typename ancestors<A>::type, typename ancestors<B>::type>::type;
  static constexpr bool joined = !std::is_void_v<common>;
  using up = typename before<typename ancestors<A>::type, common>::type;
  using down = typename reverse<typename before<typename ancestors<B>::type, common>::type>::type;
};

// Frames and their ancestors, each once, every ancestor before its children.
template <class... F>
struct closure {
  using type =
      typename unique<typename concat<typename reverse<typename ancestors<F>::type>::type...>::type>::type;
};

// The path from A to B, required to exist: the one check that two frames share a tree.
template <class A, class B>
struct joined_frames : path<A, B> {
  static_assert(
      check<path<A, B>::joined,
            error::frames_of_two_trees_relate_them_through_a_common_root_frame<root_of<A>, root_of<B>>>);
};
// The same check where a path is walked for direction cosines (frames/express.hpp).
template <class A, class B>
struct joined_path : joined_frames<A, B> {};

// Acc and the nodes above T (Up<T>::type, void above a root) that Acc lacks, ancestors first.
template <template <class> class Up, class Acc, class T, bool = std::is_void_v<T> || contains<T, Acc>::value>
struct with_ancestors {
  using type = Acc;
};
template <template <class> class Up, class Acc, class T>
struct with_ancestors<Up, Acc, T, false> {
  using above = typename with_ancestors<Up, Acc, typename Up<T>::type>::type;
  using type = typename concat<above, list<T>>::type;
};
// The nodes T... and their ancestors, each once, ancestors first: linear in the nodes times
// the depth, with recursion no deeper than their number plus the depth.
template <template <class> class Up, class Acc, class... T>
struct tree_union {
  using type = Acc;
};
template <template <class> class Up, class Acc, class T, class... Ts>
struct tree_union<Up, Acc, T, Ts...> : tree_union<Up, typename with_ancestors<Up, Acc, T>::type, Ts...> {};
template <class F>
struct frame_up {
  using type = typename F::tree_parent;
};
}  // namespace kane::detail
#pragma GCC diagnostic pop
