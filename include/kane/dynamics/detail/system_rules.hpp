// The rules a system keeps with an evaluator's speeds, checked once where an entry point
// (equations, inverse dynamics, momenta) takes it: forces at points of a mass, frames turning
// at free speeds, and each item's own rules.
#pragma once

#include <concepts>

#include "kane/detail/frame_check.hpp"
#include "kane/detail/list.hpp"
#include "kane/detail/tree.hpp"
#include "kane/dynamics/bodies.hpp"
#include "kane/kinematics/edges.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// The frames an item turns with (and their ancestors).
template <class X>
struct turning_frames {
  using type = list<>;
};
template <class X>
requires is_body<X>
struct turning_frames<X> {
  using type = typename closure<typename X::frame, typename X::inertia_type::frame>::type;
};
template <class X>
requires is_torque<X>
struct turning_frames<X> {
  using type = typename closure<typename X::frame>::type;
};
// The point of a force (void for other items), named by the rule a force keeps.
template <class X>
struct point_of {
  using type = void;
};
template <class X>
requires is_force<X>
struct point_of<X> {
  using type = typename X::point;
};
// Every force at a point of a mass, every frame of a body or torque turning at speeds of Sp.
template <class Sys, class Sp, class... X>
constexpr bool system_checked(list<X...>) {
  return ((check<force_applies<X>(typename Sys::items{}),
                 error::force_at_a_point_of_no_mass_apply_it_at_a_particle_or_a_point_fixed_in_a_body<
                     typename point_of<X>::type>> &&
           free_speeds_checked<Sp>(typename turning_frames<X>::type{})) &&
          ...);
}
template <class Sp, class... F>
constexpr bool turn_freely(list<F...>) {
  return (turns_freely<Sp, F>() && ...);
}
// The item keeps its own rules (each broken one was reported where the item was named).
template <class X>
constexpr bool item_well_formed() {
  if constexpr (requires { X::well_formed; })
    return X::well_formed;
  else
    return std::derived_from<X, load_tag>;
}
template <class Sys, class Sp, class... X>
constexpr bool system_holds(list<X...>) {
  return ((item_well_formed<X>() && force_applies<X>(typename Sys::items{}) &&
           turn_freely<Sp>(typename turning_frames<X>::type{})) &&
          ...);
}
// Sys keeps every rule with the speeds Sp; the system's own are reported here. An entry point
// computes only an admitted system, so a broken rule's error is not followed by those of the code
// that would use it.
template <class Sys, class Sp>
constexpr bool admitted() {
  if constexpr (!requires { typename Sys::items; })
    return false;
  else if constexpr (!system_holds<Sys, Sp>(typename Sys::items{})) {
    static_assert(system_checked<Sys, Sp>(typename Sys::items{}));
    return false;
  } else
    return true;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
