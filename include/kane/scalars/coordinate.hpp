// Generalized coordinates q_i(t), generalized speeds u_i(t), time t and
// runtime parameters: the leaves of scalar expressions.
#pragma once

#include <concepts>
#include <cstddef>
#include <type_traits>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
struct scalar_tag {};
}  // namespace detail

// The D-th time derivative of q_I (1-based; values at q[I-1], qd[I-1], qdd[I-1]).
template <std::size_t I, std::size_t D = 0>
struct coordinate : detail::scalar_tag {
  static_assert(I >= 1, "kane: generalized coordinates are numbered from 1 (q1, q2, ...)");
  // I of q_I (from 1)
  static constexpr std::size_t index = I;
  // D of q_I^(D): 0, 1 or 2
  static constexpr std::size_t order = D;
};

// The D-th time derivative of u_I (values at u[I-1], ud[I-1]).
template <std::size_t I, std::size_t D = 0>
struct speed : detail::scalar_tag {
  static_assert(I >= 1, "kane: generalized speeds are numbered from 1 (u1, u2, ...)");
  // I of u_I (from 1)
  static constexpr std::size_t index = I;
  // D of u_I^(D): 0 or 1
  static constexpr std::size_t order = D;
};

// A named runtime parameter (a length, a mass), value at p[I-1]. Name one by
// deriving: struct L1 : kane::parameter<1> {};
template <std::size_t I>
struct parameter : detail::scalar_tag {
  static_assert(I >= 1, "kane: parameters are numbered from 1");
  // I of p_I: the value is p[I-1]
  static constexpr std::size_t index = I;
};

// An input r_I (a joint torque, a control), value at r[I-1] of the state: read by loads,
// set per call (evaluator::set_inputs, motion::inputs) without a new pass over the frames.
template <std::size_t I>
struct input : detail::scalar_tag {
  static_assert(I >= 1, "kane: inputs are numbered from 1");
  // I of r_I: the value is r[I-1]
  static constexpr std::size_t index = I;
};

namespace detail {
// A name as a template argument ("m" in kane::named_parameter<1, "m">).
template <std::size_t N>
struct fixed_name {
  char text[N]{};
  // the characters of s, its terminating zero included
  constexpr fixed_name(const char (&s)[N]) {
    for (std::size_t i = 0; i < N; ++i) text[i] = s[i];
  }
};
}  // namespace detail

// p_I named in one line and printed by its name: inline constexpr kane::named_parameter<1, "m"> m;
template <std::size_t I, detail::fixed_name Name>
struct named_parameter : parameter<I> {
  // the name printed
  static constexpr const char* name = Name.text;
};
// r_I named in one line and printed by its name: inline constexpr kane::named_input<1, "T"> T;
template <std::size_t I, detail::fixed_name Name>
struct named_input : input<I> {
  // the name printed
  static constexpr const char* name = Name.text;
};

struct time_variable : detail::scalar_tag {};

// Tag objects: q<1> is q_1, u<2> is u_2, t is time.
template <std::size_t I>
inline constexpr coordinate<I> q{};
// u<1> is u_1, u<2> is u_2, ...
template <std::size_t I>
inline constexpr speed<I> u{};
// r<1> is the input r_1, r<2> is r_2, ...
template <std::size_t I>
inline constexpr input<I> r{};
// t is the time
inline constexpr time_variable t{};

namespace detail {
template <class T>
struct is_coordinate : std::false_type {};
template <std::size_t I>
struct is_coordinate<coordinate<I, 0>> : std::true_type {};
template <class T>
struct is_speed : std::false_type {};
template <std::size_t I>
struct is_speed<speed<I, 0>> : std::true_type {};
template <std::size_t I>
std::true_type is_parameter_base(const parameter<I>*);
std::false_type is_parameter_base(const void*);
}  // namespace detail

// q_I itself (not a derivative): what orientations and partial derivatives take.
template <class T>
concept Coordinate = detail::is_coordinate<T>::value;
template <class T>
concept Speed = detail::is_speed<T>::value;
template <class T>
concept Parameter = decltype(detail::is_parameter_base(static_cast<const T*>(nullptr)))::value;
template <class T>
concept Input = requires {
  T::index;
}
&&__is_base_of(input<T::index>, T);

}  // namespace kane
#pragma GCC diagnostic pop
