// Reference frames as types.
//
//   struct N : kane::root_frame {};                                      // {N}
//   struct A : kane::frame<N, kane::simple<kane::axis::z, q1>> {};       // A from N
//   struct B : kane::frame<A, kane::body_fixed<3, 2, 1, q2, q3, q4>> {}; // B from A
//
// A frame names its parent, which must be complete where the frame is
// declared: so every tree is built root first and can hold no cycle.
// Each frame is its own struct; deriving one frame from another is not a
// parent-child relation (the two would share parent and orientation).
#pragma once

#include <concepts>
#include <type_traits>

#include "kane/frames/orientation.hpp"
#include "kane/fwd.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

namespace detail {
struct frame_tag {};
template <class T>
concept Complete = requires {
  sizeof(T);
};
}  // namespace detail

template <class F>
concept Frame = detail::Complete<F> && std::derived_from<F, detail::frame_tag>;

// A frame with no parent, e.g. the Newtonian frame N.
struct root_frame : detail::frame_tag {
  // void: a root has no parent
  using parent = void;
  // void: a root has no edge above it
  using tree_parent = void;
};

namespace detail {
// The frame reached after step K (1-based) of Steps from Parent.
template <class Parent, class Steps, std::size_t K>
struct aux_frame : frame_tag {
  using tree_parent = std::conditional_t<K == 1, Parent, aux_frame<Parent, Steps, K - 1>>;
  using step = typename at<Steps, K - 1>::type;
};
}  // namespace detail

// A frame oriented in Parent by O (simple, body_fixed, space_fixed, euler_parameters, spin, attitude).
template <class Parent, class O>
struct frame : detail::frame_tag {
  static_assert(detail::Complete<Parent>,
                "kane: a frame's parent must be declared (complete) before the frame; "
                "declare frames root first (this keeps a frame tree free of cycles)");
  static_assert(std::derived_from<Parent, detail::frame_tag>,
                "kane: frame<Parent, Orientation> needs a frame as Parent "
                "(a struct derived from kane::root_frame or kane::frame)");
  static_assert(Orientation<O>,
                "kane: frame<Parent, Orientation> needs an orientation "
                "(kane::simple, kane::body_fixed, kane::space_fixed, kane::euler_parameters, kane::spin)");
  // the frame this one is oriented in
  using parent = Parent;
  // O, the orientation in the parent
  using orientation = O;

 private:
  static constexpr std::size_t n_ = detail::size<typename O::steps>::value;

 public:
  // The edge of the tree above this frame: its last simple rotation, or its Euler parameters.
  using tree_parent =
      std::conditional_t<n_ == 1, Parent, detail::aux_frame<Parent, typename O::steps, n_ - 1>>;
  // the last step of O: the rotation from tree_parent to this frame
  using step = typename detail::at<typename O::steps, n_ - 1>::type;
};

}  // namespace kane
#pragma GCC diagnostic pop
