// W and X of a speed set's kinematic differential equations as nodes (q' = W u + X): the numbers
// kde_weight<S, R, Sp> and kde_offset<S, Sp> the evaluator solves for, type-level zeros and ones
// where Y's structure decides them, their time derivatives (W' = -W Y' W, X' = -W (Y' X + Z')),
// and x at rest (q', u replaced by 0) for the remainders v_t.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "kane/detail/structure.hpp"
#include "kane/expressions/derived_products.hpp"
#include "kane/expressions/rebuild.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/kinematics/angular_velocity.hpp"
#include "kane/kinematics/derivative.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/scalars/expr.hpp"
#include "kane/speeds/component_speeds.hpp"
#include "kane/speeds/generalized_speeds.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

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
constexpr auto at_rest(X x);
struct rest_rule {
  template <class X>
  static constexpr bool handles =
      coordinate_info<X>::value || speed_info<X>::value || is_v<X, omega> || is_v<X, angular_velocity_of> ||
      is_v<X, alpha> || is_v<X, angular_acceleration_of>;
  template <class X>
  static constexpr auto apply(X x) {
    if constexpr (coordinate_info<X>::value) {
      if constexpr (X::order == 0)
        return x;
      else
        return zero_t{};
    } else if constexpr (speed_info<X>::value)
      return zero_t{};
    else if constexpr (is_v<X, omega>)
      return explicit_time_omega<typename X::frame>();  // linear in q', plus the prescribed rates
    else if constexpr (is_v<X, angular_velocity_of>)
      return at_rest(expand(x));
    else
      static_assert(!sizeof(X), "kane: an angular acceleration is not linear in the speeds");
  }
  template <class X>
  static constexpr auto other(X x) {
    static_assert(
        (ScalarExpr<X> && (LeafConstant<X> || std::is_same_v<X, time_variable> || kde_info<X>::value)) ||
            is_unit<X>::value || is_zero_vector_v<X>,
        "kane: at_rest of an unknown node");
    return x;
  }
};
template <class X>
constexpr auto at_rest(X x) {
  return rebuild<rest_rule>(x);
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
    const std::array<bool, n * n> no_rates{(leaves_of<std::remove_cv_t<y_type<I / d, I % d>>>.rates == 0)...};
    for (const bool none : no_rates)
      if (!none) return false;
    return true;
  }
  (std::make_index_sequence<n * n>{});
  static_assert(linear,
                "kane: a generalized speed is linear in q': u_r = sum_s Y_rs(q, t) q_s' + Z_r(q, t), "
                "with no q' in Y_rs; write u_r without products or functions of the rates");
  static constexpr pattern<n, n> m = []<std::size_t... I>(std::index_sequence<I...>) {
    const std::array<entry, n * n> e{entry_of<y_type<I / d, I % d>>()...};
    pattern<n, n> p{};
    for (std::size_t i = 0; i < n * n; ++i) p[i / d][i % d] = e[i];
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
