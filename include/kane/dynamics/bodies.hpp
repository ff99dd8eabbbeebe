// What has mass, and what acts on it (the system of Kane's dynamical equations):
//
//   kane::particle<P, m>                          a mass m at the point P
//   kane::inertia<F, Q, I11, I22, I33, I12, I23, I31>   a dyadic by its components in F, about Q
//   kane::parallel_axis<I, G, m>                  I moved to the mass centre G of mass m
//   kane::rigid_body<B, Bo, m, I>                 frame B, mass centre Bo, mass m, inertia I about Bo
//   kane::force<P, R>, torque<B, T>, gravity<g>   the loads (loads.hpp)
//   kane::system<items...>                       items, or systems whose items it adds
//
// Masses and components are scalar expressions (a parameter, kane::literal(2.0), kane::constant<1, 2>);
// loads are vector expressions of q, u, t and parameters. The inertia's frame is fixed in the body (or B
// turns in it about an axis of symmetry of I: a wheel, a disc) and its point is the mass centre
// (kane::parallel_axis moves a dyadic there); a force acts at a particle or at a point fixed in a body,
// where its partial velocities are those of a mass.
#pragma once

#include <concepts>
#include <tuple>
#include <type_traits>

#include "kane/detail/frame_check.hpp"
#include "kane/detail/tree.hpp"
#include "kane/dynamics/loads.hpp"
#include "kane/expressions/vector.hpp"
#include "kane/kinematics/derivative.hpp"
#include "kane/kinematics/edges.hpp"
#include "kane/kinematics/point.hpp"
#include "kane/scalars/expr.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
struct particle_tag {};
struct body_tag {};
struct inertia_tag {};

// The edges between A and B turn by constant angles: B is fixed in A.
template <class F>
constexpr bool constant_edge() {
  if constexpr (spin_edge<F> || matrix_edge<F>)
    return false;
  else
    return std::is_same_v<std::remove_cv_t<decltype(ddt(F::step::angle))>, zero_t>;
}
template <class... F>
constexpr bool constant_edges(list<F...>) {
  return (constant_edge<F>() && ...);
}
// B turns relative to its parent F (by an angle or a spin) about a coordinate axis k of both, and
// I (in F) is symmetric about k: equal moments about the other two axes (the same expression), no
// products. I has the same components in B (a wheel, a disc).
template <class B, class I>
constexpr bool spins_symmetric() {
  using F = typename I::frame;
  if constexpr (!requires { typename B::step::axis; } || !std::is_same_v<typename B::tree_parent, F>)
    return false;
  else {
    constexpr int k = unit_axis<typename B::step::axis>::principal;
    using c = std::remove_cvref_t<decltype(I::components)>;
    using i11 = std::tuple_element_t<0, c>;
    using i22 = std::tuple_element_t<1, c>;
    using i33 = std::tuple_element_t<2, c>;
    constexpr bool products = is_zero_v<std::tuple_element_t<3, c>> &&
                              is_zero_v<std::tuple_element_t<4, c>> && is_zero_v<std::tuple_element_t<5, c>>;
    return products && ((k == 0 && std::is_same_v<i22, i33>) || (k == 1 && std::is_same_v<i11, i33>) ||
                        (k == 2 && std::is_same_v<i11, i22>));
  }
}
template <class A, class B>
constexpr bool fixed_frames() {
  using p = path<A, B>;
  if constexpr (!p::joined)
    return false;
  else
    return constant_edges(typename p::up{}) && constant_edges(typename p::down{});
}
}  // namespace detail

// A particle of mass Mass at the point P.
template <Point P, auto Mass>
struct particle : detail::particle_tag {
  static_assert(detail::ScalarArgument<Mass>,
                "kane: particle<P, m> takes a scalar expression m (or a number)");
  // the particle keeps its rules (a system admits it only then)
  static constexpr bool well_formed = detail::ScalarArgument<Mass>;
  // P, where the mass is
  using point = P;
  // the mass, a scalar expression
  static constexpr auto mass = detail::freeze<Mass>();
};

// (I)_jk = f_j . I . f_k in F; about Q.
template <Frame F, Point Q, auto I11, auto I22, auto I33, auto I12 = constant<0>{}, auto I23 = constant<0>{},
          auto I31 = constant<0>{}>
