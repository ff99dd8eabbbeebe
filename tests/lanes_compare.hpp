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
#include <kane/scalars/soa_block.hpp>

namespace lanes_test {

// The state x by the scalar motion one against lane l of a call over lanes (its status, its x' out):
// equal statuses, NaN where not ok, |lane - scalar| <= tol (1 + |scalar|) where ok.
template <class Scalar, class S, std::size_t N, class Status, class Out>
void check_lane(Scalar& one, const std::array<S, N>& x, std::size_t state, const Status& status, Out out,
                S tol) {
  std::array<S, N> xd1;
  one(x, xd1, S(0));
  INFO("state " << state << ": scalar " << kane::to_string(one.status()) << ", lane "
                << kane::to_string(status));
  CHECK(status == one.status());
  for (std::size_t k = 0; k < N; ++k) {
    if (one.status() == kane::solve_status::ok)
      CHECK(std::abs(out(k) - xd1[k]) <= tol * (1 + std::abs(xd1[k])));
    else
      CHECK(std::isnan(out(k)));
  }
}
// x' of count states by the scalar motion Scalar and by lanes of W (Lanes), compared lane by lane
// (check_lane); the lanes load and store by to_lanes and from_lanes.
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
    for (std::size_t l = 0; l < count; ++l)
      check_lane(
          one, xs[first + l], first + l, statuses[l], [&](std::size_t k) { return out[l][k]; }, tol);
    for (std::size_t l = count; l < W; ++l)  // the padding repeats the batch's first state
      CHECK(statuses[l] == statuses[0]);
  }
}
// The same with the states in structure-of-arrays buffers, read and written by kane::soa_block; the
// rows padded to a multiple of W by the first state.
template <class Scalar, class Lanes, class S, std::size_t N>
void compare_soa(Scalar& one, Lanes& many, const std::vector<std::array<S, N>>& xs, S tol) {
  using L = typename Lanes::scalar;
  constexpr std::size_t W = L::width;
  const std::size_t B = (xs.size() + W - 1) / W * W;
  std::vector<S> x(N * B), xd(N * B);  // number i of state k at i * B + k
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t k = 0; k < B; ++k) x[i * B + k] = xs[k < xs.size() ? k : 0][i];
  const S* in = x.data();
  for (std::size_t first = 0; first < B; first += W) {
    many(kane::soa_block<L>(in, B, first), kane::soa_block<L>(xd.data(), B, first), L(S(0)));
    const auto statuses = many.status();
    for (std::size_t l = 0; l < W && first + l < xs.size(); ++l)
      check_lane(
          one, xs[first + l], first + l, statuses[l], [&](std::size_t k) { return xd[k * B + first + l]; },
          tol);
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
