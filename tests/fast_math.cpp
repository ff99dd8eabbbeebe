// kane refuses -ffast-math and -ffinite-math-only (evaluation/status.hpp): built with -ffast-math and
// KANE_ALLOW_FAST_MATH with the suite, and without the macro by compile_fail.fast_math.*, which must fail.
#include <kane/kane.hpp>

namespace {
struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, kane::coordinate<1>>> {};
}  // namespace

kane::solve_status fast_math_status(const kane::state<double, 1>& s) {
  kane::evaluator<kane::state<double, 1>, kane::frames<A>, kane::level::velocity, kane::qdot_speeds<1>> ev;
  ev.update(s);
  return ev.status();
}
