// Lanes: the states one number of a scalar holds, and what its comparisons give.
#pragma once

#include <cstddef>

namespace kane {

// One state and bool for every scalar but kane::lanes (kane/scalars/lanes.hpp), whose comparisons
// give a mask per lane.
template <class S>
struct lane_traits {
  // states per number
  static constexpr std::size_t width = 1;
  // the truth values of S's comparisons
  using mask = bool;
  // is lane i of m true
  static constexpr bool lane(bool m, std::size_t) { return m; }
  // m ? a : b
  static constexpr S select(bool m, const S& a, const S& b) { return m ? a : b; }
  // b in every lane
  static constexpr bool truth(bool b) { return b; }
};

}  // namespace kane
