// A state and its evaluator in jets: the state's numbers as constants (lift), the inputs of a
// linearization seeded as directions (seed_inputs), and the type of linearize's result.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

#include "kane/detail/inline.hpp"
#include "kane/evaluation/evaluator.hpp"
#include "kane/linearization/jet.hpp"
#include "kane/linearization/linear_model.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <class St, class T>
struct rebind_state;
template <class S, std::size_t NQ, std::size_t NU, std::size_t NP, std::size_t NR, class T>
struct rebind_state<state<S, NQ, NU, NP, NR>, T> {
  using type = state<T, NQ, NU, NP, NR>;
};
template <class Ev, class T>
struct rebind_evaluator;
template <class St, class Fr, level L, class Sp, class T>
struct rebind_evaluator<evaluator<St, Fr, L, Sp>, T> {
  using type = evaluator<typename rebind_state<St, T>::type, Fr, L, Sp>;
};
template <class Ev>
struct pose_evaluator;
template <class St, class Fr, level L, class Sp>
struct pose_evaluator<evaluator<St, Fr, L, Sp>> {
  using type = evaluator<St, Fr, level::pose, Sp>;
};
// The state s in jets of N directions, every number constant.
template <std::size_t N, class St>
auto lift(const St& s) {
  using J = jet<typename St::scalar, N>;
  const auto up = [](const auto& a) {  // built in place: no zeros written first
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
      return std::array<J, sizeof...(I)>{J(a[I])...};
    }
    (std::make_index_sequence<std::tuple_size_v<std::remove_cvref_t<decltype(a)>>>{});
  };
  using out = typename rebind_state<St, J>::type;
  if constexpr (St::nr == 0)
    return out{up(s.q), up(s.qd), up(s.qdd), up(s.u), up(s.ud), up(s.p), {}, J(s.t)};
  else
    return out{up(s.q), up(s.qd), up(s.qdd), up(s.u), up(s.ud), up(s.p), up(s.r), J(s.t)};
}
template <class In, class St>
constexpr bool inputs_fit() {
  for (std::size_t k = 0; k < In::n; ++k)
    if (In::slots[k] > (In::of_state[k] ? St::nr : St::np)) return false;
  return true;
}
// Input k is direction first + k; those in [lo, hi) are seeded at their place after lo.
template <class In, class J, class St>
void seed_inputs(St& s, std::size_t first, std::size_t lo = 0, std::size_t hi = std::size_t(-1)) {
  static_assert(inputs_fit<In, St>(),
                "kane: an input of linearize is beyond the state; declare the state with NR (inputs) or NP "
                "(parameters) >= its index");
  static_for<In::n>([&](auto k) {
    auto& x = [&]() -> auto& {
      if constexpr (In::of_state[k])
        return s.r[In::slots[k] - 1];
      else
        return s.p[In::slots[k] - 1];
    }
    ();
    if (first + k >= lo && first + k < hi) x = J::variable(x.v, first + k - lo);
  });
}
template <class Ev, class In>
using model_of = linear_model<typename Ev::scalar, Ev::state_type::nq + Ev::nu, In::n,
                              state_order<one_to<Ev::state_type::nq>(), one_to<Ev::nu>()>>;
}  // namespace kane::detail
#pragma GCC diagnostic pop
