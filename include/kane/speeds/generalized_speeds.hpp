// Generalized speeds u_r = sum_s Y_rs(q, t) q_s' + Z_r(q, t) (seed eq. 17).
//
//   kane::qdot_speeds<6>                       u_r = q_r'
//   kane::speeds<dot(w, e<L, 1>), ...>         any n expressions linear in q'
//   kane::angular_velocity_speeds<N, R, L>     u_i = ^N w^R . l_i
//   kane::speeds<dt(q<1>), kane::free_speed>   u_1 = q_1', u_2 free (a spin rate)
//   kane::free_body_speeds<N, B, 5>            body rates of B, then q_5', q_6', q_7', unit_norm<B>
//
// Y_rs = du_r/dq_s' and Z_r = u_r at q' = 0 are built at compile time; the evaluator solves the kinematic
// differential equations at each state: q' = W u + X, W = Y^-1, X = -Y^-1 Z, and q'' = W (u' - Y' q' - Z').
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kane/detail/structure.hpp"
#include "kane/expressions/derived_products.hpp"
#include "kane/expressions/expr.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/kinematics/angular_velocity.hpp"
#include "kane/kinematics/derivative.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/speeds/component_speeds.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
struct speed_set_tag {};
}  // namespace detail

template <class T>
concept SpeedSet = std::derived_from<T, detail::speed_set_tag>;

// u_r = q_r', r = 1..N.
template <std::size_t N>
struct qdot_speeds : detail::speed_set_tag {
  // n = rows = defined = N: N speeds, each defined by a q'
  static constexpr std::size_t n = N, rows = N, defined = N;
  // true: Y = W = 1, X = 0
  static constexpr bool identity = true;
};

// A kinematic differential equation that defines no speed: X = 0, linear in q'
// (for instance unit_norm of the Euler parameters of B, so that nq = nu + 1).
template <ScalarExpr X>
struct held {
  // the expression, linear in q'
  [[no_unique_address]] X x;
  // the row v = 0
  constexpr explicit held(X v) : x(v) {}
};

namespace detail {
struct free_speed_t {};
}  // namespace detail

// A speed that defines no q': the rate of a frame that spins (kane::spin), listed after the speeds q' define.
inline constexpr detail::free_speed_t free_speed{};

namespace detail {
template <class T>
inline constexpr bool is_held = false;
template <class X>
inline constexpr bool is_held<held<X>> = true;
template <class X>
inline constexpr bool is_held<const held<X>> = true;
// 0 a speed defined by q', 1 a free speed, 2 a held row
template <class T>
inline constexpr int speed_kind = is_held<T>                                          ? 2
                                  : std::is_same_v<std::remove_cv_t<T>, free_speed_t> ? 1
                                                                                      : 0;
template <class T>
constexpr auto row_of(T x) {
  if constexpr (is_held<T>)
    return x.x;
  else
    return x;
}
template <int... Kind>
constexpr bool kinds_in_order() {
  int last = 0;
  bool ok = true;
  for (int k : {0, Kind...}) ok = ok && k >= last, last = k;
  return ok;
}
}  // namespace detail

// u_r = U_r, r = 1..defined: expressions in q, q' and t, linear in q'; then free speeds (kane::free_speed),
// u_r, r = defined + 1..n; then held rows (kinematic equations without a speed): rows = defined + held = nq.
template <auto... U>
struct speeds : detail::speed_set_tag {
  static_assert(((ScalarExpr<decltype(U)> || detail::speed_kind<decltype(U)> != 0) && ...),
                "kane: speeds<u1, ..., un> takes scalar expressions");
  static_assert(detail::kinds_in_order<detail::speed_kind<decltype(U)>...>(),
                "kane: in speeds<...> the speeds that q' define come first, then kane::free_speed, then held "
                "rows (kane::held, kane::unit_norm)");
  // the number of speeds defined by q'
  static constexpr std::size_t defined = (std::size_t(detail::speed_kind<decltype(U)> == 0) + ... + 0);
  // the number of free speeds
  static constexpr std::size_t free = (std::size_t(detail::speed_kind<decltype(U)> == 1) + ... + 0);
  // the number of kinematic equations: defined + held = nq
  static constexpr std::size_t rows = sizeof...(U) - free;
  // the number of speeds: defined + free
  static constexpr std::size_t n = defined + free;
  // false: Y is built from the definitions
  static constexpr bool identity = false;
  // the rows in order: U_r of the defined speeds, then the held rows
  static constexpr auto definitions = []<std::size_t... R>(std::index_sequence<R...>) {
    constexpr std::tuple<decltype(U)...> all{U...};
    return std::tuple{detail::row_of(std::get<(R < defined ? R : R + free)>(all))...};
  }
  (std::make_index_sequence<rows>{});
};

