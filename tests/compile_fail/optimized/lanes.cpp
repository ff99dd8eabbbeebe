// Optimizing g++ refuses lanes wider than a vector register (scalars/lanes.hpp): compiled at -O2.
// case too_wide: kane: lanes.S, W. wider than a vector register && KANE_ALLOW_WIDE_LANES
#include <kane/scalars/lanes.hpp>

#ifdef KANE_CASE_too_wide
using wide = kane::lanes<double, 2 * kane::native_lanes<double>>;
#else
using wide = kane::lanes<double, kane::native_lanes<double>>;
#endif

double use(wide x) { return (x * x)[0]; }
