// Printing, kept apart from the core (the only header that includes <ostream>).
//   ^N(1, 2, 3)          components of a vector in N
//   ^N P^A [[...], ...]  direction cosines from N to A, row by row
#pragma once

#include <ostream>
#include <string_view>

#include "kane/dcm.hpp"
#include "kane/vec.hpp"

namespace kane {

// The frame's name as written in its declaration, without namespaces
// (read from the compiler's signature string: no RTTI).
template <class F>
constexpr std::string_view frame_name() {
  std::string_view s = __PRETTY_FUNCTION__;
#if defined(__clang__)
  s = s.substr(s.find("F = ") + 4);
  s = s.substr(0, s.find(']'));
#else
  s = s.substr(s.find("F = ") + 4);
  s = s.substr(0, s.find_first_of(";]"));
#endif
  const auto colons = s.rfind("::");
  return colons == std::string_view::npos ? s : s.substr(colons + 2);
}

template <class F, class S>
std::ostream& operator<<(std::ostream& os, const vec<F, S>& p) {
  return os << '^' << frame_name<F>() << '(' << p[0] << ", " << p[1] << ", " << p[2] << ')';
}

template <class A, class B, class S>
std::ostream& operator<<(std::ostream& os, const dcm<A, B, S>& p) {
  os << '^' << frame_name<A>() << " P^" << frame_name<B>() << " [";
  for (int i = 0; i < 3; ++i) os << (i ? ", [" : "[") << p(i, 0) << ", " << p(i, 1) << ", " << p(i, 2) << ']';
  return os << ']';
}

}  // namespace kane
