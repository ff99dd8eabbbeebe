// kane: Kane's equations of the 6-revolute chain with link masses (dynamics6.hpp).
#include <Eigen/Cholesky>

#include "../examples/models/arm6.hpp"
#include "dynamics6.hpp"

namespace {
using namespace models::arm6;
using kane::constant;
using kane::e;
using kane::literal;
template <class B, class From, std::size_t I>
struct centre : kane::point<From, literal(dynamics6::L[I] / 2) * e<B, 1>> {};
struct C1 : centre<B1, O, 0> {};
struct C2 : centre<B2, J2, 1> {};
struct C3 : centre<B3, J3, 2> {};
struct C4 : centre<B4, J4, 3> {};
struct C5 : centre<B5, J5, 4> {};
struct C6 : centre<B6, J6, 5> {};
template <class B, class C, std::size_t I>
using link =
    kane::rigid_body<B, C, literal(dynamics6::mass[I]),
                     kane::inertia<B, C, literal(dynamics6::inertia[I][0]), literal(dynamics6::inertia[I][1]),
                                   literal(dynamics6::inertia[I][2]), literal(dynamics6::inertia[I][3]),
                                   literal(dynamics6::inertia[I][4]), literal(dynamics6::inertia[I][5])>>;
using system =
    kane::system<link<B1, C1, 0>, link<B2, C2, 1>, link<B3, C3, 2>, link<B4, C4, 3>, link<B5, C5, 4>,
                 link<B6, C6, 5>, kane::gravity<literal(-dynamics6::g) * e<N, 3>>>;
using state = kane::state<double, 6>;
using evaluator = kane::evaluator<state, kane::frames<B6>, kane::level::acceleration, kane::qdot_speeds<6>>;

// M and h = -f at (q, q'), u' = 0
template <bool Forward>
void run(const dynamics6::input& in, dynamics6::output& out) {
  state s;
  s.q = in.q;
  s.u = in.qd;
  evaluator ev;
  ev.update(s);
  const auto eom = kane::mass_matrix_and_forcing<system>(ev);
  Eigen::Map<Eigen::Matrix<double, 6, 6>>(out.M) = eom.M;
  Eigen::Map<Eigen::Matrix<double, 6, 1>>(out.h) = -eom.f;
  if constexpr (Forward)
    Eigen::Map<Eigen::Matrix<double, 6, 1>>(out.qdd) = kane::speed_derivatives(eom).first;
}
// M alone: the partial velocities need the pose only
void mass_alone(const dynamics6::input& in, dynamics6::output& out) {
  state s;
  s.q = in.q;
  kane::evaluator<state, kane::frames<B6>, kane::level::pose, kane::qdot_speeds<6>> ev;
  ev.update(s);
  Eigen::Map<Eigen::Matrix<double, 6, 6>>(out.M) = kane::mass_matrix<system>(ev).M;
}
}  // namespace

void dynamics6::kane_mass(const input& in, output& out) { mass_alone(in, out); }
void dynamics6::kane_bias(const input& in, output& out) { run<false>(in, out); }
void dynamics6::kane_forward(const input& in, output& out) { run<true>(in, out); }