// q0 q0' + q1 q1' + q2 q2' + q3 q3' = 0, half the derivative of |e|^2 = 1 for
// the Euler parameters of B: the held row that completes three speeds of B.
template <Frame B>
inline constexpr auto unit_norm = [] {
  if constexpr (detail::euler_edge<B>) {
    constexpr auto c = B::step::coordinates;
    constexpr coordinate<c[0]> a{};
    constexpr coordinate<c[1]> b{};
    constexpr coordinate<c[2]> g{};
    constexpr coordinate<c[3]> h{};
    return held(a * dt(a) + b * dt(b) + g * dt(g) + h * dt(h));
  } else {
    static_assert(detail::check<false, error::unit_norm_needs_a_frame_oriented_by_euler_parameters<B>>);
    return held(zero_t{});
  }
}();

// u_1..u_3 = ^A w^B . f_1..3 (the components of ^A w^B in F), then Extra... (such as kane::dt(kane::q<4>)).
template <class A, class B, class F, auto... Extra>
using angular_velocity_speeds =
    speeds<dot(angular_velocity<A, B>(), e<F, 1>), dot(angular_velocity<A, B>(), e<F, 2>),
           dot(angular_velocity<A, B>(), e<F, 3>), Extra...>;

// A free body B on Euler parameters, its mass centre at q_P n1 + q_P+1 n2 + q_P+2 n3 of N: the body
// rates u_1..u_3 = ^N w^B . b_i, then u_4..u_6 = q_P', q_P+1', q_P+2', and unit_norm<B>.
template <class N, class B, std::size_t P>
using free_body_speeds =
    speeds<dot(angular_velocity<N, B>(), e<B, 1>), dot(angular_velocity<N, B>(), e<B, 2>),
           dot(angular_velocity<N, B>(), e<B, 3>), dt(coordinate<P>{}), dt(coordinate<P + 1>{}),
           dt(coordinate<P + 2>{}), unit_norm<B>>;
// q_P n1 + q_P+1 n2 + q_P+2 n3: a position by three coordinates along N's axes.
template <class N, std::size_t P>
inline constexpr auto position_coordinates =
    coordinate<P>{} * e<N, 1> + coordinate<P + 1>{} * e<N, 2> + coordinate<P + 2>{} * e<N, 3>;

// W_SR = dq_S'/du_R and X_S = q_S' at u = 0 of the speed set Sp: numbers the evaluator solves for.
template <std::size_t S, std::size_t R, class Sp>
struct kde_weight : detail::scalar_tag, detail::pose_number_tag {
  // row = S and column = R of W_SR
  static constexpr std::size_t row = S, column = R;
  // Sp, the speed set
  using speed_set = Sp;
  // W' = -W Y' W
  static constexpr auto time_derivative();
};
// X_S of q' = W u + X for the speed set Sp: a scalar the evaluator computes.
template <std::size_t S, class Sp>
struct kde_offset : detail::scalar_tag, detail::pose_number_tag {
  // S of X_S
  static constexpr std::size_t row = S;
  // Sp, the speed set
  using speed_set = Sp;
  // X' = -W (Y' X + Z')
  static constexpr auto time_derivative();
};

// 1, read only by an evaluator of the speed set Sp: velocity_remainder<Sp> is this times the remainder.
template <class Sp>
struct speed_set_one : detail::scalar_tag, detail::bound_one_tag {
  // Sp, the speed set
  using speed_set = Sp;
};

