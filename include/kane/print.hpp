// Printing, kept apart from the core (the only header that includes ostream).
//   ^N(1, 2, 3)          components of a vector in N
//   ^N P^A [[...], ...]  direction cosines from N to A, row by row
//   L1*q1' a2 + ^N w^B x b1   expressions, in Kane's notation: e_A1 is a1,
//                        ^A w^B and ^A alpha^B angular velocity and acceleration,
//                        q1' the time derivative; auxiliary frames of a
//                        rotation sequence from D print as D', D''.
#pragma once

#include <cctype>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>

#include "kane/evaluation.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/frames/dcm.hpp"
#include "kane/frames/vec.hpp"
#include "kane/kinematics/derivative.hpp"
#include "kane/kinematics/point.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// A type's name as written in its declaration, without namespaces
// (read from the compiler's signature string: no RTTI).
template <class F>
constexpr std::string_view type_name() {
  std::string_view s = __PRETTY_FUNCTION__;
#if defined(__clang__)
  s = s.substr(s.find("F = ") + 4);
  s = s.substr(0, s.find(']'));
#else
  s = s.substr(s.find("F = ") + 4);
  s = s.substr(0, s.find_first_of(";]"));
#endif
  const auto colons = s.rfind("::", s.find('<'));
  return colons == std::string_view::npos ? s : s.substr(colons + 2);
}

namespace detail {
template <class F>
struct aux_info : std::false_type {};
template <class P, class Steps, std::size_t K>
struct aux_info<aux_frame<P, Steps, K>> : std::true_type {
  using parent = P;
  static constexpr std::size_t k = K;
};
}  // namespace detail

// A frame's name: its type's name; D', D'' for the auxiliary frames from D.
template <class F>
std::string frame_name() {
  if constexpr (detail::aux_info<F>::value)
    return frame_name<typename detail::aux_info<F>::parent>() + std::string(detail::aux_info<F>::k, '\'');
  else
    return std::string(type_name<F>());
}

// p as ^F(a1, a2, a3)
template <class F, class S>
std::ostream& operator<<(std::ostream& os, const vec<F, S>& p) {
  return os << '^' << frame_name<F>() << '(' << p[0] << ", " << p[1] << ", " << p[2] << ')';
}

// ^A P^B row after row
template <class A, class B, class S>
std::ostream& operator<<(std::ostream& os, const dcm<A, B, S>& p) {
  os << '^' << frame_name<A>() << " P^" << frame_name<B>() << " [";
  for (int i = 0; i < 3; ++i) os << (i ? ", [" : "[") << p(i, 0) << ", " << p(i, 1) << ", " << p(i, 2) << ']';
  return os << ']';
}

