// kane: forward declarations.
//
// Naming rule: types are snake_case nouns (vec, dcm, state, coordinate);
// concepts are PascalCase adjectives or nouns (Frame, Scalar, Axis, Orientation);
// they never share a name. Frame template arguments follow the notation:
// ^A P^B is dcm<A, B>, observer (or "from") frame first.
#pragma once

#include <cstddef>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

struct root_frame;
template <class Parent, class Orientation>
struct frame;

template <class F, class S>
class vec;
template <class A, class B, class S>
class dcm;

}  // namespace kane
#pragma GCC diagnostic pop
