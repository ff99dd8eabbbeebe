// kane's small models (small_models.hpp), written as the README teaches: the system, its speed
// set, and kane::motion<System, Speeds> (the system's own evaluator) called per state.
#include "../../examples/models/gyrostat.hpp"
#include "../../examples/models/heavy_top.hpp"
#include "../../examples/models/pendulum_absolute.hpp"
#include "small_models.hpp"

namespace {
using kane::dot;
using kane::e;
using kane::literal;
template <std::size_t I>
using q = kane::coordinate<I>;

namespace top {
namespace m = models::heavy_top;
kane::motion<m::system, m::speeds> motion{m::state{}};
}  // namespace top

namespace spacecraft {
namespace m = models::gyrostat;
kane::motion<m::system, m::speeds> motion{m::state{}};
}  // namespace spacecraft

namespace pendulum {
struct N : kane::root_frame {};
struct A : kane::frame<N, kane::simple<kane::axis::z, q<1>>> {};
struct B : kane::frame<A, kane::simple<kane::axis::z, q<2>>> {};
struct O : kane::origin<N> {};
struct P1 : kane::point<O, literal(1.2) * e<A, 1>> {};
struct P2 : kane::point<P1, literal(0.8) * e<B, 1>> {};
using system = kane::system<kane::particle<P1, literal(1.0)>, kane::particle<P2, literal(0.7)>,
                            kane::gravity<literal(9.81) * e<N, 1>>>;
kane::motion<system> motion{kane::state_of<system>{}};
}  // namespace pendulum

namespace pendulum_absolute {  // B turned from N by q2, as a textbook writes it
namespace m = models::pendulum_absolute;
kane::motion<m::system> motion{kane::state_of<m::system>{}};
}  // namespace pendulum_absolute

// the status as the checked twins give it: 0 ok
template <class Motion, class In, class Out>
void call(Motion& motion, const In& in, Out& out) {
  motion(in.x, out.xd, 0.0);
  out.status = motion.status() == kane::solve_status::ok ? 0 : 1;
}
}  // namespace

void small::top_kane(const top_in& in, top_out& out) { call(top::motion, in, out); }
void small::spacecraft_kane(const spacecraft_in& in, spacecraft_out& out) {
  call(spacecraft::motion, in, out);
}
void small::pendulum_kane(const pendulum_in& in, pendulum_out& out) { call(pendulum::motion, in, out); }
void small::pendulum_absolute_kane(const pendulum_in& in, pendulum_out& out) {
  call(pendulum_absolute::motion, in, out);
}