struct inertia : detail::inertia_tag {
  static_assert((detail::ScalarArgument<I11> && detail::ScalarArgument<I22> && detail::ScalarArgument<I33> &&
                 detail::ScalarArgument<I12> && detail::ScalarArgument<I23> && detail::ScalarArgument<I31>),
                "kane: inertia<F, Q, I11, I22, I33, I12, I23, I31> takes scalar expressions or numbers");
  // F, the frame of the components
  using frame = F;
  // Q, the point the inertia is about
  using about = Q;
  // (I11, I22, I33, I12, I23, I31)
  static constexpr std::tuple components{detail::freeze<I11>(), detail::freeze<I22>(), detail::freeze<I33>(),
                                         detail::freeze<I12>(), detail::freeze<I23>(), detail::freeze<I31>()};
};

namespace detail {
// I_G = I_Q - m (|d|^2 1 - d d), d = r^QG in F's components (fixed in F).
template <class I, class G, auto Mass>
struct moved_inertia {
  using F = typename I::frame;
  static constexpr auto d = position<typename I::about, G>();
  static_assert(is_zero_vector_v<decltype(ddt_in<F>(d))>,
                "kane: parallel_axis<I, G, m> needs the mass centre G fixed in the frame of I");
  static constexpr auto m = freeze<Mass>();
  static constexpr auto d1 = dot(d, e<F, 1>), d2 = dot(d, e<F, 2>), d3 = dot(d, e<F, 3>);
  static constexpr auto c = I::components;
  using type = inertia<F, G, std::get<0>(c) - m*(d2* d2 + d3 * d3), std::get<1>(c) - m*(d3* d3 + d1 * d1),
                       std::get<2>(c) - m*(d1* d1 + d2 * d2), std::get<3>(c) + m * d1 * d2,
                       std::get<4>(c) + m * d2 * d3, std::get<5>(c) + m * d3 * d1>;
};
}  // namespace detail

// The inertia I (about any point Q) moved to the mass centre G of mass m.
template <class I, Point G, auto Mass>
using parallel_axis = typename detail::moved_inertia<I, G, Mass>::type;

namespace detail {
// I as given, or, in a frame W that spins, I in W's parent: the same components if symmetric
// about the spin axis, the only inertia a frame of unknown axes can have.
template <class I>
struct inertia_for {
  using type = I;
};
template <class I>
requires spin_edge<typename I::frame>
struct inertia_for<I> {
  using P = typename I::frame::tree_parent;
  static constexpr auto c = I::components;
  using in_parent = inertia<P, typename I::about, std::get<0>(c), std::get<1>(c), std::get<2>(c),
                            std::get<3>(c), std::get<4>(c), std::get<5>(c)>;
  static constexpr bool symmetric = spins_symmetric<typename I::frame, in_parent>();
  static_assert(
      check<symmetric,
            error::inertia_in_a_spinning_frame_is_symmetric_about_its_spin_axis<typename I::frame>>);
  // after the error, an inertia that raises no other
  using type =
      std::conditional_t<symmetric, in_parent,
                         inertia<P, typename I::about, std::get<0>(c), std::get<0>(c), std::get<0>(c)>>;
};

// I in the highest frame up the tree from its own whose edges below it turn about axes I is
// symmetric about (a disc or a wheel given in its own frame): the same components there, read
// without the turns' angles. Not into a spinning frame (its axes are not known).
template <class I>
struct symmetric_lift {
  using type = I;
};
template <class I>
requires(!std::is_void_v<typename I::frame::tree_parent> &&
         !matrix_edge<typename I::frame>) struct symmetric_lift<I> {
  using P = typename I::frame::tree_parent;
  static constexpr auto c = I::components;
  using in_parent = inertia<P, typename I::about, std::get<0>(c), std::get<1>(c), std::get<2>(c),
                            std::get<3>(c), std::get<4>(c), std::get<5>(c)>;
  using type = typename std::conditional_t<spins_symmetric<typename I::frame, in_parent>() && !spin_edge<P>,
                                           symmetric_lift<in_parent>, std::type_identity<I>>::type;
};
// The point an inertia is given about; Bo for what is no inertia (another rule refuses it).
template <class Given, class Bo>
struct about_of : std::type_identity<Bo> {};
template <class Given, class Bo>
requires std::derived_from<Given, inertia_tag>
struct about_of<Given, Bo> : std::type_identity<typename Given::about> {
};
// The rules of rigid_body<B, Bo, m, I> as one value, without an error.
template <class B, class Bo, class Given>
constexpr bool body_rules() {
  if constexpr (!std::derived_from<Given, inertia_tag> ||
                !std::is_same_v<typename about_of<Given, Bo>::type, Bo>)
    return false;
  else {
    using F = typename Given::frame;
    if constexpr (!path<B, F>::joined)
      return false;
    else if constexpr (spin_edge<F>)
      return inertia_for<Given>::symmetric;
    else
      return fixed_frames<B, F>() || spins_symmetric<B, Given>();
  }
}
}  // namespace detail

