// kane's floating base: forward dynamics, its analytical derivatives and kane::linearize.
#include "../../tests/floating_arms.hpp"
#include "floating_base.hpp"

namespace {
using model = floating_arms::model<8>;
static_assert(model::state::nq == floating_base::nq && model::state::nu == floating_base::nu);
model::state state_of(const floating_base::input& in) {
  model::state s{};
  s.q = in.q, s.u = in.u;
  s.r = {70.0, 0.4, -0.3};
  return s;
}
template <class M>
void put(const M& m, double* out) {
  for (Eigen::Index j = 0; j < m.cols(); ++j)
    for (Eigen::Index i = 0; i < m.rows(); ++i) out[j * m.rows() + i] = m(i, j);
}
template <class L>
void rows(const L& lin, floating_base::output& out) {
  put(lin.A.template bottomRows<int(floating_base::nu)>(), out.a);
  for (std::size_t i = 0; i < floating_base::nu; ++i)
    out.ud[i] = lin.rate(Eigen::Index(floating_base::nq + i));
  out.status = int(lin.status);
}
}  // namespace

namespace floating_base {
void kane_forward(const input& in, output& out) {
  model::evaluator ev;
  ev.update(state_of(in));
  const auto fd = kane::forward_dynamics<model::system>(ev);
  for (std::size_t i = 0; i < nu; ++i) out.ud[i] = fd.ud(Eigen::Index(i));
  out.status = int(fd.status);
}
void kane_derivatives(const input& in, output& out) {
  model::evaluator ev;
  ev.update(state_of(in));
  const auto d = kane::forward_dynamics_derivatives<model::system>(ev);
  for (std::size_t i = 0; i < nu; ++i) out.ud[i] = d.ud(Eigen::Index(i));
  put(d.dud_dq, out.dq), put(d.dud_du, out.du);
  out.status = int(d.status);
}
void kane_linearize(const input& in, output& out) {
  rows(kane::linearize<model::system, model::evaluator, model::inputs>(state_of(in)), out);
}
void jets_linearize(const input& in, output& out) {
  rows(kane::detail::linearize_in_batches<model::system, model::evaluator, model::inputs>(state_of(in)), out);
}
void kane_linearize_tangent(const input& in, output& out) {
  const auto lin = kane::linearize_tangent<model::system, model::evaluator, model::inputs>(state_of(in));
  put(lin.A.bottomRows<int(nu)>(), out.a);
  out.status = int(lin.status);
}
void central(const input& in, output& out) {
  const double h = 1e-6;
  model::state s = state_of(in);
  const auto column = [&](const model::state& p, const model::state& m, double* d) {
    output a{}, b{};
    input x = in;
    x.q = p.q, x.u = p.u, kane_forward(x, a);
    x.q = m.q, x.u = m.u, kane_forward(x, b);
    for (std::size_t i = 0; i < nu; ++i) d[i] = (a.ud[i] - b.ud[i]) / (2 * h);
  };
  for (std::size_t j = 0; j < nu; ++j) {
    column(floating_arms::moved(s, j, h), floating_arms::moved(s, j, -h), out.dq + j * nu);
    model::state p = s, m = s;
    p.u[j] += h, m.u[j] -= h;
    column(p, m, out.du + j * nu);
  }
  kane_forward(in, out);
}
}  // namespace floating_base