namespace detail {
template <class X>
struct kde_info : std::false_type {};
template <std::size_t S, std::size_t R, class Sp>
struct kde_info<kde_weight<S, R, Sp>> : std::true_type {};
template <std::size_t S, class Sp>
struct kde_info<kde_offset<S, Sp>> : std::true_type {};

// The part of ^R w^F without q' and u: dtheta/dt k of the edges above F turned by a prescribed angle.
template <class F>
constexpr auto explicit_time_omega() {
  if constexpr (std::is_void_v<typename F::tree_parent>)
    return zero_vector{};
  else if constexpr (matrix_edge<F> || spin_edge<F>)
    return explicit_time_omega<typename F::tree_parent>();
  else {
    constexpr auto d = partial<time_variable>(F::step::angle);
    if constexpr (is_zero_v<std::remove_cv_t<decltype(d)>>)
      return explicit_time_omega<typename F::tree_parent>();
    else
      return explicit_time_omega<typename F::tree_parent>() + d * axis_vector<F>();
  }
}

// Replace q', q'', u, u' by zero (the part of an expression linear in them drops out): x at rest.
template <class X>
constexpr auto at_rest(X x) {
  if constexpr (coordinate_info<X>::value) {
    if constexpr (X::order == 0)
      return x;
    else
      return zero_t{};
  } else if constexpr (speed_info<X>::value)
    return zero_t{};
  else if constexpr (ScalarExpr<X> &&
                     (LeafConstant<X> || std::is_same_v<X, time_variable> || kde_info<X>::value))
    return x;
  else if constexpr (is_v<X, add> || is_v<X, vsum>)
    return at_rest(x.l) + at_rest(x.r);
  else if constexpr (is_v<X, sub> || is_v<X, vdiff>)
    return at_rest(x.l) - at_rest(x.r);
  else if constexpr (is_v<X, mul>)
    return at_rest(x.l) * at_rest(x.r);
  else if constexpr (is_v<X, quot>)
    return at_rest(x.l) / at_rest(x.r);
  else if constexpr (is_v<X, neg>)
    return -at_rest(x.x);
  else if constexpr (is_v<X, vneg>)
    return -at_rest(x.v);
  else if constexpr (is_v<X, unary>)
    return unary_info<X>::fn::apply(at_rest(x.x));
  else if constexpr (power_info<X>::value)
    return pow<power_info<X>::n>(at_rest(x.x));
  else if constexpr (is_v<X, call>)
    return invoke(x.f, at_rest(x.x));
  else if constexpr (is_v<X, scaled>)
    return at_rest(x.s) * at_rest(x.v);
  else if constexpr (is_v<X, vcross>)
    return derived_cross(at_rest(x.l), at_rest(x.r));
  else if constexpr (is_v<X, vdot>)
    return derived_dot(at_rest(x.l), at_rest(x.r));
  else if constexpr (is_unit<X>::value || is_zero_vector_v<X>)
    return x;
  else if constexpr (is_v<X, omega>)
    return explicit_time_omega<typename X::frame>();  // linear in q', plus the prescribed rates
  else if constexpr (is_v<X, angular_velocity_of>)
    return at_rest(expand(x));
  else if constexpr (is_v<X, alpha> || is_v<X, angular_acceleration_of>)
    static_assert(!sizeof(X), "kane: an angular acceleration is not linear in the speeds");
  else if constexpr (Quantity<X>)
    return at_rest(x.v);
  else
    static_assert(!sizeof(X), "kane: at_rest of an unknown node");
}

// The kind of an entry of a matrix whose entries are expressions.
template <class X>
constexpr entry entry_of() {
  return is_zero_v<X> ? entry::zero : is_one_v<X> ? entry::one : entry::other;
}

// The kinematic differential equations of a speed set as a structured solve
// (evaluation/block_solve.hpp): Y = du/dq' (rows x rows, held rows included), W = Y^-1 with its pattern x,
// and the patterns of Z = u at q' = 0 and of X = -W Z.
template <class Sp>
struct kde_system {
  static constexpr std::size_t n = Sp::rows, k = n, d = n == 0 ? 1 : n;  // d: no division by 0 for nq = 0
  template <std::size_t R, std::size_t C>
  using y_type = decltype(diff(std::get<R>(Sp::definitions), coordinate<C + 1, 1>{}));
  template <std::size_t R>
  using z_type = decltype(at_rest(std::get<R>(Sp::definitions)));
  // Y_rs holds no q': each row is linear in q'
  static constexpr bool linear = []<std::size_t... I>(std::index_sequence<I...>) {
    return ((leaves_of<std::remove_cv_t<y_type<I / d, I % d>>>.rates == 0) && ... && true);
  }
  (std::make_index_sequence<n * n>{});
  static_assert(linear,
                "kane: a generalized speed is linear in q': u_r = sum_s Y_rs(q, t) q_s' + Z_r(q, t), "
                "with no q' in Y_rs; write u_r without products or functions of the rates");
  static constexpr pattern<n, n> m = []<std::size_t... I>(std::index_sequence<I...>) {
    pattern<n, n> p{};
    ((p[I / d][I % d] = entry_of<y_type<I / d, I % d>>()), ...);
    return p;
  }
  (std::make_index_sequence<n * n>{});
  static constexpr pattern<n, n> r = identity_pattern<n>();
  static constexpr block_form<n> form = blocks_of(m);
  static constexpr pattern<n, n> x = solution_pattern(m, form, r);
  static constexpr std::array<entry, n> z = []<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<entry, n>{entry_of<z_type<I>>()...};
  }
  (std::make_index_sequence<n>{});
  static constexpr std::array<bool, n> offset = [] {
    std::array<bool, n> o{};
    for (std::size_t c = 0; c < n; ++c)
      for (std::size_t j = 0; j < n; ++j) o[c] = o[c] || (x[c][j] != entry::zero && z[j] != entry::zero);
    return o;
  }();
  // The blocks of orthogonal rows (Y_B Y_B^T diagonal, Y_B^-1 = Y_B^T (Y_B Y_B^T)^-1): the three
  // rates and the unit_norm row of a frame turned by Euler parameters, in its four q'.
  static constexpr std::array<bool, n + 1> orthogonal = []<std::size_t... R>(std::index_sequence<R...>) {
    const std::array<std::array<std::size_t, 4>, n> rows{euler_row<Sp, R>()...};
    std::array<bool, n + 1> out{};
    for (std::size_t b = 0; b < form.count; ++b) {
      const std::size_t first = form.start[b];
      bool ok = form.start[b + 1] - first == 4;
      for (std::size_t a = 0; ok && a < 4; ++a) {
        const auto& q = rows[form.row[form.order[first + a]]];
        for (std::size_t e = 0; ok && e < 4; ++e) {
          bool in = false;
          for (std::size_t i : q) in = in || i == form.order[first + e] + 1;
          ok = in;
        }
      }
      out[b] = ok;
    }
    return out;
  }
  (std::make_index_sequence<n>{});
};

