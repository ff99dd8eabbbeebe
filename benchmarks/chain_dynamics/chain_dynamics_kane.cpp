// kane: Kane's equations of the n-link chain (chain_dynamics.hpp), n = KANE_CHAIN_N,
// one translation unit per n (its compile cost measured alone).
#include "chain_model.hpp"

#ifndef KANE_CHAIN_N
#error "chain_dynamics_kane.cpp: define KANE_CHAIN_N, the number of links"
#endif
static_assert(KANE_CHAIN_N >= 1 && KANE_CHAIN_N <= chain_dynamics::max_n);

template <std::size_t N>
void chain_dynamics::kane_forward(const input& in, output& out) {
  typename chain_model::evaluator<N> ev;
  ev.update(chain_model::state_of<N>(in));
  Eigen::Map<Eigen::Matrix<double, int(N), 1>>(out.qdd) =
      kane::forward_dynamics<chain_model::system<N>>(ev).ud;
}
template void chain_dynamics::kane_forward<KANE_CHAIN_N>(const input&, output&);

template <std::size_t N>
void chain_dynamics::kane_inverse(const input& in, torques& out) {
  typename chain_model::evaluator<N> ev;
  ev.update(chain_model::state_of<N>(in));
  Eigen::Map<Eigen::Matrix<double, int(N), 1>>(out.tau) =
      kane::inverse_dynamics<chain_model::system<N>>(ev).tau;
}
template void chain_dynamics::kane_inverse<KANE_CHAIN_N>(const input&, torques&);
