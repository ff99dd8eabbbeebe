// The attitudes of a state as an evaluator reads them (evaluator.hpp): Euler parameters divided
// by their norm, attitudes read from the parameters checked to be rotations.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>

#include "kane/detail/inline.hpp"
#include "kane/detail/list.hpp"
#include "kane/kinematics/edges.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// e / |e| for the Euler parameters e of each frame F in st; 0, or NaN for |e| zero or not finite.
template <class St, class... F>
KANE_ALWAYS_INLINE typename St::scalar normalise(St& st, list<F...>) {
  using S = typename St::scalar;
  S residue = -S(0);
  (
      [&] {
        if constexpr (euler_edge<F>) {
          using std::sqrt;
          constexpr auto c = F::step::coordinates;
          const auto sq = [&](std::size_t i)
                              KANE_ALWAYS_INLINE_LAMBDA { return st.q[c[i] - 1] * st.q[c[i] - 1]; };
          const S n2 = (sq(0) + sq(1)) + (sq(2) + sq(3));
          // the square root beside the division, not after it
          const S k = sqrt(n2) * (S(1) / n2);
          static_for_inline<4>([&](auto i) KANE_ALWAYS_INLINE_LAMBDA { st.q[c[i] - 1] *= k; });
          residue += k - k;
        }
      }(),
      ...);
  return residue;
}

// Each attitude of st is a rotation; where one is not, its numbers in st become NaN.
template <class St, class... F>
KANE_ALWAYS_INLINE bool attitudes(St& st, list<F...>) {
  bool all = true;
  (
      [&] {
        if constexpr (attitude_edge<F>) {
          using src = typename F::step::source;
          if (!F::step::rotation(st)) {
            for (std::size_t i = 0; i < src::count; ++i)
              st.p[src::first - 1 + i] = std::numeric_limits<typename St::scalar>::quiet_NaN();
            all = false;
          }
        }
      }(),
      ...);
  return all;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