namespace detail {

// Precedence: 0 sum, 1 product, 2 unary minus, 3 atom.
template <class X>
constexpr int precedence() {
  if constexpr (is_v<X, add> || is_v<X, sub> || is_v<X, vsum> || is_v<X, vdiff>)
    return 0;
  else if constexpr (is_v<X, mul> || is_v<X, quot> || is_v<X, scaled> || is_v<X, vcross> || is_v<X, vdot>)
    return 1;
  else if constexpr (is_v<X, neg> || is_v<X, vneg>)
    return 2;
  else if constexpr (is_constant<X>::value) {
    if constexpr (X::den != 1 || X::num < 0) return 1;
    return 3;
  } else
    return 3;
}

template <class X>
void print_expr(std::ostream& os, const X& x);
template <class F>
void print_function(std::ostream& os, const F& f);

// speed_set_one<Sp> * r, as velocity_remainder<Sp> builds it: printed as r
template <class X>
constexpr bool bound_product() {
  if constexpr (is_v<X, mul>)
    return BoundOne<std::remove_cvref_t<decltype(std::declval<const X&>().l)>>;
  else if constexpr (is_v<X, scaled>)
    return BoundOne<std::remove_cvref_t<decltype(std::declval<const X&>().s)>>;
  else
    return false;
}
template <class X>
const auto& remainder_factor(const X& x) {
  if constexpr (is_v<X, mul>)
    return x.r;
  else
    return x.v;
}

template <class X>
void print_operand(std::ostream& os, const X& x, int min) {
  if constexpr (is_v<X, velocity_of> || is_v<X, acceleration_of>)
    print_operand(os, x.v, min);
  else if constexpr (bound_product<X>())  // a velocity remainder: the speed set is not printed
    print_operand(os, remainder_factor(x), min);
  else if (precedence<X>() < min) {
    os << '(';
    print_expr(os, x);
    os << ')';
  } else
    print_expr(os, x);
}

template <class X>
void print_expr(std::ostream& os, const X& x) {
  if constexpr (bound_product<X>())
    print_expr(os, remainder_factor(x));
  else if constexpr (BoundOne<X>)
    os << '1';
  else if constexpr (coordinate_info<X>::value || speed_info<X>::value)
    os << (coordinate_info<X>::value ? 'q' : 'u') << X::index << std::string(X::order, '\'');
  else if constexpr ((Parameter<X> || Input<X>)&&requires { X::name; })
    os << X::name;
  else if constexpr (Parameter<X>) {
    if constexpr (std::is_same_v<X, parameter<X::index>>)
      os << 'p' << X::index;
    else
      os << type_name<X>();
  } else if constexpr (Input<X>)
    os << 'r' << X::index;
  else if constexpr (std::is_same_v<X, time_variable>)
    os << 't';
  else if constexpr (is_constant<X>::value) {
    os << X::num;
    if constexpr (X::den != 1) os << '/' << X::den;
  } else if constexpr (std::is_same_v<X, literal> || is_fixed<X>::value)
    os << x.value;
  else if constexpr (kde_info<X>::value) {  // W_SR = dq_S'/du_R, X_S: numbers of the evaluator
    if constexpr (requires { X::column; })
      os << 'W' << X::row << '_' << X::column;
    else
      os << 'X' << X::row;
  } else if constexpr (is_v<X, add> || is_v<X, vsum>) {
    print_operand(os, x.l, 0);
    os << " + ";
    print_operand(os, x.r, 1);
  } else if constexpr (is_v<X, sub> || is_v<X, vdiff>) {
    print_operand(os, x.l, 0);
    os << " - ";
    print_operand(os, x.r, 1);
  } else if constexpr (is_v<X, mul> || is_v<X, quot>) {
    print_operand(os, x.l, 1);
    os << (is_v<X, mul> ? "*" : "/");
    print_operand(os, x.r, is_v<X, mul> ? 1 : 2);
  } else if constexpr (is_v<X, neg>) {
    os << '-';
    print_operand(os, x.x, 2);
  } else if constexpr (is_v<X, vneg>) {
    os << '-';
    print_operand(os, x.v, 2);
  } else if constexpr (is_v<X, unary>) {
    os << unary_info<X>::fn::name << '(';
    print_expr(os, x.x);
    os << ')';
  } else if constexpr (power_info<X>::value) {
    print_operand(os, x.x, 3);
    os << '^' << power_info<X>::n;
  } else if constexpr (is_v<X, call>) {
    print_function(os, x.f);
    os << '(';
    print_expr(os, x.x);
    os << ')';
  } else if constexpr (is_unit<X>::value) {
    std::string name = frame_name<typename X::frame>();
    for (auto& c : name) c = char(std::tolower(static_cast<unsigned char>(c)));
    os << name << X::index;
  } else if constexpr (is_zero_vector_v<X>)
    os << '0';
  else if constexpr (is_v<X, scaled>) {
    print_operand(os, x.s, 1);
    os << ' ';
    print_operand(os, x.v, 2);
  } else if constexpr (is_v<X, vcross> || is_v<X, vdot>) {
    print_operand(os, x.l, 2);
    os << (is_v<X, vcross> ? " x " : " . ");
    print_operand(os, x.r, 2);
  } else if constexpr (is_v<X, omega> || is_v<X, alpha>) {
    os << '^' << frame_name<root_of<typename X::frame>>() << (is_v<X, omega> ? " w^" : " alpha^")
       << frame_name<typename X::frame>();
  } else if constexpr (is_v<X, angular_velocity_of> || is_v<X, angular_acceleration_of>) {
    os << '^' << frame_name<typename X::observer>() << (is_v<X, angular_velocity_of> ? " w^" : " alpha^")
       << frame_name<typename X::body>();
  } else if constexpr (Quantity<X>)
    print_expr(os, x.v);
  else
    static_assert(!sizeof(X), "kane: printing of an unknown node");
}

template <class F>
void print_function(std::ostream& os, const F& f) {
  if constexpr (is_v<F, derivative_of>) {
    print_function(os, f.f);
    os << '\'';
  } else
    os << type_name<F>();
}

}  // namespace detail

// The expression in Kane's notation, e.g. "L1*q1' a2".
template <class X>
requires ScalarExpr<X> || VectorExpr<X> std::string to_string(const X& x) {
  std::ostringstream os;
  detail::print_expr(os, x);
  return os.str();
}

// the expression in Kane's notation, as to_string
template <class X>
requires ScalarExpr<X> || VectorExpr<X> std::ostream& operator<<(std::ostream& os, const X& x) {
  detail::print_expr(os, x);
  return os;
}

}  // namespace kane
#pragma GCC diagnostic pop
