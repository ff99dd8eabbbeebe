// The choices kane's internals make at compile time, named where a call makes them.
#pragma once

namespace kane::detail {

// An edge's ^P P^F walking down the tree, or its transpose walking up.
enum class walk : bool { down, up };
// A derivative with respect to the rates q' or to the speeds u.
enum class wrt : bool { rates, speeds };
// A repeated node's value recalled from the evaluator's memo, or computed afresh.
enum class memo_use : bool { fresh, recall };
// What an update reads of a state: the pose alone, or the pose and the rates.
enum class reading : bool { pose, whole_state };
// The levels one outward pass computes, a set. nan_acceleration: the level asked for, NaN in a
// frame whose angular acceleration no one reads. rest: u' = 0, known when the code is compiled.
enum class stages : unsigned {
  none = 0,
  pose = 1,
  velocity = 2,
  acceleration = 4,
  nan_acceleration = 8,
  rest = 16
};
constexpr stages operator|(stages a, stages b) { return stages(unsigned(a) | unsigned(b)); }
constexpr bool has(stages set, stages s) { return (unsigned(set) & unsigned(s)) != 0; }
constexpr stages rest_if(bool rest) { return rest ? stages::rest : stages::none; }
// The rate levels of an evaluator: velocity, and acceleration.
constexpr stages rate_stages(bool velocity, bool acceleration) {
  return (velocity ? stages::velocity : stages::none) | (acceleration ? stages::acceleration : stages::none);
}
// The levels of one frame: no angular acceleration, but NaN, where no one reads it.
constexpr stages read_only(stages levels, bool read) {
  return read || !has(levels, stages::acceleration)
             ? levels
             : stages(unsigned(levels) & ~unsigned(stages::acceleration)) | stages::nan_acceleration;
}
// The parts of x = T u + t computed: the table T, the remainder t, or both.
enum class linear_part : unsigned { table = 1, remainder = 2, both = 3 };
constexpr bool has(linear_part set, linear_part p) { return (unsigned(set) & unsigned(p)) != 0; }
// Whether a structured solve writes x's entries known at compile time, or leaves them to the caller.
enum class known_entries : bool { written, left };
// W v, or W v + X.
enum class map : bool { linear, affine };
// x + r k, or r k onto zero.
enum class onto : bool { sum, zero };
// A mass with its central inertia, or a particle's.
enum class item_kind : bool { particle, body };

// The u' the equations take: the state's (of_state); the accelerations as the state has them, at
// u' = 0 or giving f = -tau (at_rest); 0 in every speed, known at compile time (zero: motion's state).
enum class rates : unsigned char { of_state, at_rest, zero };
// tau = M u' - f, or -tau (at rest, -tau is the forcing f).
enum class sign : bool { plus, minus };
// What Kane's sums compute: M and f, M alone, or f alone where M is known at compile time.
enum class parts { both, mass_matrix, forcing };
constexpr bool has(parts set, parts p) { return set == parts::both || set == p; }

}  // namespace kane::detail
