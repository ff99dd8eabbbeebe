// A few iterations of iLQR (iterative linear-quadratic regulator) swing the 6R arm with masses
// (models/arm6_dynamics.hpp) from rest at q = 0 to rest at a target pose in 1 s. Each iteration
// asks kane::linearize for A = d x'/dx and B = d x'/dr along the trajectory: for this arm they
// come from the analytical derivatives of forward dynamics. The step is semi-implicit Euler,
// u+ = u + dt u'(x, r), q+ = q + dt u+. The cost is 1/2 sum r^T R r plus a terminal cost on the
// pose and the speeds. Each iteration must lower the cost; the arm must end within 0.01 rad.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>

#include <Eigen/Cholesky>

#include "models/arm6_dynamics.hpp"

namespace arm = models::arm6;
using state = kane::state<double, 6, 6, 0, 6>;  // 6 inputs: the joint torques
using evaluator = kane::evaluator<state, kane::frames<arm::B6>, kane::level::pose, kane::qdot_speeds<6>>;
using inputs = kane::inputs<kane::r<1>, kane::r<2>, kane::r<3>, kane::r<4>, kane::r<5>, kane::r<6>>;

constexpr int T = 80;  // steps
constexpr double dt = 1.0 / T;
using X = Eigen::Matrix<double, 12, 1>;
using R = Eigen::Matrix<double, 6, 1>;
const X target = (X() << 0.8, -0.5, 0.6, 0.3, -0.4, 0.2, 0, 0, 0, 0, 0, 0).finished();
const double r_weight = 1e-3, q_weight = 1e3, u_weight = 1e2;

// One step of semi-implicit Euler; with its Jacobians fx, fr if asked.
bool step(const X& x, const R& r, X& next, Eigen::Matrix<double, 12, 12>* fx = nullptr,
          Eigen::Matrix<double, 12, 6>* fr = nullptr) {
  state s;
  for (std::size_t i = 0; i < 6; ++i)
    s.q[i] = x(Eigen::Index(i)), s.u[i] = x(Eigen::Index(6 + i)), s.r[i] = r(Eigen::Index(i));
  const auto lin = kane::linearize<arm::driven, evaluator, inputs>(s);  // x' = A dx + B dr
  if (lin.status != kane::solve_status::ok) return false;
  const R ud = lin.rate.tail<6>();
  next.tail<6>() = x.tail<6>() + dt * ud;
  next.head<6>() = x.head<6>() + dt * next.tail<6>();
  if (fx) {
    fx->setZero(), fx->block<6, 6>(6, 6).setIdentity();
    fx->bottomRows<6>() += dt * lin.A.bottomRows<6>();
    fx->topRows<6>() = dt * fx->bottomRows<6>();
    fx->block<6, 6>(0, 0) += Eigen::Matrix<double, 6, 6>::Identity();
    fr->bottomRows<6>() = dt * lin.B.bottomRows<6>();
    fr->topRows<6>() = dt * fr->bottomRows<6>();
  }
  return true;
}
double terminal_cost(const X& x) {
  const X e = x - target;
  return 0.5 * (q_weight * e.head<6>().squaredNorm() + u_weight * e.tail<6>().squaredNorm());
}

struct trajectory {
  std::array<X, T + 1> x;
  std::array<R, T> r;
  std::array<Eigen::Matrix<double, 12, 12>, T> fx;
  std::array<Eigen::Matrix<double, 12, 6>, T> fr;
  std::array<Eigen::Matrix<double, 6, 12>, T> gain;
  std::array<R, T> feedforward;
  double cost = 0;
};
trajectory now, trial;  // large: static storage, no heap

// Roll out from x0 with r_k = r0_k + alpha k_k + K_k (x_k - x0_k) where the policy is given.
bool roll_out(const trajectory& from, trajectory& to, double alpha, bool policy) {
  to.x[0] = from.x[0], to.cost = 0;
  for (int k = 0; k < T; ++k) {
    to.r[k] = from.r[k];
    if (policy) to.r[k] += alpha * from.feedforward[k] + from.gain[k] * (to.x[k] - from.x[k]);
    to.cost += 0.5 * r_weight * to.r[k].squaredNorm();
    if (!step(to.x[k], to.r[k], to.x[k + 1], &to.fx[k], &to.fr[k])) return false;
  }
  to.cost += terminal_cost(to.x[T]);
  return true;
}

// The backward pass: gains from the quadratic model of the cost to go, V.
bool backward(trajectory& t, double mu) {
  X vx = (t.x[T] - target).cwiseProduct((X() << R::Constant(q_weight), R::Constant(u_weight)).finished());
  Eigen::Matrix<double, 12, 12> vxx = Eigen::Matrix<double, 12, 12>::Zero();
  vxx.diagonal() << R::Constant(q_weight), R::Constant(u_weight);
  for (int k = T - 1; k >= 0; --k) {
    const auto& a = t.fx[k];
    const auto& b = t.fr[k];
    const X qx = a.transpose() * vx;
    const R qu = r_weight * t.r[k] + b.transpose() * vx;
    const Eigen::Matrix<double, 12, 12> qxx = a.transpose() * vxx * a;
    const Eigen::Matrix<double, 6, 12> qux = b.transpose() * vxx * a;
    const Eigen::Matrix<double, 6, 6> quu =
        (r_weight + mu) * Eigen::Matrix<double, 6, 6>::Identity() + b.transpose() * vxx * b;
    const Eigen::LLT<Eigen::Matrix<double, 6, 6>> llt(quu);
    if (llt.info() != Eigen::Success) return false;
    t.gain[k] = -llt.solve(qux), t.feedforward[k] = -llt.solve(qu);
    vx = qx + qux.transpose() * t.feedforward[k];
    vxx = qxx + qux.transpose() * t.gain[k];
    vxx = 0.5 * (vxx + vxx.transpose()).eval();
  }
  return true;
}

int main() {
  // The first guess holds the arm at rest against gravity: r = inverse dynamics at q = u = u' = 0.
  state s;
  evaluator ev;
  ev.update(s);
  const auto hold = kane::inverse_dynamics<arm::links>(ev);
  if (hold.status != kane::solve_status::ok) return 1;
  now.x[0].setZero();
  for (auto& r : now.r) r = hold.tau;
  if (!roll_out(now, now, 0, false)) return 1;
  std::printf("iteration  0: cost %10.4f\n", now.cost);
  bool lowered = true;
  for (int it = 1; it <= 20; ++it) {
    if (!backward(now, 1e-6)) return 1;
    bool accepted = false;
    for (double alpha = 1; alpha > 1e-3 && !accepted; alpha /= 2)
      accepted = roll_out(now, trial, alpha, true) && trial.cost < now.cost;
    lowered = lowered && accepted;
    if (!accepted) break;
    const bool converged = now.cost - trial.cost < 1e-6 * now.cost;
    now = trial;
    if (it % 4 == 0 || converged) std::printf("iteration %2d: cost %10.4f\n", it, now.cost);
    if (converged) break;
  }
  const double error = (now.x[T].head<6>() - target.head<6>()).cwiseAbs().maxCoeff();
  std::printf("largest joint error at 1 s: %.2e rad\n", error);
  const bool pass = lowered && error < 1e-2;
  std::printf(pass ? "reached\n" : "FAILED\n");
  return pass ? 0 : 1;
}
