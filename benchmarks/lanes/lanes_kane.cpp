// kane over a batch of 64 states (lanes_models.hpp): kane::motion<System, Speeds, S> with S
// double (one state a call), kane::lanes<double, 4>, kane::lanes<double, 8> and
// kane::lanes<float, 16>. The lanes load W states, call once and store W results and statuses.
#include <kane/scalars/lanes.hpp>
#include <kane/scalars/soa_block.hpp>

#include "../../examples/models/arm6_dynamics.hpp"
#include "../../examples/models/bicycle.hpp"
#include "../../examples/models/disc.hpp"
#include "../../examples/models/gyrostat.hpp"
#include "../../examples/models/heavy_top.hpp"
#include "../../examples/models/pendulum_absolute.hpp"
#include "../chain_dynamics/chain_model.hpp"
#include "lanes_models.hpp"

namespace {
template <class S>
using top = kane::motion<models::heavy_top::system, models::heavy_top::speeds, S>;
template <class S>
using spacecraft = kane::motion<models::gyrostat::system, models::gyrostat::speeds, S>;
template <class S>
using pendulum_absolute = kane::motion<models::pendulum_absolute::system, void, S>;

// out[i] = x' at in[i] by motion, W states a call (In: x; Out: xd, and status where it has one)
template <class Motion, class In, class Out>
void batches(Motion& motion, const In* in, Out* out) {
  using L = typename Motion::scalar;
  using S = typename kane::real_type<L>::type;
  constexpr int W = int(kane::lane_traits<L>::width), N = int(Motion::size);
  for (int first = 0; first < lanes_bench::batch; first += W) {
    if constexpr (W == 1) {  // as ../small/small_kane.cpp calls it: x and x' where they are
      Out& o = out[first];
      motion(in[first].x, o.xd, S(0));
      if constexpr (requires { o.status; }) o.status = motion.status() == kane::solve_status::ok ? 0 : 1;
    } else if constexpr (std::is_same_v<S, double>) {  // as the docs teach: to_lanes, from_lanes
      const auto x = kane::to_lanes<W, N>([&](std::size_t l) { return in[first + int(l)].x.data(); }, W);
      std::array<L, N> xd;
      motion(x, xd, L(S(0)));
      kane::from_lanes(
          xd, [&](std::size_t l) { return out[first + int(l)].xd; }, W);
      if constexpr (requires { out->status; }) {
        const auto status = motion.status();
        for (int l = 0; l < W; ++l) out[first + l].status = status[l] == kane::solve_status::ok ? 0 : 1;
      }
    } else {  // floats from and to the doubles of In and Out
      std::array<L, N> x, xd;
      for (int k = 0; k < N; ++k)
        x[k] = L::generate([&](std::size_t l) { return S(in[first + int(l)].x[k]); });
      motion(x, xd, L(S(0)));
      const auto status = motion.status();
      for (int l = 0; l < W; ++l) {
        Out& o = out[first + l];
        for (int k = 0; k < N; ++k) o.xd[k] = double(xd[k][l]);
        if constexpr (requires { o.status; }) o.status = status[l] == kane::solve_status::ok ? 0 : 1;
      }
    }
  }
}
// The right-hand side F over S, built once with the parameters p (none: the default state).
template <class F>
F& instance() {
  static F f{typename F::state_type{}};
  return f;
}
template <class F, std::size_t NP>
F& instance(const std::array<double, NP>& p) {
  static F f = [&] {
    typename F::state_type s{};
    for (std::size_t i = 0; i < NP; ++i)
      s.p[i] = typename F::scalar(typename kane::real_type<typename F::scalar>::type(p[i]));
    return F(s);
  }();
  return f;
}
template <class Motion, class In, class Out>
void batches(const In* in, Out* out) {
  batches(instance<Motion>(), in, out);
}

// the widest lanes of doubles the target's registers hold
using widest = kane::lanes<double, kane::native_lanes<double>>;
// x' of the batch kept as structure-of-arrays buffers (lanes_models.hpp): number k of state i at
// x[k * B + i], filled from the states at the first call. Each call reads W states and writes x' in
// place by kane::soa_block, and stores the statuses.
template <class Motion>
struct soa {
  using L = typename Motion::scalar;
  static constexpr int W = int(kane::lane_traits<L>::width), N = int(Motion::size), B = lanes_bench::batch;
  static inline std::array<double, N * B> x, xd;
  static inline std::array<int, B> status;
  template <class In>
  static const void* run(const In* in) {
    static const bool loaded = [&] {
      for (int i = 0; i < B; ++i)
        for (int k = 0; k < N; ++k) x[k * B + i] = in[i].x[k];
      return true;
    }();
    (void)loaded;
    Motion& motion = instance<Motion>();
    for (int first = 0; first < B; first += W) {
      motion(kane::soa_block<L>(x.data(), B, first), kane::soa_block<L>(xd.data(), B, first), L(0.0));
      const auto st = motion.status();
      for (int l = 0; l < W; ++l) status[first + l] = st[l] == kane::solve_status::ok ? 0 : 1;
    }
    return &xd;
  }
  template <class Out>
  static void out(Out* o) {
    for (int i = 0; i < B; ++i) {
      for (int k = 0; k < N; ++k) o[i].xd[k] = xd[k * B + i];
      o[i].status = status[i];
    }
  }
};

template <class S>
using disc = kane::constrained_motion<models::disc::system, models::disc::rolling, S>;
template <class S>
using bicycle_evaluator =
    kane::evaluator<kane::state<S, 6, 8, 27>, kane::frames<models::bicycle::Wr, models::bicycle::Wf>,
                    kane::level::acceleration, models::bicycle::speeds>;
template <class S>
using bike =
    kane::constrained_motion<models::bicycle::system, models::bicycle::rolling, bicycle_evaluator<S>>;
template <class S>
void disc_batches(const disc_dynamics::input* in, disc_dynamics::output* out) {
  batches(
      instance<disc<S>>(std::array<double, 3>{disc_dynamics::p.r, disc_dynamics::p.m, disc_dynamics::p.g}),
      in, out);
}
template <class S>
void bicycle_batches(const bicycle::input* in, bicycle::rates* out) {
  batches(instance<bike<S>>(bicycle::p), in, out);
}

// q'' = u' of a chain of N revolute joints (System, its last frame Last) at q and u = q', W states a
// call, as ../dynamics6/dynamics6_kane.cpp writes it
template <class L, std::size_t N, class Last, class In, class Out, class Store>
void tree_batches(const In* in, Out* out, Store store) {
  using S = typename kane::real_type<L>::type;
  constexpr int W = int(kane::lane_traits<L>::width);
  using state = kane::state<L, N>;
  using evaluator = kane::evaluator<state, kane::frames<Last>, kane::level::pose, kane::qdot_speeds<N>>;
  for (int first = 0; first < lanes_bench::batch; first += W) {
    state s;
    for (std::size_t k = 0; k < N; ++k) {
      if constexpr (W == 1)
        s.q[k] = in[first].q[k], s.u[k] = in[first].qd[k];
      else
        s.q[k] = L::generate([&](std::size_t l) { return S(in[first + int(l)].q[k]); }),
        s.u[k] = L::generate([&](std::size_t l) { return S(in[first + int(l)].qd[k]); });
    }
    evaluator ev;
    ev.update(s);
    store(ev, out + first);
  }
}
// lane l of x as a double
template <class L>
double lane(const L& x, int l) {
  if constexpr (kane::lane_traits<L>::width == 1)
    return x;
  else
    return double(x[std::size_t(l)]);
}
template <class L, std::size_t N, class System, class Last, class In, class Out>
void tree_batches(const In* in, Out* out) {
  tree_batches<L, N, Last>(in, out, [](const auto& ev, Out* o) {
    const auto ud = kane::forward_dynamics<System>(ev).ud;
    for (int l = 0; l < int(kane::lane_traits<L>::width); ++l)
      for (int k = 0; k < int(N); ++k) o[l].qdd[k] = lane(ud(k), l);
  });
}
// q'' and its derivatives by q and q' of the arm, W states a call (forward_dynamics_derivatives)
template <class L>
void arm6_derivative_batches(const dynamics6::input* in, lanes_bench::arm6_derivatives* out) {
  tree_batches<L, 6, models::arm6::B6>(in, out, [](const auto& ev, lanes_bench::arm6_derivatives* o) {
    const auto d = kane::forward_dynamics_derivatives<models::arm6::links>(ev);
    for (int l = 0; l < int(kane::lane_traits<L>::width); ++l) {
      for (int k = 0; k < 6; ++k) o[l].qdd[k] = lane(d.ud(k), l);
      for (int k = 0; k < 36; ++k) o[l].dq[k] = lane(d.dud_dq(k), l), o[l].dqd[k] = lane(d.dud_du(k), l);
    }
  });
}
template <class L>
void chain24_batches(const chain_dynamics::input* in, chain_dynamics::output* out) {
  tree_batches<L, 24, chain_model::system<24>, chain_model::B<24>>(in, out);
}
template <class L>
void arm6_batches(const dynamics6::input* in, dynamics6::output* out) {
  tree_batches<L, 6, models::arm6::links, models::arm6::B6>(in, out);
}
}  // namespace

