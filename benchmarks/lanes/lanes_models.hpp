// Many states per call: the right-hand sides of the small models (../small/small_models.hpp) over
// a batch of 64 states, by kane's scalar path (one state a call), by lanes of 4 and 8 doubles and
// 16 floats (kane/scalars/lanes.hpp; each batch loaded into lanes and stored back), and by the
// hand-written and SymPy functions called state by state; the same for the 6-revolute arm's and the
// 24-link chain's forward dynamics, the arm's derivatives and the rolling disc's and the bicycle's u'. A
// row's time is that of 64 states.
#pragma once

#include "../bicycle/bicycle.hpp"
#include "../chain_dynamics/chain_dynamics.hpp"
#include "../disc_dynamics/disc_dynamics.hpp"
#include "../dynamics6/dynamics6.hpp"
#include "../small/small_models.hpp"

// Lanes of 8 doubles and 16 floats fill 64 bytes: built where a register holds them (AVX-512) or
// under Clang; optimizing g++ refuses lanes wider than a register (kane::native_lanes).
#if defined(__AVX512F__) || defined(__clang__)
#define KANE_LANES_WIDE 1
#else
#define KANE_LANES_WIDE 0
#endif

namespace lanes_bench {
inline constexpr int batch = 64;
// F over the batch: in[0..63] -> out[0..63]
template <int N>
using batch_function = void (*)(const small::input<N>*, small::output<N>*);

void top_kane(const small::top_in*, small::top_out*);
void top_kane_x4(const small::top_in*, small::top_out*);
void top_kane_x8(const small::top_in*, small::top_out*);
void top_kane_float_x16(const small::top_in*, small::top_out*);
void spacecraft_kane(const small::spacecraft_in*, small::spacecraft_out*);
void spacecraft_kane_x4(const small::spacecraft_in*, small::spacecraft_out*);
void spacecraft_kane_x8(const small::spacecraft_in*, small::spacecraft_out*);
void spacecraft_kane_float_x16(const small::spacecraft_in*, small::spacecraft_out*);
void pendulum_absolute_kane(const small::pendulum_in*, small::pendulum_out*);
void pendulum_absolute_kane_x4(const small::pendulum_in*, small::pendulum_out*);
void pendulum_absolute_kane_x8(const small::pendulum_in*, small::pendulum_out*);
void pendulum_absolute_kane_float_x16(const small::pendulum_in*, small::pendulum_out*);
// x' of the batch in the widest lanes of doubles (kane::native_lanes: 8 with AVX-512, 4 with AVX2)
// from structure-of-arrays buffers (number k of state i at x[k][i]), as an integrator of many
// trajectories keeps its states: the buffers are filled from in once (at the first call); each
// call loads W states by L::load, calls once and stores x' and the statuses into buffers of the
// same form. out receives them (not timed: once, to check them)
const void* top_kane_soa(const small::top_in*);
const void* spacecraft_kane_soa(const small::spacecraft_in*);
const void* pendulum_absolute_kane_soa(const small::pendulum_in*);
void top_soa_out(small::top_out*);
void spacecraft_soa_out(small::spacecraft_out*);
void pendulum_absolute_soa_out(small::pendulum_out*);
// the 6-revolute arm's forward dynamics (../dynamics6/dynamics6.hpp): q'' of each state
void arm6_forward_kane(const dynamics6::input*, dynamics6::output*);
void arm6_forward_kane_x4(const dynamics6::input*, dynamics6::output*);
void arm6_forward_kane_x8(const dynamics6::input*, dynamics6::output*);
void arm6_forward_kane_float_x16(const dynamics6::input*, dynamics6::output*);
// the arm's forward dynamics and its derivatives by q and q' (forward_dynamics_derivatives)
struct arm6_derivatives {
  double qdd[6], dq[36], dqd[36];
};
void arm6_derivatives_kane(const dynamics6::input*, arm6_derivatives*);
void arm6_derivatives_kane_x4(const dynamics6::input*, arm6_derivatives*);
void arm6_derivatives_kane_x8(const dynamics6::input*, arm6_derivatives*);
// the rolling disc's and the bicycle's u' (constrained_motion), the 24-link chain's forward dynamics
void disc_kane(const disc_dynamics::input*, disc_dynamics::output*);
void disc_kane_x4(const disc_dynamics::input*, disc_dynamics::output*);
void disc_kane_x8(const disc_dynamics::input*, disc_dynamics::output*);
void disc_kane_float_x16(const disc_dynamics::input*, disc_dynamics::output*);
void bicycle_kane(const bicycle::input*, bicycle::rates*);
void bicycle_kane_x4(const bicycle::input*, bicycle::rates*);
void bicycle_kane_x8(const bicycle::input*, bicycle::rates*);
void bicycle_kane_float_x16(const bicycle::input*, bicycle::rates*);
void chain24_forward_kane(const chain_dynamics::input*, chain_dynamics::output*);
void chain24_forward_kane_x4(const chain_dynamics::input*, chain_dynamics::output*);
void chain24_forward_kane_x8(const chain_dynamics::input*, chain_dynamics::output*);
void chain24_forward_kane_float_x16(const chain_dynamics::input*, chain_dynamics::output*);
}  // namespace lanes_bench
