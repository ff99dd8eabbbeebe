// An expression rebuilt node by node: the leaves a rule T handles (T::handles<X>) become
// T::apply(x), every sum, difference, product, quotient, negation, function, power, scaling, cross
// and dot product is rebuilt from its rebuilt operands (type-level zeros erase their terms), a
// quantity becomes its rebuilt vector, and any other node T::other(x).
#pragma once

#include "kane/expressions/derived_products.hpp"
#include "kane/expressions/nodes.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/scalars/expr.hpp"

namespace kane::detail {

template <class T, class X>
constexpr auto rebuild(X x) {
  if constexpr (T::template handles<X>)
    return T::apply(x);
  else if constexpr (is_v<X, add> || is_v<X, vsum>)
    return rebuild<T>(x.l) + rebuild<T>(x.r);
  else if constexpr (is_v<X, sub> || is_v<X, vdiff>)
    return rebuild<T>(x.l) - rebuild<T>(x.r);
  else if constexpr (is_v<X, mul>)
    return rebuild<T>(x.l) * rebuild<T>(x.r);
  else if constexpr (is_v<X, quot>)
    return rebuild<T>(x.l) / rebuild<T>(x.r);
  else if constexpr (is_v<X, neg>)
    return -rebuild<T>(x.x);
  else if constexpr (is_v<X, vneg>)
    return -rebuild<T>(x.v);
  else if constexpr (is_v<X, unary>)
    return unary_info<X>::fn::apply(rebuild<T>(x.x));
  else if constexpr (power_info<X>::value)
    return pow<power_info<X>::n>(rebuild<T>(x.x));
  else if constexpr (is_v<X, call>)
    return invoke(x.f, rebuild<T>(x.x));
  else if constexpr (is_v<X, scaled>)
    return rebuild<T>(x.s) * rebuild<T>(x.v);
  else if constexpr (is_v<X, vcross>)
    return derived_cross(rebuild<T>(x.l), rebuild<T>(x.r));
  else if constexpr (is_v<X, vdot>)
    return derived_dot(rebuild<T>(x.l), rebuild<T>(x.r));
  else if constexpr (Quantity<X>)
    return rebuild<T>(x.v);
  else
    return T::other(x);
}

}  // namespace kane::detail
