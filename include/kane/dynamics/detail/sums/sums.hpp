// Kane's sums (mass_matrix_and_forcing.hpp for the entry points): M and f over every item's partial
// velocities, in the root frame N of the evaluator's tree:
//   M_rs = sum m v_r . v_s + w_r . I . w_s
//   f_r  = F_r - sum m v_r . a_0 + w_r . (I . alpha_0 + w x I . w)
//   F_r  = sum v_r . R + w_r . T   (the generalized active forces)
// over particles and rigid bodies (v of the particle or mass centre, w of the
// body), with a_0 = a - sum_s v_s u_s' and alpha_0 = alpha - sum_s w_s u_s':
// a and alpha are linear in u' with the partial velocities as coefficients, so
// one evaluator pass at level::acceleration, at any u', gives M and f. Any
// system; O(n^3) work (crba.hpp and rnea.hpp regroup them where the tree allows).
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "kane/detail/choices.hpp"
#include "kane/detail/inline.hpp"
#include "kane/detail/invert.hpp"
#include "kane/detail/lane_traits.hpp"
#include "kane/detail/wide_stores.hpp"
#include "kane/dynamics/bodies.hpp"
#include "kane/dynamics/detail/sums/columns.hpp"
#include "kane/dynamics/detail/sums/known_mass_matrix.hpp"
#include "kane/dynamics/detail/sums/rest_bias.hpp"
#include "kane/dynamics/detail/sums/terms.hpp"
#include "kane/dynamics/detail/system_rules.hpp"
#include "kane/dynamics/results.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/evaluate_in.hpp"
#include "kane/evaluation/memo.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/evaluation/tables.hpp"
#include "kane/frames/vec.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
// f alone, where M is known at compile time (known_mass_matrix.hpp)
template <class S, std::size_t N>
struct forcing_only {
  Eigen::Matrix<S, int(N), 1> f;
  status_of<S> status;
};
template <class R, class X, class Ev>
Eigen::Matrix<typename Ev::scalar, 3, 1> in_root(const X& x, const Ev& ev) {
  return express_in<R>(x, ev).eigen();
}
template <class A, class X, class Ev>
Eigen::Matrix<typename Ev::scalar, 3, 1> in_frame_of(const X& x, const Ev& ev) {  // components in A
  const auto r = eval_in<A>(x, ev);
  return {r.x, r.y, r.z};
}
// The columns of M that the partial velocities of X reach, as a type. g++ 12: it merged
// instantiations of one function template that differed only in an array argument.
// kinds: the columns' patterns in A's components (columns.hpp).
template <class Cols, class Sp, class X, class A = void>
struct reached_columns {
  static constexpr auto value = Cols::template nonzero<nonzero_columns<Sp, X>()>();
  static constexpr auto kinds = Cols::template kinds<nonzero_columns<Sp, X, A>()>();
};
// r N + c for r <= c in the columns Nz::value
template <class Nz, std::size_t N>
constexpr std::array<bool, N * N> upper_entries() {
  std::array<bool, N * N> at{};
  for (std::size_t r = 0; r < N; ++r)
    for (std::size_t c = r; c < N; ++c) at[r * N + c] = Nz::value[r] && Nz::value[c];
  return at;
}
// The upper triangle of M += a^T b (symmetric: b = W a, W symmetric) over the columns Nz::value,
// without the components that the patterns Nz::kinds of a (and of b, Scaled: b = m a) know to be zero.
template <class Nz, bool Scaled, class S, int N>
KANE_ALWAYS_INLINE void add_upper(Eigen::Matrix<S, N, N>& m, const Eigen::Matrix<S, 3, N>& a,
                                  const Eigen::Matrix<S, 3, N>& b) {
  static_for_where<upper_entries<Nz, std::size_t(N)>()>([&](auto rc) {
    constexpr std::size_t r = rc / std::size_t(N), c = rc % std::size_t(N);
    constexpr pattern3 k = Scaled ? product_zeros(Nz::kinds[r], Nz::kinds[c]) : Nz::kinds[r];
    if constexpr (!all_zero(k))
      m(Eigen::Index(r), Eigen::Index(c)) += dot_where<k>(a.col(Eigen::Index(r)), b.col(Eigen::Index(c)));
  });
}
template <class Ev>
auto speed_rates(const Ev& ev) {  // u' of the evaluator's state
  using S = typename Ev::scalar;
  constexpr std::size_t n = Ev::nu;
  Eigen::Matrix<S, int(n), 1> ud;
  for (std::size_t r = 0; r < n; ++r)
    ud(Eigen::Index(r)) = std::is_void_v<typename Ev::speed_set> ? ev.state().qdd[r] : ev.state().ud[r];
  return ud;
}
// The columns the equations are written for. Every speed: M and f.
template <std::size_t N>
struct all_speeds {
  static constexpr std::size_t n = N;
  template <auto Nz>
  static constexpr std::array<bool, n> nonzero() {
    std::array<bool, n> out{};
    for (std::size_t k = 0; k < n; ++k) out[k] = !all_zero(Nz[k]);
    return out;
  }
  template <auto Nz>
  static constexpr std::array<pattern3, n> kinds() {  // of the columns (columns.hpp)
    return Nz;
  }
  template <auto Nz, class V>
  KANE_ALWAYS_INLINE const V& columns(const V& v) const {
    return v;
  }
  template <auto Nz, class A, class V>
  KANE_ALWAYS_INLINE void add_bias(A&, const V&) const {}
};
// The frame of an item's sums: the first of L (the root) while common subexpressions are
// recalled (their slots hold root components), else the cheapest.
template <class Cols, class L, bool Recalling>
struct frame_of_columns;
template <class Cols, class R, class... F>
struct frame_of_columns<Cols, list<R, F...>, false> : cheapest_frame<Cols, R, F...> {};
template <class Cols, class R, class... F>
struct frame_of_columns<Cols, list<R, F...>, true> {
  using type = R;
};
// The sums of M and f over the items of Sys, M_rs and f_r being invariant: the mass terms in the
// root (a body's in its own frame where its partial velocities are known constants there alone), a
// body's rotational term in the root, its inertia's frame or the frame above that the inertia is
// symmetric about the turn to (symmetric_lift), whichever holds fewer rotations in the partial
// angular velocities (foreign_units). parts::forcing: M is known (known_mass_matrix.hpp).
template <class Sys, rates Rates, parts Parts, class Out, class Ev, class Cols, class Ud>
inline void add_items(Out& out, const Ev& ev, const Cols& cols, const Ud& ud) {
  using S = typename Ev::scalar;
  using R = typename Ev::root;
  using Sp = detail::speeds_of<Ev>;
  constexpr std::size_t n = Cols::n;
  // the partial velocities of x along the columns, and x's bias (a0 or alpha0), in A
  const auto along = [&]<class A>(std::type_identity<A>, const auto& x, const auto& x_dot,
                                  Eigen::Matrix<S, 3, 1>& bias) {
    constexpr auto nz = detail::nonzero_columns<Sp, std::remove_cvref_t<decltype(x)>, A>();
    auto v = linear_parts_in<A, linear_part::table>(x, ev);
    if constexpr (has(Parts, parts::forcing)) {
      if constexpr (Rates == rates::zero)
        bias = detail::in_frame_of<A>(rest_bias<typename Ev::speed_set>(x_dot), ev);
      else
        bias = detail::in_frame_of<A>(x_dot, ev);
      if constexpr (Rates == rates::of_state) bias -= product_in_blocks(v, ud);
      cols.template add_bias<nz>(bias, v);
    }
    if constexpr (std::is_same_v<decltype(v), Eigen::Matrix<S, 3, int(n)>> &&
                  std::is_lvalue_reference_v<decltype(cols.template columns<nz>(v))>)
      return v;  // the table itself: no copy (a copy of lanes is a call of memmove)
    else
      return Eigen::Matrix<S, 3, int(n)>(cols.template columns<nz>(v));
  };
  // the mass terms in A
  const auto mass = [&]<class A>(std::type_identity<A> in, const auto& point_velocity,
                                 const auto& point_acceleration, const auto& m) {
    Eigen::Matrix<S, 3, 1> a0;
    const auto v = along(in, point_velocity, point_acceleration, a0);
    using X = std::remove_cvref_t<decltype(point_velocity)>;
    const S mass = detail::eval_scalar(m, ev);
    if constexpr (has(Parts, parts::mass_matrix)) {
      const Eigen::Matrix<S, 3, int(n)> mv = mass * v;
      detail::add_upper<reached_columns<Cols, Sp, X, A>, true>(out.M, v, mv);
    }
    if constexpr (has(Parts, parts::forcing)) {
      const Eigen::Matrix<S, 3, 1> g = in_frame_of<A>(gravity_of(typename Sys::items{}), ev);
      Eigen::Matrix<S, 3, 1> load;  // m (g - a0) number by number: no wide load of a0 stored so
      store_in_blocks<3>(load.data(), [&](auto i) KANE_ALWAYS_INLINE_LAMBDA {
        return mass * (g(Eigen::Index(i)) - a0(Eigen::Index(i)));
      });
      detail::add_transposed<Cols::template kinds<detail::nonzero_columns<Sp, X, A>()>()>(out.f, v, load);
    }
  };
  [&]<class... X>(detail::list<X...>) {
    (
        [&] {
          if constexpr (detail::is_particle<X>) {
            using P = typename X::point;
            mass(std::type_identity<R>{}, velocity<R, P>(), acceleration<R, P>(), X::mass);
          } else if constexpr (detail::is_body<X>) {
            using B = typename X::frame;
            using P = typename X::centre;
            using I = typename X::inertia_type;
            // the mass terms in B where its partial velocities are constants there alone
            constexpr bool in_body = !is_recalling<Ev> && !columns_known_in<Sp, R>(velocity<R, P>()).known &&
                                     columns_known_in<Sp, B>(velocity<R, P>()).known;
            mass(std::type_identity<std::conditional_t<in_body, B, R>>{}, velocity<R, P>(),
                 acceleration<R, P>(), X::mass);
            using IL = typename symmetric_lift<I>::type;  // I's components hold in IL's frame too
            using A = typename frame_of_columns<columns_t<Sp, decltype(angular_velocity<R, B>())>,
                                                list<R, typename I::frame, typename IL::frame>,
                                                is_recalling<Ev>>::type;
            Eigen::Matrix<S, 3, 1> alpha0;
            const auto w = along(std::type_identity<A>{}, angular_velocity<R, B>(),
                                 angular_acceleration<R, B>(), alpha0);
            using Om = decltype(angular_velocity<R, B>());
            const Eigen::Matrix<S, 3, 3> i = [&] {
              if constexpr (std::is_same_v<A, typename I::frame>)
                return detail::inertia_in_own<I>(ev);
              else if constexpr (std::is_same_v<A, typename IL::frame>)
                return detail::inertia_in_own<IL>(ev);
              else
                return detail::inertia_in_root<I>(ev);
            }();
            constexpr auto zeros = detail::inertia_zeros_in<A, I, IL>();
            if constexpr (has(Parts, parts::mass_matrix)) {
              const Eigen::Matrix<S, 3, int(n)> iw = product_in_blocks<zeros>(i, w);
              detail::add_upper<reached_columns<Cols, Sp, Om, A>, false>(out.M, w, iw);
            }
            if constexpr (has(Parts, parts::forcing)) {
              // -(I alpha0 + w x I w) number by number: no wide load of what was stored so
              const auto as_v3 = [](const Eigen::Matrix<S, 3, 1>& x) { return v3<S>{x(0), x(1), x(2)}; };
              const v3<S> omega = eval_in<A>(angular_velocity<R, B>(), ev);
              const v3<S> t = as_v3(product_in_blocks<zeros>(i, alpha0)) +
                              cross3(omega, as_v3(product_in_blocks<zeros>(
                                                i, Eigen::Matrix<S, 3, 1>(omega.x, omega.y, omega.z))));
              detail::add_transposed<Cols::template kinds<detail::nonzero_columns<Sp, Om, A>()>()>(
                  out.f, w, Eigen::Matrix<S, 3, 1>(-t.x, -t.y, -t.z));
            }
          } else if constexpr (has(Parts, parts::forcing) && detail::is_force<X>) {
            const auto x = velocity<R, typename X::point>();
            const auto v = linear_parts_in<R, linear_part::table>(x, ev);
            constexpr auto nz = detail::nonzero_columns<Sp, std::remove_cvref_t<decltype(x)>>();
            detail::add_transposed<Cols::template kinds<nz>()>(
                out.f, Eigen::Matrix<S, 3, int(n)>(cols.template columns<nz>(v)),
                detail::in_root<R>(X::vector, ev));
          } else if constexpr (has(Parts, parts::forcing) && detail::is_torque<X>) {
            const auto x = angular_velocity<R, typename X::frame>();
            const auto w = linear_parts_in<R, linear_part::table>(x, ev);
            constexpr auto nz = detail::nonzero_columns<Sp, std::remove_cvref_t<decltype(x)>>();
            detail::add_transposed<Cols::template kinds<nz>()>(
                out.f, Eigen::Matrix<S, 3, int(n)>(cols.template columns<nz>(w)),
                detail::in_root<R>(X::vector, ev));
          }
        }(),
        ...);
  }(typename Sys::items{});
}
// M and f along the columns Cols. rates::at_rest: the bias accelerations are the evaluator's
// (a - v u' would multiply by zeros); at a state of any u', f is -tau. rates::zero: every u' of the
// caller's state is 0 (motion.hpp), and the biases are expressions at u' = 0 (rest_bias.hpp).
// parts::mass_matrix: M alone (f stays 0: no velocity, acceleration or load is read).
// parts::forcing: f alone (forcing_only). Where M is known or Check is checking::at_end, f is not
// checked: the caller checks u' = M^-1 f (at_end: M still is).
template <class Sys, rates Rates, parts Parts = parts::both, checking Check = checking::each, class Ev,
          class Cols>
