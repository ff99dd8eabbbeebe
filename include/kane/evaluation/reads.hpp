// What a computation reads of an evaluator's acceleration level, found from the types of
// the expressions it evaluates: the frames whose ^R alpha^F it needs (alpha nodes, and up
// the tree the parents a frame's alpha is built from) and the coordinates whose q'' it
// needs (q'' leaves, and the edges those alphas turn). evaluator::update_for computes
// only these at the acceleration level (motion.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kane/detail/list.hpp"
#include "kane/detail/tree.hpp"
#include "kane/evaluation/component_rates.hpp"
#include "kane/kinematics/angular_velocity.hpp"
#include "kane/kinematics/derivative_traits.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <std::size_t N, std::size_t NQ>
struct acceleration_reads {
  std::array<bool, N> alpha{};
  std::array<bool, NQ> qdd{};
};

// the q'' of the edge above F
template <class Closure, class F, class Out>
constexpr void mark_edge(Out& out) {
  constexpr std::uint64_t bits = [] {
    if constexpr (std::is_void_v<typename F::tree_parent>)
      return std::uint64_t(0);
    else
      return edge_rates<F>();
  }();
  for (std::size_t i = 0; i < out.qdd.size() && i < 64; ++i)
    if (bits & (std::uint64_t(1) << i)) out.qdd[i] = true;
}
template <class Closure, class X, class Out>
constexpr void mark_reads(Out& out) {
  if constexpr (is_v<X, alpha>) {
    using F = typename X::frame;
    if constexpr (contains<F, Closure>::value)
      out.alpha[index_of<F, Closure>::value] = true;
    else  // one edge below a held frame: its parent's alpha and the edge's q''
      mark_reads<Closure, alpha<typename F::tree_parent>>(out), mark_edge<Closure, F>(out);
  } else if constexpr (is_v<X, angular_acceleration_of>)
    mark_reads<Closure, decltype(expand(std::declval<const X&>()))>(out);
  else if constexpr (coordinate_info<X>::value) {
    if constexpr (X::order == 2 && X::index <= std::tuple_size_v<decltype(Out::qdd)>)
      out.qdd[X::index - 1] = true;
  } else if constexpr (requires(X x) {
                         x.l;
                         x.r;
                       })
    mark_reads<Closure, std::remove_cvref_t<decltype(std::declval<const X&>().l)>>(out),
        mark_reads<Closure, std::remove_cvref_t<decltype(std::declval<const X&>().r)>>(out);
  else if constexpr (requires(X x) {
                       x.s;
                       x.v;
                     })
    mark_reads<Closure, std::remove_cvref_t<decltype(std::declval<const X&>().s)>>(out),
        mark_reads<Closure, std::remove_cvref_t<decltype(std::declval<const X&>().v)>>(out);
  else if constexpr (requires(X x) { x.v; })
    mark_reads<Closure, std::remove_cvref_t<decltype(std::declval<const X&>().v)>>(out);
  else if constexpr (requires(X x) { x.x; })
    mark_reads<Closure, std::remove_cvref_t<decltype(std::declval<const X&>().x)>>(out);
}

// The reads of the expressions Xs at the acceleration level of the evaluator Rates: alphas
// propagate to parents through edges, not through frames
// whose speeds give their rates (component_rates.hpp).
template <class Rates, class... Xs>
constexpr auto acceleration_reads_of(list<Xs...>) {
  using Closure = typename Rates::closure;
  constexpr std::size_t N = size<Closure>::value;
  constexpr std::size_t NQ = Rates::state_type::nq;
  acceleration_reads<N, NQ> out;
  (mark_reads<Closure, Xs>(out), ...);
  [&]<class... F>(list<F...>) {
    constexpr std::size_t n = sizeof...(F);
    constexpr std::array<std::size_t, n> parents{[] {
      if constexpr (std::is_void_v<typename F::tree_parent>)
        return n;
      else
        return std::size_t(index_of<typename F::tree_parent, Closure>::value);
    }()...};
    constexpr std::array<bool, n> by_edge{
        (!std::is_void_v<typename F::tree_parent> && component_speeds_in<Closure, F, Rates>() == 0)...};
    using edge_marker = void (*)(acceleration_reads<N, NQ>&);
    constexpr std::array<edge_marker, n> edges{&mark_edge<Closure, F, acceleration_reads<N, NQ>>...};
    for (std::size_t k = n; k-- > 0;)
      if (out.alpha[k] && by_edge[k]) {
        out.alpha[parents[k]] = true;
        edges[k](out);
      }
  }(Closure{});
  return out;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