// A rigid body fixed in B, mass centre Bo, mass Mass, inertia Given (kane::inertia).
template <Frame B, Point Bo, auto Mass, class Given>
struct rigid_body
    : detail::body_tag,
      detail::holds<detail::fixed_frames<B, typename detail::inertia_for<Given>::type::frame>() ||
                        detail::spins_symmetric<B, typename detail::inertia_for<Given>::type>(),
                    error::inertia_given_in_a_frame_that_turns_relative_to_the_body<
                        typename detail::inertia_for<Given>::type::frame, B>,
                    fix::give_the_inertia_in_the_body_frame<B>>,
      detail::holds<std::is_same_v<typename detail::about_of<Given, Bo>::type, Bo>,
                    error::inertia_about_another_point_than_the_mass_centre_use_parallel_axis<
                        typename detail::about_of<Given, Bo>::type, Bo>,
                    fix::give_the_inertia_about_the_mass_centre<Bo>> {
  static_assert(detail::ScalarArgument<Mass>,
                "kane: rigid_body<B, Bo, m, I> takes a scalar expression m (or a number)");
  static_assert(std::derived_from<Given, detail::inertia_tag>,
                "kane: rigid_body<B, Bo, m, I> takes I = kane::inertia<F, Bo, ...>");
  // the inertia as given, or in the parent of a frame that spins
  using I = typename detail::inertia_for<Given>::type;
  static_assert(detail::joined_frames<B, typename I::frame>::joined);
  // the body keeps its rules (a system admits it only then)
  static constexpr bool well_formed = detail::ScalarArgument<Mass> && detail::body_rules<B, Bo, Given>();
  // B, the frame the body is fixed in
  using frame = B;
  // Bo, the mass centre
  using centre = Bo;
  // the inertia used
  using inertia_type = I;
  // the mass, a scalar expression
  static constexpr auto mass = detail::freeze<Mass>();
};

namespace detail {
template <class T>
inline constexpr bool is_particle = __is_base_of(particle_tag, T);  // a builtin: a short error context
template <class T>
inline constexpr bool is_body = __is_base_of(body_tag, T);

// P is a particle's point, or its position from a mass centre is constant in that body.
template <class P, class X>
constexpr bool carries(X*) {
  if constexpr (is_particle<X>)
    return std::is_same_v<P, typename X::point>;
  else if constexpr (is_body<X>) {
    using cp = typename point_chain<P>::type;
    using cq = typename point_chain<typename X::centre>::type;
    if constexpr (std::is_void_v<typename first_common<cp, cq>::type>)
      return false;
    else
      return is_zero_vector_v<decltype(ddt_in<typename X::frame>(position<typename X::centre, P>()))>;
  } else
    return false;
}

struct system_tag {};
template <class X>
struct items_of {
  using type = list<X>;
};
template <class X>
requires std::derived_from<X, system_tag>
struct items_of<X> {
  using type = typename X::items;
};
}  // namespace detail

// The items of a system, in order; a system among them adds its own.
template <class... X>
struct system : detail::system_tag {
  static_assert(
      ((detail::is_particle<X> || detail::is_body<X> || std::derived_from<X, detail::load_tag> ||
        std::derived_from<X, detail::system_tag>)&&...),
      "kane: system<...> takes particles, rigid bodies, loads (force, torque, gravity) and systems");
  // the particles, bodies and loads, nested systems flattened
  using items = typename detail::concat<typename detail::items_of<X>::type...>::type;
};

// kane::system<...>, or a class that derives from one.
template <class T>
concept System = __is_base_of(detail::system_tag, T);  // a builtin: a short error context

namespace detail {
// A force of Sys acts where its partial velocities are those of a mass.
template <class F, class... X>
constexpr bool force_applies(list<X...>) {
  if constexpr (!is_force<F>)
    return true;
  else
    return (carries<typename F::point>(static_cast<X*>(nullptr)) || ...);
}
// The point of a particle, the mass centre of a body.
template <class X>
struct point_of_mass {
  using type = typename X::point;
};
template <class X>
requires is_body<X>
struct point_of_mass<X> {
  using type = typename X::centre;
};
}  // namespace detail

}  // namespace kane
#pragma GCC diagnostic pop
