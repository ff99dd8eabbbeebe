// Direction cosines the tree decides: e_Ai . e_Bj is 1 or 0 when the two unit
// vectors are vectors of one frame, and cos theta, +-sin theta or 0 when they
// sit on the two sides of one simple rotation about a principal axis by theta
// (undecided across a spin but on its axis).
// A unit vector on the axis of such a rotation is a unit vector of both frames.
#pragma once

#include <type_traits>

#include "kane/frames/axis.hpp"
#include "kane/scalars/expr.hpp"
#include "kane/scalars/functions.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// The principal axis (0, 1, 2) the edge above F turns about; -1 for a root, another axis or no axis.
template <class F>
constexpr int edge_principal() {
  if constexpr (std::is_void_v<typename F::tree_parent>)
    return -1;
  else if constexpr (requires { typename F::step::axis; })
    return unit_axis<typename F::step::axis>::principal;
  else
    return -1;
}

// The highest frame up the tree of which e_FI is a unit vector.
template <class F, int I>
constexpr auto lift() {
  if constexpr (edge_principal<F>() == I - 1)
    return lift<typename F::tree_parent, I>();
  else
    return static_cast<F*>(nullptr);
}
template <class F, int I>
using lifted_t = std::remove_pointer_t<decltype(lift<F, I>())>;

// e_AI = e_PI for P = A or a frame below A.
template <class A, int I, class P>
constexpr bool reaches_down() {
  if constexpr (std::is_same_v<A, P>)
    return true;
  else if constexpr (edge_principal<P>() == I - 1)
    return reaches_down<A, I, typename P::tree_parent>();
  else
    return false;
}

// e_AI is a unit vector of the tree parent of B, and B turns about a principal axis by an angle.
template <class A, int I, class B>
constexpr bool above_edge() {
  if constexpr (edge_principal<B>() < 0 || requires { B::step::speed_index; })
    return false;  // a spin's angle is not known
  else
    return reaches_down<A, I, typename B::tree_parent>();
}

struct undecided {};

// e_PI . e_CJ, C turned from its tree parent P about a principal axis p by theta: (^P P^C)_JI.
template <class C, int I, int J>
constexpr auto across_edge() {
  constexpr int p = edge_principal<C>(), i = I - 1, j = J - 1;
  if constexpr (i == p || j == p)
    return std::conditional_t<i == j, one_t, zero_t>{};
  else if constexpr (i == j)
    return cos(C::step::angle);
  else if constexpr (j == (p + 1) % 3)
    return sin(C::step::angle);
  else
    return -sin(C::step::angle);
}

// e_AI . e_BJ when the tree decides it, undecided otherwise.
template <class A, int I, class B, int J>
constexpr auto tree_dot() {
  using LA = lifted_t<A, I>;
  using LB = lifted_t<B, J>;
  if constexpr (std::is_same_v<LA, LB>)
    return std::conditional_t<I == J, one_t, zero_t>{};
  else if constexpr (above_edge<LA, I, LB>())
    return across_edge<LB, I, J>();
  else if constexpr (above_edge<LB, J, LA>())
    return across_edge<LA, J, I>();
  else
    return undecided{};
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
