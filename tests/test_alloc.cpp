// Evaluating kinematics allocates nothing: the global allocation functions
// are replaced by counting ones, and every evaluation below runs between two
// readings of the counter. A plain program (no test framework allocating in
// between); exit code 0 when nothing was allocated.
#include <cstdio>
#include <cstdlib>
#include <new>

#include <kane/kane.hpp>

namespace {
long allocations = 0;
}

void* operator new(std::size_t n) {
  ++allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace {
using kane::dot;
using kane::e;
template <std::size_t I>
using q = kane::coordinate<I>;
struct N : kane::root_frame {};
struct B1 : kane::frame<N, kane::simple<kane::axis::z, q<1>>> {};
struct B2 : kane::frame<B1, kane::simple<kane::axis::y, q<2>>> {};
struct B3 : kane::frame<B2, kane::simple<kane::axis::y, q<3>>> {};
struct B4 : kane::frame<B3, kane::simple<kane::axis::x, q<4>>> {};
struct B5 : kane::frame<B4, kane::simple<kane::axis::y, q<5>>> {};
struct B6 : kane::frame<B5, kane::simple<kane::axis::x, q<6>>> {};
struct O : kane::origin<N> {};
struct End : kane::point<O, 0.3 * e<B1, 1> + 0.25 * e<B2, 1> + 0.2 * e<B3, 1> + 0.15 * e<B4, 1> +
                                0.1 * e<B5, 1> + 0.05 * e<B6, 1>> {};

struct Y : kane::frame<N, kane::simple<kane::axis::z, q<1>>> {};
struct L : kane::frame<Y, kane::simple<kane::axis::x, q<2>>> {};
struct R : kane::frame<L, kane::simple<kane::axis::y, q<3>>> {};
struct Rad : kane::parameter<1> {};
inline constexpr Rad r;
struct Contact : kane::point<O, kane::q<4> * e<N, 1> + kane::q<5> * e<N, 2>> {};
struct Centre : kane::point<Contact, r * e<L, 3>> {};
struct Below : kane::point<Centre, -r * e<L, 3>> {};
using speeds5 = kane::angular_velocity_speeds<N, R, L, kane::dt(kane::q<4>), kane::dt(kane::q<5>)>;
inline constexpr auto v_below = kane::body_point_velocity<N, R, Centre, Below>();
using rolling =
    kane::nonholonomic<speeds5, kane::dependent<4, 5>, dot(v_below, e<N, 1>), dot(v_below, e<N, 2>)>;
}  // namespace

int main() {
  kane::state<double, 6> s;
  s.q = {0.1, -0.4, 0.8, 0.3, -1.2, 0.6};
  s.qd = {0.5, 0.2, -0.3, 1.0, 0.4, -0.7};
  s.qdd = {0.1, -0.2, 0.3, -0.1, 0.2, 0.05};
  kane::state<double, 5, 5, 1> d;
  d.q = {0.3, 0.2, 1.0, 2.0, -1.0};
  d.u = {0.5, -1.5, 0.8, 0, 0};
  d.p = {0.25};

  const long before = allocations;
  double sink = 0;
  kane::evaluator<decltype(s), kane::frames<B6>> ev;
  ev.update(s);
  sink += kane::direction_cosines<N, B6>(s)(0, 0);
  sink += kane::express<N>(kane::position<O, End>(), ev)[0];
  sink += kane::express<N>(kane::velocity<N, End>(), ev)[1];
  sink += kane::express<N>(kane::acceleration<N, End>(), ev)[2];
  sink += kane::express<B6>(kane::angular_velocity<N, B6>(), ev)[0];
  sink += kane::express<N>(kane::angular_acceleration<N, B6>(), ev)[1];
  sink += kane::partial_velocities<N>(kane::velocity<N, End>(), ev)(0, 3);
  sink += kane::partial_velocities<N>(kane::angular_velocity<N, B6>(), ev)(2, 5);
  kane::evaluator<decltype(d), kane::frames<R>, kane::level::acceleration, speeds5> ed;
  ed.update(d);
  const auto sol = kane::solve_constraints<rolling>(ed);
  sink += sol.A(0, 1) +
          kane::nonholonomic_partial_velocities<N, rolling>(kane::velocity<N, Centre>(), ed, sol)(1, 1);
  sink += kane::nonholonomic_remainder<N, rolling>(kane::velocity<N, Centre>(), ed, sol)(0);
  const long counted = allocations - before;

  std::printf("allocations during evaluation: %ld (checksum %.6f)\n", counted, sink);
  return counted == 0 ? 0 : 1;
}
