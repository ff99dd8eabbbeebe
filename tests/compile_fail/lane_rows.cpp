// Loading and storing lanes through row functions (scalars/lanes.hpp): the numbers a row points to.
// Each case is a misuse (#ifdef) and its fix (#else): the file as it is compiles every fix.
// case to_lanes_of_ints: kane: to_lanes reads float or double
// case from_lanes_into_floats: kane: from_lanes writes the lanes. numbers
#include <array>

#include <kane/scalars/lanes.hpp>

using L = kane::lanes<double, 2>;

double use() {
#ifdef KANE_CASE_to_lanes_of_ints
  std::array<int, 3> in[2]{};
#else
  std::array<double, 3> in[2]{};
#endif
  const auto x = kane::to_lanes<2, 3>([&](std::size_t l) { return in[l].data(); }, 2);
#ifdef KANE_CASE_from_lanes_into_floats
  std::array<float, 3> out[2]{};
#else
  std::array<double, 3> out[2]{};
#endif
  kane::from_lanes(
      x, [&](std::size_t l) { return out[l].data(); }, 2);
  return double(out[1][2]);
}