auto equations_along(const Ev& ev, const Cols& cols) {
  using S = typename Ev::scalar;
  using R = typename Ev::root;
  using Sp = detail::speeds_of<Ev>;
  constexpr std::size_t n = Cols::n;
  static_assert(detail::system_checked<Sys, Sp>(typename Sys::items{}));
  constexpr bool known = [] {
    if constexpr (std::is_same_v<Cols, all_speeds<n>>)
      return known_mass_matrix<Sys, R, Sp>.known;
    else
      return false;
  }();
  constexpr bool with_m = has(Parts, parts::mass_matrix);
  using result = std::conditional_t<with_m, equations_of_motion<S, n>, forcing_only<S, n>>;
  result out = [&] {
    if constexpr (!with_m)
      return result{Eigen::Matrix<S, int(n), 1>::Zero(), ev.status()};
    else if constexpr (known)  // symmetric: rows or columns alike
      return result{
          Eigen::Map<const Eigen::Matrix<double, int(n), int(n)>>(known_mass_matrix<Sys, R, Sp>.m.data())
              .template cast<S>(),
          Eigen::Matrix<S, int(n), 1>::Zero(), ev.status()};
    else
      return result{Eigen::Matrix<S, int(n), int(n)>::Zero(), Eigen::Matrix<S, int(n), 1>::Zero(),
                    ev.status()};
  }();
  [[maybe_unused]] const auto ud = detail::speed_rates(ev);
  if constexpr (!known || Parts != parts::mass_matrix)
    detail::with_common_subexpressions(system_terms<R, Sp>(typename Sys::items{}), ev, [&](const auto& e) {
      add_items<Sys, Rates, known ? parts::forcing : Parts>(out, e, cols, ud);
    });
  if constexpr (!known && with_m) out.M.template triangularView<Eigen::StrictlyLower>() = out.M.transpose();
  if constexpr ((known && !with_m) || (Check == checking::at_end && (known || !with_m))) return out;
  const auto finite = [&] {
    if constexpr (Check == checking::at_end)  // a NaN or inf of f reaches M^-1 f; one of M may not
      return detail::finite_masses(out.M);
    else if constexpr (known || !with_m)
      return detail::all_finite_numbers(out.f);
    else
      return detail::finite_masses(out.M) && detail::all_finite_numbers(out.f);
  }();
  fail_unless(out.status, finite, solve_status::not_finite);
  return out;
}
}  // namespace detail
}  // namespace kane
#pragma GCC diagnostic pop