// dq_S'/du_R and q_S' at u = 0 as nodes: type-level zero and one where the
// structure of Y decides them, numbers of the evaluator otherwise.
template <class Sp, std::size_t S, std::size_t R>
constexpr auto weight() {
  if constexpr (R > Sp::defined)  // a free speed
    return zero_t{};
  else if constexpr (Sp::identity)
    return std::conditional_t<S == R, one_t, zero_t>{};
  else if constexpr (kde_system<Sp>::x[S - 1][R - 1] == entry::zero)
    return zero_t{};
  else if constexpr (kde_system<Sp>::x[S - 1][R - 1] == entry::one)
    return one_t{};
  else
    return kde_weight<S, R, Sp>{};
}
template <class Sp, std::size_t S>
constexpr auto offset() {
  if constexpr (Sp::identity || !kde_system<Sp>::offset[S - 1])
    return zero_t{};
  else
    return kde_offset<S, Sp>{};
}

// W_SA of every row A, held rows included (weight() gives 0 there: u is 0 in a held row).
template <class Sp, std::size_t S, std::size_t A>
constexpr auto full_weight() {
  if constexpr (kde_system<Sp>::x[S - 1][A - 1] == entry::zero)
    return zero_t{};
  else if constexpr (kde_system<Sp>::x[S - 1][A - 1] == entry::one)
    return one_t{};
  else
    return kde_weight<S, A, Sp>{};
}
// sum over a = 1..rows of W_Sa Y'_a(X), skipping the products known to be zero; Y'_a(X) of row a.
template <class Sp, std::size_t S, class Row>
constexpr auto weighted_rows(Row row) {
  return [&]<std::size_t... A>(std::index_sequence<A...>) {
    return (zero_t{} + ... + [&] {
      const auto w = full_weight<Sp, S, A + 1>();
      const auto y = row(index_c<A + 1>{});
      if constexpr (is_zero_v<std::remove_cv_t<decltype(w)>> || is_zero_v<std::remove_cv_t<decltype(y)>>)
        return zero_t{};
      else
        return w * y;
    }());
  }
  (std::make_index_sequence<Sp::rows>{});
}
// sum over b = 1..rows of dt(Y_ab) x_b for row a, x_b = Of(b)
template <class Sp, std::size_t A, class Of>
constexpr auto rate_row(Of of) {
  return [&]<std::size_t... B>(std::index_sequence<B...>) {
    return (zero_t{} + ... + [&] {
      const auto yd = ddt(diff(std::get<A - 1>(Sp::definitions), coordinate<B + 1, 1>{}));
      const auto x = of(index_c<B + 1>{});
      if constexpr (is_zero_v<std::remove_cv_t<decltype(yd)>> || is_zero_v<std::remove_cv_t<decltype(x)>>)
        return zero_t{};
      else
        return yd * x;
    }());
  }
  (std::make_index_sequence<Sp::rows>{});
}

}  // namespace detail

template <std::size_t S, std::size_t R, class Sp>
constexpr auto kde_weight<S, R, Sp>::time_derivative() {
  return -detail::weighted_rows<Sp, S>([](auto a) {
    return detail::rate_row<Sp, decltype(a)::value>(
        [](auto b) { return detail::full_weight<Sp, decltype(b)::value, R>(); });
  });
}
template <std::size_t S, class Sp>
constexpr auto kde_offset<S, Sp>::time_derivative() {
  return -detail::weighted_rows<Sp, S>([](auto a) {
    constexpr std::size_t A = decltype(a)::value;
    return detail::rate_row<Sp, A>([](auto b) { return detail::offset<Sp, decltype(b)::value>(); }) +
           detail::ddt(detail::at_rest(std::get<A - 1>(Sp::definitions)));
  });
}

}  // namespace kane
#pragma GCC diagnostic pop
