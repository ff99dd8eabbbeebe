// The evaluator: one outward pass over the frame tree per state, the kinematic differential
// equations solved at it, then any number of expressions evaluated from its cache (evaluate.hpp).
//
//   kane::evaluator<State, kane::frames<C, E>> ev;  // C, E and their ancestors
//   ev.update(s);                                    // sin/cos once, then per frame
//   kane::vec<N> v = kane::express<N>(expr, ev);     // ^N components of expr
//
// With a speed set, q' and q'' are solved from u and u' (kinematic_equations.hpp). Without one u is
// q': q' is read from s.qd, or from s.u where s.qd holds 0 (q'' from s.qdd or s.ud likewise);
// different nonzero numbers in both are conflicting_rates. update(s) copies what evaluation reads of s
// (q, p, t and, with a speed set, u and u', else q' and q''): every result is of the state of the last
// update, never a mix of two states, and s may be a temporary. An attitude of s that is not a rotation
// (frames/orientation.hpp, rotation_tolerance) gives status not_a_rotation and NaN for all computed
// from it. Before the first update the state is NaN (updated() is false, debug builds assert): every
// result is NaN, never a read of memory not written. Evaluating allocates nothing and calls no sin or
// cos of a frame coordinate.
#pragma once

#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

#include "kane/detail/choices.hpp"
#include "kane/detail/lane_copy.hpp"
#include "kane/detail/tree.hpp"
#include "kane/detail/trig.hpp"
#include "kane/detail/v3.hpp"
#include "kane/evaluation/attitudes.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/kinematic_equations.hpp"
#include "kane/evaluation/merged_rates.hpp"
#include "kane/evaluation/outward_pass.hpp"
#include "kane/evaluation/state_indices.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/frames/state.hpp"
#include "kane/kinematics/edges.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane {

template <State St, class Frames, level Level = level::acceleration, class Speeds = void>
class evaluator;

