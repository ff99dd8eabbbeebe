// kane's free body (quaternion.hpp, models/free_body.hpp): update at the velocity level, then
// q' and ^N v^P from the evaluator.
#include "../../examples/models/free_body.hpp"
#include "quaternion.hpp"

void quaternion::kane_rates(const input& in, output& out) {
  using namespace models::free_body;
  state s;
  s.q = in.q;
  s.u = in.u;
  s.p = in.p;
  kane::evaluator<state, kane::frames<B>, kane::level::velocity, speeds> ev;
  ev.update(s);
  const auto qd = ev.coordinate_rates();
  for (int i = 0; i < 7; ++i) out.qd[i] = qd[i];
  const auto v = kane::express<N>(kane::velocity<N, P>(), ev);
  out.v[0] = v[0], out.v[1] = v[1], out.v[2] = v[2];
}
