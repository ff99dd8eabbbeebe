// Momenta and energies of a system, measured in the evaluator's root frame R:
//
//   kane::linear_momentum<Sys>(ev)       ^R p = sum m ^R v^P
//   kane::angular_momentum<Sys, O>(ev)   ^R H^O = sum r^OP x m ^R v^P + I . ^R w^B
//                                        (O = kane::mass_centre, the default: the system's)
//   kane::kinetic_energy<Sys>(ev)        T = sum m v . v / 2 + w . I . w / 2
//   kane::potential_energy<Sys, O>(ev)   V = -sum m g . r^OP over the gravity loads, zero at O
//                                        (default: the origin that locates the first mass),
//                                        + k s^2 / 2 of each spring (springs.hpp)
//
// P runs over the particles and mass centres. Positions need level::pose, the rest
// level::velocity; the vectors come as vec<R>. A mass centre known by its velocity alone
// (point_by_velocity) has p, T and H about points located from it, but no V.
#pragma once

#include <type_traits>

#include <Eigen/Core>

#include "kane/dynamics/bodies.hpp"
#include "kane/dynamics/detail/sums/sums.hpp"
#include "kane/dynamics/detail/sums/terms.hpp"
#include "kane/dynamics/detail/system_rules.hpp"
#include "kane/dynamics/springs.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/frames/vec.hpp"
#include "kane/kinematics/point.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// The mass centre of the system, as the point of angular_momentum.
struct mass_centre {};

namespace detail {
template <class P, class From = typename P::from>
struct chain_origin {
  using type = typename chain_origin<From>::type;
};
template <class P>
struct chain_origin<P, void> {
  using type = P;
};

template <class X>
inline constexpr bool has_mass = is_particle<X> || is_body<X>;
template <class... X>
constexpr bool has_gravity(list<X...>) {
  return (is_gravity<X> || ...);
}
template <class L>
struct first_mass {
  using type = void;
};
template <class X, class... Xs>
struct first_mass<list<X, Xs...>> {
  using type = std::conditional_t<has_mass<X>, X, typename first_mass<list<Xs...>>::type>;
};
template <class Sys>
struct reference_point {
  using X = typename first_mass<typename Sys::items>::type;
  static_assert(!std::is_void_v<X>, "kane: a system without particles or bodies has no momenta or energies");
  using type = typename chain_origin<typename point_of_mass<X>::type>::type;
};

// f(X) for every item X with mass.
template <class Sys, class Ev, class F>
void for_each_mass_item(F&& f) {
  if constexpr (admitted<Sys, speeds_of<Ev>>())
    [&]<class... X>(list<X...>) {
      (
          [&] {
            if constexpr (has_mass<X>) f(std::type_identity<X>{});
          }(),
          ...);
    }(typename Sys::items{});
}
// f(X, r^{Ref,P} in R) for every item with mass; Ref = the reference point of Sys.
template <class Sys, class Ev, class F>
void for_each_mass(const Ev& ev, F&& f) {
  for_each_mass_item<Sys, Ev>([&]<class X>(std::type_identity<X> x) {
    using Ref = typename reference_point<Sys>::type;
    f(x, in_root<typename Ev::root>(position<Ref, typename point_of_mass<X>::type>(), ev));
  });
}
}  // namespace detail

// ^R p = sum m ^R v^P, as vec<R>
template <System Sys, Evaluator Ev>
vec<typename Ev::root, typename Ev::scalar> linear_momentum(const Ev& ev) {
  using S = typename Ev::scalar;
  using R = typename Ev::root;
  Eigen::Matrix<S, 3, 1> p = Eigen::Matrix<S, 3, 1>::Zero();
  detail::for_each_mass_item<Sys, Ev>([&]<class X>(std::type_identity<X>) {
    p += detail::eval_scalar(X::mass, ev) *
         detail::in_root<R>(velocity<R, typename detail::point_of_mass<X>::type>(), ev);
  });
  return vec<R, S>(p);
}