namespace lanes_bench {
void top_kane(const small::top_in* in, small::top_out* out) { batches<top<double>>(in, out); }
void top_kane_x4(const small::top_in* in, small::top_out* out) {
  batches<top<kane::lanes<double, 4>>>(in, out);
}
#if KANE_LANES_WIDE
void top_kane_x8(const small::top_in* in, small::top_out* out) {
  batches<top<kane::lanes<double, 8>>>(in, out);
}
#endif
#if KANE_LANES_WIDE
void top_kane_float_x16(const small::top_in* in, small::top_out* out) {
  batches<top<kane::lanes<float, 16>>>(in, out);
}
#endif
const void* top_kane_soa(const small::top_in* in) { return soa<top<widest>>::run(in); }
const void* spacecraft_kane_soa(const small::spacecraft_in* in) { return soa<spacecraft<widest>>::run(in); }
const void* pendulum_absolute_kane_soa(const small::pendulum_in* in) {
  return soa<pendulum_absolute<widest>>::run(in);
}
void top_soa_out(small::top_out* out) { soa<top<widest>>::out(out); }
void spacecraft_soa_out(small::spacecraft_out* out) { soa<spacecraft<widest>>::out(out); }
void pendulum_absolute_soa_out(small::pendulum_out* out) { soa<pendulum_absolute<widest>>::out(out); }
void spacecraft_kane(const small::spacecraft_in* in, small::spacecraft_out* out) {
  batches<spacecraft<double>>(in, out);
}
void spacecraft_kane_x4(const small::spacecraft_in* in, small::spacecraft_out* out) {
  batches<spacecraft<kane::lanes<double, 4>>>(in, out);
}
#if KANE_LANES_WIDE
void spacecraft_kane_x8(const small::spacecraft_in* in, small::spacecraft_out* out) {
  batches<spacecraft<kane::lanes<double, 8>>>(in, out);
}
#endif
#if KANE_LANES_WIDE
void spacecraft_kane_float_x16(const small::spacecraft_in* in, small::spacecraft_out* out) {
  batches<spacecraft<kane::lanes<float, 16>>>(in, out);
}
#endif
void pendulum_absolute_kane(const small::pendulum_in* in, small::pendulum_out* out) {
  batches<pendulum_absolute<double>>(in, out);
}
void pendulum_absolute_kane_x4(const small::pendulum_in* in, small::pendulum_out* out) {
  batches<pendulum_absolute<kane::lanes<double, 4>>>(in, out);
}
#if KANE_LANES_WIDE
void pendulum_absolute_kane_x8(const small::pendulum_in* in, small::pendulum_out* out) {
  batches<pendulum_absolute<kane::lanes<double, 8>>>(in, out);
}
#endif
#if KANE_LANES_WIDE
void pendulum_absolute_kane_float_x16(const small::pendulum_in* in, small::pendulum_out* out) {
  batches<pendulum_absolute<kane::lanes<float, 16>>>(in, out);
}
#endif
#define KANE_LANES_NARROW(name, In, Out, call)                        \
  void name##_kane(const In* in, Out* out) { call<double>(in, out); } \
  void name##_kane_x4(const In* in, Out* out) { call<kane::lanes<double, 4>>(in, out); }
#if KANE_LANES_WIDE
#define KANE_LANES_KANE(name, In, Out, call)                                             \
  KANE_LANES_NARROW(name, In, Out, call)                                                 \
  void name##_kane_x8(const In* in, Out* out) { call<kane::lanes<double, 8>>(in, out); } \
  void name##_kane_float_x16(const In* in, Out* out) { call<kane::lanes<float, 16>>(in, out); }
#else
#define KANE_LANES_KANE KANE_LANES_NARROW
#endif
KANE_LANES_KANE(arm6_forward, dynamics6::input, dynamics6::output, arm6_batches)
KANE_LANES_KANE(disc, disc_dynamics::input, disc_dynamics::output, disc_batches)
KANE_LANES_NARROW(arm6_derivatives, dynamics6::input, arm6_derivatives, arm6_derivative_batches)
#if KANE_LANES_WIDE
void arm6_derivatives_kane_x8(const dynamics6::input* in, arm6_derivatives* out) {
  arm6_derivative_batches<kane::lanes<double, 8>>(in, out);
}
#endif
KANE_LANES_KANE(bicycle, bicycle::input, bicycle::rates, bicycle_batches)
KANE_LANES_KANE(chain24_forward, chain_dynamics::input, chain_dynamics::output, chain24_batches)
}  // namespace lanes_bench
