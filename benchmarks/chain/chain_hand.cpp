// The hand-written outward pass for the scaling chain (chain.hpp).
#include "../common/hand.hpp"
#include "chain.hpp"

namespace {
struct model {
  static constexpr int axis(int i) {  // z, y, y, x, y, x repeated
    const int m = (i + 1) % 6;
    return m == 1 ? 2 : (m == 4 || m == 0) ? 0 : 1;
  }
  static constexpr double length(int) { return 0.1; }
};
}  // namespace

namespace chain {
// All quantities in one outward pass (hand.hpp's outward_pass, as arm6's ALL): plain doubles, sin
// and cos of every joint first, joints unrolled at compile time, two columns turned per joint.
template <int n>
void hand_all(const input& in, output& out) {
  hand::outward_pass<n, model>(in.q, in.qd, in.qdd, out);
}
template void hand_all<2>(const input&, output&);
template void hand_all<4>(const input&, output&);
template void hand_all<6>(const input&, output&);
template void hand_all<10>(const input&, output&);
template void hand_all<16>(const input&, output&);
template void hand_all<20>(const input&, output&);
}  // namespace chain
