// One classical Runge-Kutta step of x' = f(x, t), for any right-hand side with
// kane::motion's signature f(x, dxdt, t) (the examples' and tests' integrator).
#pragma once

#include <cstddef>

template <class F, class X>
void rk4_step(F& f, X& x, double t, double h) {
  X k1, k2, k3, k4, y;
  const auto at = [&](const X& k, double a) {
    for (std::size_t i = 0; i < x.size(); ++i) y[i] = x[i] + a * k[i];
    return y;
  };
  f(x, k1, t);
  f(at(k1, h / 2), k2, t + h / 2);
  f(at(k2, h / 2), k3, t + h / 2);
  f(at(k3, h), k4, t + h);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
}