// ^R H^O = sum r^OP x m ^R v^P + I . ^R w^B, as vec<R>; O the system's mass centre by default
template <System Sys, class O = mass_centre, Evaluator Ev>
requires(std::is_same_v<O, mass_centre> ||
         Point<O>) vec<typename Ev::root, typename Ev::scalar> angular_momentum(const Ev& ev) {
  using S = typename Ev::scalar;
  using R = typename Ev::root;
  using V = Eigen::Matrix<S, 3, 1>;
  V o = V::Zero();  // r^{Ref,O}
  if constexpr (std::is_same_v<O, mass_centre>) {
    S total = S(0);
    detail::for_each_mass<Sys>(ev, [&]<class X>(std::type_identity<X>, const V& r) {
      const S m = detail::eval_scalar(X::mass, ev);
      o += m * r;
      total += m;
    });
    o /= total;
  } else {
    o = detail::in_root<R>(position<typename detail::reference_point<Sys>::type, O>(), ev);
  }
  V h = V::Zero();
  detail::for_each_mass<Sys>(ev, [&]<class X>(std::type_identity<X>, const V& r) {
    using P = typename detail::point_of_mass<X>::type;
    h += (r - o).cross(detail::eval_scalar(X::mass, ev) * detail::in_root<R>(velocity<R, P>(), ev));
    if constexpr (detail::is_body<X>)
      h += detail::inertia_in_root<typename X::inertia_type>(ev) *
           detail::in_root<R>(angular_velocity<R, typename X::frame>(), ev);
  });
  return vec<R, S>(h);
}

// T = sum m v . v / 2 + w . I . w / 2
template <System Sys, Evaluator Ev>
typename Ev::scalar kinetic_energy(const Ev& ev) {
  using S = typename Ev::scalar;
  using R = typename Ev::root;
  S energy = S(0);
  detail::for_each_mass_item<Sys, Ev>([&]<class X>(std::type_identity<X>) {
    const Eigen::Matrix<S, 3, 1> v =
        detail::in_root<R>(velocity<R, typename detail::point_of_mass<X>::type>(), ev);
    energy += detail::eval_scalar(X::mass, ev) * v.squaredNorm() / 2;
    if constexpr (detail::is_body<X>) {
      const Eigen::Matrix<S, 3, 1> w = detail::in_root<R>(angular_velocity<R, typename X::frame>(), ev);
      energy += w.dot(detail::inertia_in_root<typename X::inertia_type>(ev) * w) / 2;
    }
  });
  return energy;
}

// V = -sum m g . r^OP + sum k s^2 / 2, zero at O
template <System Sys, class O = void, Evaluator Ev>
requires(std::is_void_v<O> || Point<O>) typename Ev::scalar potential_energy(const Ev& ev) {
  using S = typename Ev::scalar;
  using R = typename Ev::root;
  using V = Eigen::Matrix<S, 3, 1>;
  S energy = S(0);
  const V g = detail::in_root<R>(detail::gravity_of(typename Sys::items{}), ev);
  [&]<class... X>(detail::list<X...>) {
    (
        [&] {
          if constexpr (detail::is_spring_energy<X>) energy += detail::eval_scalar(X::energy, ev);
        }(),
        ...);
  }(typename Sys::items{});
  if constexpr (detail::has_gravity(typename Sys::items{}) || !std::is_void_v<O>) {
    using Ref = typename detail::reference_point<Sys>::type;
    static_assert(
        detail::check<
            !detail::by_velocity<Ref>,
            error::potential_energy_needs_positions_from_an_origin_not_from_a_point_known_by_its_velocity<
                Ref>>);
    if constexpr (!detail::by_velocity<Ref>) {
      V o = V::Zero();
      if constexpr (!std::is_void_v<O>) o = detail::in_root<R>(position<Ref, O>(), ev);
      detail::for_each_mass<Sys>(ev, [&]<class X>(std::type_identity<X>, const V& r) {
        energy -= detail::eval_scalar(X::mass, ev) * g.dot(r - o);
      });
    }
  }
  return energy;
}

}  // namespace kane
#pragma GCC diagnostic pop
