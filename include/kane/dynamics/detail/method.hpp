// The method of the dynamics for a system and an evaluator, chosen in one place: the recursive
// passes for a system of joint form (tree/joint_form.hpp), Kane's sums otherwise; M as a table of
// numbers where the sums know it at compile time (sums/known_mass_matrix.hpp); articulated bodies
// (tree/aba.hpp) for u' above articulated_above speeds.
#pragma once

#include <cstddef>
#include <type_traits>

#include "kane/dynamics/detail/sums/known_mass_matrix.hpp"
#include "kane/dynamics/detail/sums/rest_bias.hpp"
#include "kane/dynamics/detail/sums/terms.hpp"
#include "kane/dynamics/detail/system_rules.hpp"
#include "kane/dynamics/detail/tree/joint_form.hpp"
#include "kane/evaluation/reads.hpp"
#include "kane/evaluation/tables.hpp"

namespace kane::detail {

template <class Sys, class Ev>
using joint_form_of = joint_form<Sys, typename Ev::root, speeds_of<Ev>>;
// Sys is of joint form with the evaluator's speeds (joint_form.hpp): the tree's tables hold.
template <class Sys, class Ev>
inline constexpr bool tree_form = [] {
  if constexpr (admitted<Sys, speeds_of<Ev>>())
    return joint_form_of<Sys, Ev>::table.local;
  else
    return false;
}();
// Sys takes the recursive passes. A free joint without joints whose M the sums know at compile time
// (a free body alone) keeps the sums; its derivatives take the tree.
template <class Sys, class Ev>
inline constexpr bool recursive_form = [] {
  if constexpr (tree_form<Sys, Ev>) {
    if constexpr (joint_form_of<Sys, Ev>::table.free >= 0 && speeds_of<Ev>::n == 6)
      return !known_mass_matrix<Sys, typename Ev::root, speeds_of<Ev>>.known;
    else
      return true;
  } else
    return false;
}();
// Sys is of joint form with a free joint (speed_layout.hpp): M and f, not articulated bodies.
template <class Sys, class Ev>
inline constexpr bool free_joint = [] {
  if constexpr (tree_form<Sys, Ev>)
    return joint_form_of<Sys, Ev>::table.free >= 0;
  else
    return false;
}();
// Above this many speeds u' of numbers comes from articulated bodies (aba.hpp), below (and for
// jets) from M and a Cholesky factorization: the crossing of the two on a spatial chain with full
// inertias (benchmarks/chain_dynamics; the performance page gives the figures).
inline constexpr std::size_t articulated_above = 20;
// M of Kane's sums is a table of numbers (known_mass_matrix.hpp)
template <class Sys, class Ev>
constexpr bool known_masses() {
  if constexpr (!admitted<Sys, speeds_of<Ev>>() || recursive_form<Sys, Ev>)
    return false;
  else
    return known_mass_matrix<Sys, typename Ev::root, speeds_of<Ev>>.known;
}

// The acceleration level that the equations of Sys read, for Ev's update_for: every angular
// acceleration and q'' for the recursive passes, those of the terms for Kane's sums
// (evaluation/reads.hpp). Rest: u' = 0, not read from the state (motion.hpp).
struct resting {
  static constexpr bool rest = true;
};
struct moving {};
template <class Sys, class Ev, bool Rest>
struct equation_reads : std::conditional_t<Rest, resting, moving> {
  static constexpr auto reads = [] {
    if constexpr (recursive_form<Sys, Ev>)
      return acceleration_reads<size<typename Ev::closure>::value, Ev::state_type::nq>{
          every<size<typename Ev::closure>::value>(), every<Ev::state_type::nq>()};
    else {
      using terms = decltype(system_terms<typename Ev::root, speeds_of<Ev>>(typename Sys::items{}));
      if constexpr (Rest)  // the terms as Kane's sums at rates::zero evaluate them
        return acceleration_reads_of<Ev>(decltype(rest_terms<typename Ev::speed_set>(terms{})){});
      else
        return acceleration_reads_of<Ev>(terms{});
    }
  }();
  static constexpr auto alpha = reads.alpha;
  static constexpr auto qdd = reads.qdd;
};

}  // namespace kane::detail
