// The 6-revolute arm's entry points (examples/models/arm6_dynamics.hpp) as a user's unit: M, M and
// f, forward and inverse dynamics at double; with -DKANE_LANES=W the same at kane::lanes<double, W>
// too. The compile table gives what the lanes add to the unit, built for this machine
// (-march=native), where a register holds eight doubles.
#include <cstdio>

#include "../../examples/models/arm6_dynamics.hpp"
#if defined(KANE_LANES)
#define KANE_ALLOW_WIDE_LANES  // compiled for its cost, never run: any W on any target
#include <kane/scalars/lanes.hpp>
#endif

namespace {
using namespace models::arm6;
template <class S>
using evaluator =
    kane::evaluator<kane::state<S, 6>, kane::frames<B6>, kane::level::pose, kane::qdot_speeds<6>>;

// M, f, u' and tau at s; the number of lanes whose four statuses are ok
template <class S>
int all(const kane::state<S, 6>& s, Eigen::Matrix<S, 6, 1>& out) {
  evaluator<S> ev;
  ev.update(s);
  const auto e = kane::mass_matrix_and_forcing<links>(ev);
  const auto m = kane::mass_matrix<links>(ev);
  const auto f = kane::forward_dynamics<links>(ev);
  const auto i = kane::inverse_dynamics<links>(ev);
  out = e.M * f.ud - e.f + i.tau + m.M.col(0);
  int ok = 0;
  for (std::size_t l = 0; l < kane::lane_traits<S>::width; ++l) {
    const auto at = [&](const auto& st) {
      if constexpr (kane::lane_traits<S>::width == 1)
        return st;
      else
        return st[l];
    };
    ok += at(e.status) == kane::solve_status::ok && at(m.status) == kane::solve_status::ok &&
          at(f.status) == kane::solve_status::ok && at(i.status) == kane::solve_status::ok;
  }
  return ok;
}
}  // namespace

int main() {
  kane::state<double, 6> s;
  for (std::size_t k = 0; k < 6; ++k) s.q[k] = 0.1 * double(k), s.u[k] = 0.2, s.ud[k] = -0.1;
  Eigen::Matrix<double, 6, 1> out;
  int ok = all(s, out);
#if defined(KANE_LANES)
  using L = kane::lanes<double, KANE_LANES>;
  kane::state<L, 6> ls;
  for (std::size_t k = 0; k < 6; ++k) ls.q[k] = L(s.q[k]), ls.u[k] = L(s.u[k]), ls.ud[k] = L(s.ud[k]);
  Eigen::Matrix<L, 6, 1> lout;
  ok += all(ls, lout);
#endif
  std::printf("%d ok, %g\n", ok, out(0));
  return 0;
}
