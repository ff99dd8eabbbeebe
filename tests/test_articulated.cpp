// Articulated bodies (the articulated-body algorithm) on a branched tree, called below the size
// that forward_dynamics takes them at: an oblique axis turns by a general E, a tool is fixed in its
// body, a particle sits on a branch. u' equals M^-1 f of the composite bodies and inward sums.
#include <catch2/catch.hpp>

#include <random>

#include <Eigen/Cholesky>
#include <kane/kane.hpp>

#include "recursive_models.hpp"

namespace {
namespace tree = recursive::tree;
using recursive::random_state;
}  // namespace

TEST_CASE("tree: u' by articulated bodies equals M^-1 f by composite bodies and inward sums", "[recursive]") {
  std::mt19937 rng(29);
  for (int k = 0; k < 10; ++k) {
    const auto s = random_state<tree::state>(rng);
    tree::evaluator ev;
    ev.update(s);
    using JF = kane::detail::joint_form_of<tree::system, tree::evaluator>;
    const kane::detail::body_frames<JF, tree::evaluator> bf(ev);
    Eigen::Matrix<double, 4, 1> ud;
    REQUIRE(kane::detail::articulated_accelerations<JF, tree::system>(bf, ev, ud));
    const auto eom = kane::mass_matrix_and_forcing<tree::system>(ev);
    const Eigen::Matrix<double, 4, 1> ref = eom.M.llt().solve(eom.f);
    CHECK((ud - ref).cwiseAbs().maxCoeff() < 1e-10 * (1 + ref.cwiseAbs().maxCoeff()));
  }
}
