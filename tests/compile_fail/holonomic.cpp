// Holonomic constraints name as many dependent coordinates as equations, each once, each one
// that the equations involve. Each case is a misuse (#ifdef) and its fix (#else).
// case holonomic_count: kane: m dependent coordinates need m holonomic constraints
// case dependent_coordinate_twice: kane: a dependent coordinate is named twice
// case dependent_not_in_loop: kane: the holonomic constraints do not determine the dependent coordinates
// case dependent_beyond_state: kane: a dependent coordinate is beyond the state
// case holonomic_not_scalar: kane: holonomic constraints are scalar expressions
#include <kane/kane.hpp>

using kane::q;
struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, kane::coordinate<1>>> {};
inline constexpr auto f1 = kane::cos(q<1>) + kane::cos(q<2>) - 1.5;
inline constexpr auto f2 = kane::sin(q<1>) + kane::sin(q<2>) - q<3>;

#ifdef KANE_CASE_holonomic_count
using h1 = kane::holonomic<kane::dependent_coordinates<2, 3>, f1>;
#else
using h1 = kane::holonomic<kane::dependent_coordinates<2>, f1>;
#endif
#ifdef KANE_CASE_dependent_coordinate_twice
using h2 = kane::holonomic<kane::dependent_coordinates<2, 2>, f1, f2>;
#else
using h2 = kane::holonomic<kane::dependent_coordinates<2, 3>, f1, f2>;
#endif
// f1 does not involve q3
#ifdef KANE_CASE_dependent_not_in_loop
using h3 = kane::holonomic<kane::dependent_coordinates<3>, f1>;
#else
using h3 = kane::holonomic<kane::dependent_coordinates<2>, f1>;
#endif
#ifdef KANE_CASE_holonomic_not_scalar
using h4 = kane::holonomic<kane::dependent_coordinates<2>, kane::e<N, 1>>;
#else
using h4 = kane::holonomic<kane::dependent_coordinates<2>, kane::dot(kane::e<N, 1>, kane::e<A, 1>) - q<2>>;
#endif

double use() {
  using St = kane::state<double, 3>;
  St s;
  kane::evaluator<St, kane::frames<A>> ev;
  double x = double(kane::solve_configuration<h1>(ev, s).iterations + h2::m + h3::m);
  x += double(kane::solve_configuration<h4>(ev, s).iterations);
#ifdef KANE_CASE_dependent_beyond_state
  using h5 = kane::holonomic<kane::dependent_coordinates<4>, f1 - q<4>>;
#else
  using h5 = kane::holonomic<kane::dependent_coordinates<3>, f1 - q<3>>;
#endif
  return x + double(kane::solve_configuration<h5>(ev, s).iterations);
}
