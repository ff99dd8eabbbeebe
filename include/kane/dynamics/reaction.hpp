// Noncontributing forces brought into evidence by auxiliary generalized speeds (Kane and Levinson):
// the force and the moment about P that the rest of a system exerts on a part of it.
//
//   using pin = kane::cut<J, B, Q>;                   // the part: the body fixed in B, the particle at Q
//   const auto r = kane::reaction<System, pin>(ev);   // r.force, r.moment (about J), r.status
//
// Six auxiliary speeds move the part alone: three translations along the root's axes and three
// rotations about P. Their partial velocities at a point Q of the part are e_i and e_i x r^PQ, their
// partial angular velocities 0 and e_i. Kane's equations along them, F~_i + F~*_i = 0 with the
// unknown load in F~, give in the root's components
//   force  = sum m (a - g) - sum F
//   moment = sum (r^PG x m (a - g) + I alpha + w x I w) - sum (r^PQ x F + T)
// over the part's masses and the loads on it: forces at points it carries (a particle's point, a
// point fixed in one of its bodies) and torques on its bodies' frames. The accelerations are the
// evaluator's: update it with the u' of the motion (forward dynamics, the reduced equations).
#pragma once

#include <type_traits>

#include <Eigen/Geometry>

#include "kane/detail/frame_check.hpp"
#include "kane/detail/list.hpp"
#include "kane/dynamics/bodies.hpp"
#include "kane/dynamics/detail/sums/sums.hpp"
#include "kane/dynamics/detail/sums/terms.hpp"
#include "kane/dynamics/detail/system_rules.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/frames/vec.hpp"
#include "kane/kinematics/point.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

// A part of a system cut free at the point P: the rigid bodies fixed in the frames and the
// particles at the points among Items.
template <Point P, class... Items>
struct cut {
  static_assert(
      ((Frame<Items> || Point<Items>)&&...),
      "kane: cut<P, Items...> takes the frames of the part's bodies and the points of its particles");
  // P, the point the moment is about
  using point = P;
  // the frames and points of the part
  using items = detail::list<Items...>;
};

// The load that the rest of a system exerts on a part, in the root R's components.
template <class R, class S>
struct reaction_load {
  // the force on the part
  vec<R, S> force;
  // its moment about the cut's point
  vec<R, S> moment;
  // the evaluator's status, or not_finite
  solve_status status;
};

namespace detail {
// X is a mass of the part: a body fixed in one of its frames, a particle at one of its points.
template <class X, class... Items>
constexpr bool in_part(list<Items...>) {
  if constexpr (is_body<X>)
    return (std::is_same_v<typename X::frame, Items> || ...);
  else if constexpr (is_particle<X>)
    return (std::is_same_v<typename X::point, Items> || ...);
  else
    return false;
}
// The item M is a body fixed in the frame F.
template <class F, class M>
constexpr bool body_in() {
  if constexpr (is_body<M>)
    return std::is_same_v<F, typename M::frame>;
  else
    return false;
}
// The load X acts on the part's masses Ms...: a force at a point they carry, a torque on a body's frame.
template <class X, class... Ms>
constexpr bool acts_on(list<Ms...>) {
  if constexpr (is_force<X>)
    return (carries<typename X::point>(static_cast<Ms*>(nullptr)) || ...);
  else if constexpr (is_torque<X>)
    return (body_in<typename X::frame, Ms>() || ...);
  else
    return false;
}
template <class Items, class... X>
constexpr auto masses_of(list<X...>) {
  return typename concat<std::conditional_t<in_part<X>(Items{}), list<X>, list<>>...>::type{};
}
}  // namespace detail

// The force and moment about Cut's point that the rest of Sys exerts on Cut's part, at ev's state
// (its q, u and u'; ev at the acceleration level).
template <System Sys, class Cut, Evaluator Ev>
reaction_load<typename Ev::root, typename Ev::scalar> reaction(const Ev& ev) {
  using R = typename Ev::root;
  using S = typename Ev::scalar;
  using P = typename Cut::point;
  using V = Eigen::Matrix<S, 3, 1>;
  using masses = decltype(detail::masses_of<typename Cut::items>(typename Sys::items{}));
  static_assert(
      !std::is_same_v<masses, detail::list<>>,
      "kane: cut<P, Items...> names no body (by its frame) or particle (by its point) of the system");
  const V g = detail::in_root<R>(detail::gravity_of(typename Sys::items{}), ev);
  V force = V::Zero(), moment = V::Zero();
  // m (a - g) at the point Q, and its moment about P
  const auto mass_at = [&]<class Q>(std::type_identity<Q>, const auto& m) {
    const V f = S(detail::eval_scalar(m, ev)) * (detail::in_root<R>(acceleration<R, Q>(), ev) - g);
    force += f;
    moment += detail::in_root<R>(position<P, Q>(), ev).cross(f);
  };
  [&]<class... X>(detail::list<X...>) {
    (([&] {
       if constexpr (detail::in_part<X>(typename Cut::items{}) && detail::is_particle<X>) {
         mass_at(std::type_identity<typename X::point>{}, X::mass);
       } else if constexpr (detail::in_part<X>(typename Cut::items{}) && detail::is_body<X>) {
         using B = typename X::frame;
         mass_at(std::type_identity<typename X::centre>{}, X::mass);
         const Eigen::Matrix<S, 3, 3> i = detail::inertia_in_root<typename X::inertia_type>(ev);
         const V w = detail::in_root<R>(angular_velocity<R, B>(), ev);
         moment += i * detail::in_root<R>(angular_acceleration<R, B>(), ev) + w.cross(i * w);
       } else if constexpr (detail::acts_on<X>(masses{}) && detail::is_force<X>) {
         const V f = detail::in_root<R>(X::vector, ev);
         force -= f;
         moment -= detail::in_root<R>(position<P, typename X::point>(), ev).cross(f);
       } else if constexpr (detail::acts_on<X>(masses{}) && detail::is_torque<X>) {
         moment -= detail::in_root<R>(X::vector, ev);
       }
     }()),
     ...);
  }(typename Sys::items{});
  solve_status status = ev.status();
  if (status == solve_status::ok && !(detail::all_finite_matrix(force) && detail::all_finite_matrix(moment)))
    status = solve_status::not_finite;
  const auto spoil = detail::nan_unless<S>(status == solve_status::ok);
  spoil(force), spoil(moment);
  return {vec<R, S>(force(0), force(1), force(2)), vec<R, S>(moment(0), moment(1), moment(2)), status};
}

}  // namespace kane
#pragma GCC diagnostic pop
