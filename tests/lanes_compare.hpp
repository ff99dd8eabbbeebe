// Lanes against the scalar path: x' of a batch of states by a scalar right-hand side and by one over
// lanes, compared lane by lane (tests/test_lanes.cpp, tests/test_lane_models.cpp).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

#include <catch2/catch.hpp>
#include <kane/kane.hpp>
#include <kane/scalars/lanes.hpp>

namespace lanes_test {

// x' of count states by the scalar motion Scalar and by lanes of W (Lanes), compared lane by lane:
// equal statuses, NaN where not ok, |lane - scalar| <= tol (1 + |scalar|) where ok.
template <class Scalar, class Lanes, class S, std::size_t N>
void compare(Scalar& one, Lanes& many, const std::vector<std::array<S, N>>& xs, S tol) {
  using L = typename Lanes::scalar;
  constexpr std::size_t W = L::width;
  for (std::size_t first = 0; first < xs.size(); first += W) {
    const std::size_t count = xs.size() - first < W ? xs.size() - first : W;
    const auto x = kane::to_lanes<W>(&xs[first], count);
    std::array<L, N> xd;
    many(x, xd, L(S(0)));
    std::vector<std::array<S, N>> out(W);
    kane::from_lanes(xd, out.data(), count);
    const auto statuses = many.status();
    for (std::size_t l = 0; l < count; ++l) {
      std::array<S, N> xd1;
      one(xs[first + l], xd1, S(0));
      INFO("state " << first + l << ": scalar " << kane::to_string(one.status()) << ", lane "
                    << kane::to_string(statuses[l]));
      CHECK(statuses[l] == one.status());
      for (std::size_t k = 0; k < N; ++k) {
        if (one.status() == kane::solve_status::ok)
          CHECK(std::abs(out[l][k] - xd1[k]) <= tol * (1 + std::abs(xd1[k])));
        else
          CHECK(std::isnan(out[l][k]));
      }
    }
    for (std::size_t l = count; l < W; ++l)  // the padding repeats the batch's first state
      CHECK(statuses[l] == statuses[0]);
  }
}
// The same with both right-hand sides built at default states (no parameters).
template <class Scalar, class Lanes, class S, std::size_t N>
void compare(const std::vector<std::array<S, N>>& xs, S tol) {
  Scalar one{typename Scalar::state_type{}};
  Lanes many{typename Lanes::state_type{}};
  compare(one, many, xs, tol);
}

// count random states of N numbers in [-2, 2].
template <class S, std::size_t N>
std::vector<std::array<S, N>> states(std::size_t count, unsigned seed) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> d(-2, 2);
  std::vector<std::array<S, N>> xs(count);
  for (auto& x : xs)
    for (auto& v : x) v = S(d(g));
  return xs;
}

}  // namespace lanes_test