// The numbers of a state St for the frames Fs... and their ancestors, up to Level, with the speeds
// Given: one outward pass per update.
template <State St, Frame... Fs, level Level, class Given>
class evaluator<St, frames<Fs...>, Level, Given>
    : public detail::outward_pass<typename St::scalar, typename detail::closure<Fs...>::type, Level>,
      public detail::kinematic_equations<St, detail::usable_speeds<Given>> {
  using Speeds = detail::usable_speeds<Given>;
  static_assert(std::is_void_v<Given> || SpeedSet<Given>,
                "kane: the fourth argument of evaluator is a speed set (speeds/generalized_speeds.hpp)");
  using pass_type = detail::outward_pass<typename St::scalar, typename detail::closure<Fs...>::type, Level>;
  static_assert((detail::one_tree_v<detail::join_trees_t<detail::root_of<Fs>, typename pass_type::root>> &&
                 ...));
  static_assert(detail::free_speeds_checked<Speeds>(typename pass_type::closure{}));
  static constexpr std::size_t frames_q_ = detail::highest_of_edges(typename pass_type::closure{}).q;
  static_assert(
      detail::check<frames_q_ <= St::nq,
                    error::a_frame_turns_by_a_coordinate_beyond_the_state<coordinate<frames_q_>, St>,
                    fix::declare_kane_state_with_nq_at_least<frames_q_>>);
  using equations = detail::kinematic_equations<St, Speeds>;
  using equations::direct;
  using equations::solves;
  using typename pass_type::trig_type;

 public:
  // St
  using state_type = St;
  // the scalar type of St
  using scalar = typename St::scalar;
  // Speeds, or void (u = q')
  using speed_set = Speeds;
  // the number of speeds: the speed set's, or nq (u = q')
  static constexpr std::size_t nu =
      std::conditional_t<std::is_void_v<Speeds>, qdot_speeds<St::nq>, Speeds>::n;
  using typename pass_type::closure;

  KANE_ALWAYS_INLINE evaluator() {  // NaN until the first update
    detail::fill_nan(st_.q), detail::fill_nan(st_.qd), detail::fill_nan(st_.qdd);
    detail::fill_nan(st_.u), detail::fill_nan(st_.ud), detail::fill_nan(st_.p);
    if constexpr (St::nr > 0) detail::fill_nan(st_.r);
    st_.t = std::numeric_limits<scalar>::quiet_NaN();
  }

  // The outward pass at a copy of s (later changes of s are not seen). With a speed set, W and X at every
  // level, q' and q'' from s.u and s.ud at the velocity and acceleration levels. status() is ok only if the
  // numbers of s this level reads are finite (q, p, t; then qd or u, then qdd or ud) and, with a speed set, Y
  // is regular and W, X, q', q'' are finite; otherwise it is singular or not_finite, and W (but for its
  // structural zeros and ones), X, q', q'' and all computed from them are NaN (without a speed set, NaN or
  // inf in s reaches what is computed from it).
  KANE_INLINE_FLATTEN void update(const St& s) requires(detail::inlined_entry<pass_type>) {
    pass_at<detail::reading::whole_state>(s);
  }
  // update(s) for more than 8 frames: one flattened function
  KANE_FLATTEN void update(const St& s) requires(!detail::inlined_entry<pass_type>) {
    pass_at<detail::reading::whole_state>(s);
  }

  // With a speed set, update(s) in two steps: update_pose(s) reads q, p, t (the
  // pose, W and X: enough for the constraints' A and B); update_speeds(s) then
  // reads u and u' at that pose (s.q, s.p, s.t are not read again) for the
  // velocity and acceleration levels. Between the two only the pose level may
  // be evaluated; after both, every result and status() are those of update(s).
  KANE_INLINE_FLATTEN void update_pose(const St& s) requires(solves&& detail::inlined_entry<pass_type>) {
    pass_at<detail::reading::pose>(s);
  }
  // update_pose(s) for more than 8 frames: one flattened function
  KANE_FLATTEN void update_pose(const St& s) requires(solves && !detail::inlined_entry<pass_type>) {
    pass_at<detail::reading::pose>(s);
  }
  // u and u' of s at the pose of the last update_pose(s)
  KANE_INLINE_FLATTEN void update_speeds(const St& s) requires(solves&& detail::inlined_entry<pass_type>) {
    speeds_at(s);
  }
  // update_speeds(s) for more than 8 frames: one flattened function
  KANE_FLATTEN void update_speeds(const St& s) requires(solves && !detail::inlined_entry<pass_type>) {
    speeds_at(s);
  }

  // update_speeds(s) for the reads of one computation, as update_for
  template <class Reads>
  KANE_INLINE_FLATTEN void update_speeds_for(const St& s) requires(solves) {
    speeds_at<Reads>(s);
  }

  // update(s) for the reads of one computation (motion.hpp): at the acceleration level the
  // angular accelerations of the frames of Reads::alpha (by closure index) and the q'' of
  // Reads::qdd (by coordinate) only; the others are NaN. With Reads::rest, u' (or q'') is 0,
  // not read from s.
  template <class Reads>
  KANE_INLINE_FLATTEN void update_for(const St& s) {
    pass_at<detail::reading::whole_state, Reads>(s);
  }

  // The inputs r for what is evaluated from now on (loads read them; no pass reads them).
  void set_inputs(const typename St::inputs_type& r) { st_.r = r; }

  // The state of the last update as far as evaluation reads it (with a speed set,
  // q' and q'' stay NaN: coordinate_value gives the solved ones; without, u and u').
  const St& state() const {
    assert(updated_ && "kane: evaluate after update(s)");
    return st_;
  }
  // there was an update: results are of a state, not NaN
  bool updated() const { return updated_; }

  // q_I, q_I', q_I'': from the state, or solved from the speeds.
  template <std::size_t I, std::size_t D>
  scalar coordinate_value() const {
    static_assert(I >= 1 && I <= St::nq,
                  "kane: this coordinate is beyond the state; declare the state with NQ >= I");
    static_assert(D <= 2, "kane: a state holds q, q' and q'' only");
    if constexpr (D == 0)
      return st_.q[I - 1];
    else if constexpr (solves) {
      static_assert(D == 1 ? Level >= level::velocity : Level >= level::acceleration,
                    "kane: q' and q'' are solved from the speeds at the velocity and acceleration levels; "
                    "declare the evaluator with level::velocity or level::acceleration");
      return this->template rate<I, D>();
    } else
      return D == 1 ? st_.qd[I - 1] : st_.qdd[I - 1];
  }

  // (q_1^(D), ..., q_nq^(D)): q' (D = 1) or q'' (D = 2), as coordinate_value.
  template <std::size_t D = 1>
  std::array<scalar, St::nq> coordinate_rates() const {
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
      return std::array<scalar, St::nq>{coordinate_value<I + 1, D>()...};
    }
    (std::make_index_sequence<St::nq>{});
  }

  // sin q_I and cos q_I: from the cache when a frame turns by q_I.
  template <std::size_t I>
  scalar sin_q() const {
    using std::sin;
    if constexpr (trig_type::template holds<I>())
      return this->cached_trig().template sin<I>();
    else
      return sin(st_.q[I - 1]);
  }
  // cos q_I, from the cache when a frame turns by q_I
  template <std::size_t I>
  scalar cos_q() const {
    using std::cos;
    if constexpr (trig_type::template holds<I>())
      return this->cached_trig().template cos<I>();
    else
      return cos(st_.q[I - 1]);
  }

 private:
  static constexpr bool velocity = Level >= level::velocity, acceleration = Level >= level::acceleration;
  static constexpr detail::stages rate_stages = detail::rate_stages(velocity, acceleration);

  // 0 if the rates this level reads (u and u' of s, or q' and q'' as read into st_) are finite, NaN if not.
  template <detail::rates Ud = detail::rates::of_state>
  scalar rates_residue(const St& s) const {
    constexpr bool ud = acceleration && Ud == detail::rates::of_state;
    if constexpr (!velocity)
      return scalar(0);
    else if constexpr (solves)
      return detail::nonfinite_residue(s.u) + (ud ? detail::nonfinite_residue(s.ud) : -scalar(0));
    else  // st_.qd and st_.qdd were just copied whole: read in blocks
      return ud ? detail::input_residue<true>(st_.qd, st_.qdd) : detail::input_residue<true>(st_.qd);
  }

  // Reads::rest: u' = 0, not read from the state (motion.hpp)
  template <class Reads>
  static constexpr bool rests = requires {
    Reads::rest;
  };
  template <class Reads>
  static constexpr detail::rates ud_of = rests<Reads> ? detail::rates::at_rest : detail::rates::of_state;

  struct everything {
    static constexpr auto alpha = pass_type::every_frame::alpha;
    static constexpr auto qdd = equations::every_coordinate::qdd;
  };
  template <detail::reading Read, class Reads = everything>
  KANE_ALWAYS_INLINE void pass_at(const St& s) {
    constexpr bool Rates = Read == detail::reading::whole_state;
    const auto tr = detail::make_trig<pass_type::cached>(s);  // first: nothing lives across the calls
    detail::assign(st_.q, s.q), detail::assign(st_.p, s.p), st_.t = s.t, detail::assign(st_.r, s.r);
    updated_ = true;
    const scalar norm_residue = detail::normalise(st_, closure{});  // Euler parameters of unit norm
    const bool rotations = detail::attitudes(st_, closure{});       // NaN in st_ where not
    bool conflict = false;  // without a speed set: q' and u (q'' and u') that disagree
    if constexpr (!solves) {
      constexpr bool qdd = !rests<Reads>;
      conflict = detail::merged_state_rates<qdd, velocity, acceleration>(st_, s);
      if constexpr (rests<Reads>) st_.qdd = {};
    } else if constexpr (Rates && rests<Reads>)
      detail::assign(st_.u, s.u), detail::assign_zero(st_.ud);
    else if constexpr (Rates)
      detail::assign(st_.u, s.u), detail::assign(st_.ud, s.ud);
    constexpr bool u = Rates && solves && velocity, ud = u && acceleration && !rests<Reads>;  // u' of s
    scalar residue = norm_residue + detail::state_residue<detail::reads_in_blocks<Reads>, u, ud>(s);
    if constexpr (Rates && !solves) residue += rates_residue<ud_of<Reads>>(s);
    this->status_ =
        detail::checks<scalar>(residue == scalar(0), solve_status::not_finite, rotations,
                               solve_status::not_a_rotation, !conflict, solve_status::conflicting_rates);
    if constexpr (!solves) {
      this->template pass<detail::stages::pose | rate_stages, Reads>(
          tr, *this);  // frame after frame, all levels at once
      this->store_trig(tr);
    } else {  // Y, Z need the axes; Y', Z' the angular velocities
      this->template pass<detail::stages::pose>(tr, *this);
      this->store_trig(tr);
      if constexpr (!direct) this->solve_kinematic_equations(*this);
      if constexpr (Rates) rates_at<Reads>(s, tr);
    }
  }

  // The velocity and acceleration levels at s.u and s.ud (a speed set), the pose kept.
  template <class Reads = everything>
  KANE_ALWAYS_INLINE void rates_at(const St& s, const trig_type& tr) {
    if constexpr (velocity) {
      this->template solve_rates<detail::checking_of<Reads>>(s);
      this->template pass<detail::stages::velocity>(tr, *this);
    }
    if constexpr (acceleration) {
      this->template solve_accelerations<Reads>(*this, st_);  // u' as copied (or 0)
      this->template pass<detail::stages::acceleration | detail::rest_if(rests<Reads>), Reads>(tr, *this);
    }
  }
  template <class Reads = everything>
  KANE_ALWAYS_INLINE void speeds_at(const St& s) {
    assert(updated_ && "kane: update_speeds after update_pose");
    st_.u = s.u;
    if constexpr (rests<Reads>)
      st_.ud = {};
    else
      st_.ud = s.ud;
    const scalar residue = rates_residue<ud_of<Reads>>(s);
    if constexpr (lane_traits<scalar>::width == 1)  // a select (g++ then keeps fewer stores than by a branch)
      this->status_ = this->status_ == solve_status::ok && !(residue == scalar(0)) ? solve_status::not_finite
                                                                                   : this->status_;
    else
      detail::fail_unless(this->status_, residue == scalar(0), solve_status::not_finite);
    rates_at<Reads>(s, this->cached_trig());
  }

  St st_;
  bool updated_ = false;
};

namespace detail {
template <class St, class Fr, level L, class Sp>
struct is_evaluator<evaluator<St, Fr, L, Sp>> : std::true_type {};
}  // namespace detail

}  // namespace kane
#pragma GCC diagnostic pop
