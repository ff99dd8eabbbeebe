// kane: the analytical derivatives of the n-link chain's forward dynamics (du'/dq, du'/du) and of
// its inverse dynamics (dtau/dq, dtau/du),
// n = KANE_CHAIN_N, one translation unit per n (its compile cost measured alone).
#include "chain_model.hpp"

#ifndef KANE_CHAIN_N
#error "chain_dynamics_derivatives.cpp: define KANE_CHAIN_N, the number of links"
#endif
static_assert(KANE_CHAIN_N >= 1 && KANE_CHAIN_N <= chain_dynamics::max_n);

template <std::size_t N>
void chain_dynamics::kane_derivatives(const input& in, derivatives& out) {
  typename chain_model::evaluator<N> ev;
  ev.update(chain_model::state_of<N>(in));
  const auto d = kane::forward_dynamics_derivatives<chain_model::system<N>>(ev);
  using square = Eigen::Map<Eigen::Matrix<double, int(N), int(N)>>;
  Eigen::Map<Eigen::Matrix<double, int(N), 1>>(out.ud) = d.ud;
  square(out.dq) = d.dud_dq, square(out.du) = d.dud_du;
}
template void chain_dynamics::kane_derivatives<KANE_CHAIN_N>(const input&, derivatives&);

template <std::size_t N>
void chain_dynamics::kane_inverse_derivatives(const input& in, inverse_derivatives& out) {
  typename chain_model::evaluator<N> ev;
  ev.update(chain_model::state_of<N>(in));
  const auto d = kane::inverse_dynamics_derivatives<chain_model::system<N>>(ev);
  using square = Eigen::Map<Eigen::Matrix<double, int(N), int(N)>>;
  Eigen::Map<Eigen::Matrix<double, int(N), 1>>(out.tau) = d.tau;
  square(out.dq) = d.dtau_dq, square(out.du) = d.dtau_du;
}
template void chain_dynamics::kane_inverse_derivatives<KANE_CHAIN_N>(const input&, inverse_derivatives&);
