// Central differences of a function of the evaluator, and the error measure of the derivatives'
// tests.
#pragma once

#include <cstddef>

// Column j of d g / dq (Speed: d g / du) by central differences of g(evaluator) with step h.
template <class Ev, bool Speed, class St, class G>
auto central(const St& s, std::size_t j, G g, double h = 1e-6) {
  St a = s, b = s;
  (Speed ? a.u[j] : a.q[j]) += h;
  (Speed ? b.u[j] : b.q[j]) -= h;
  Ev ea, eb;
  ea.update(a), eb.update(b);
  return ((g(ea) - g(eb)) / (2 * h)).eval();
}
// max |a - b| relative to 1 + max |b|
template <class M, class R>
double relative(const M& a, const R& b) {
  return (a - b).cwiseAbs().maxCoeff() / (1 + b.cwiseAbs().maxCoeff());
}
