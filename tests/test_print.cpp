#include <catch2/catch.hpp>

#include <sstream>

#include <kane/print.hpp>

#include "../examples/models/disc.hpp"
#include "trees.hpp"

using namespace trees;

TEST_CASE("print: frames print by name, vectors and dcms in Kane's notation") {
  STATIC_REQUIRE(kane::type_name<N>() == "N");
  CHECK(kane::frame_name<E>() == "E");
  CHECK(kane::frame_name<E::tree_parent>() == "D''");
  std::ostringstream os;
  os << kane::vec<B>(1, -2, 0.5);
  CHECK(os.str() == "^B(1, -2, 0.5)");
  os.str("");
  state6 s;
  s.q[0] = 0.0;
  os << kane::direction_cosines<N, A>(s);
  CHECK(os.str() == "^N P^A [[1, 0, 0], [-0, 1, 0], [0, 0, 1]]");
}

namespace {
struct L : kane::parameter<1> {};
struct P0 : kane::origin<N> {};
struct P1 : kane::point<P0, 0.5 * kane::e<A, 1>> {};
struct ramp {
  template <class T>
  T operator()(T x) const {
    return x * x;
  }
};
}  // namespace

TEST_CASE("print: expressions print in Kane's notation") {
  using kane::e;
  using kane::q;
  constexpr L l;
  CHECK(kane::to_string(l * kane::dt(q<1>)) == "L*q1'");
  CHECK(kane::to_string(kane::dt(kane::dt(q<2>)) - kane::sin(q<1>) / 2.0) == "q2'' - sin(q1)/2");
  CHECK(kane::to_string(kane::pow<2>(q<1> + q<2>)) == "(q1 + q2)^2");
  CHECK(kane::to_string(kane::cross(l * kane::dt(q<1>) * e<A, 1>, e<B, 2>)) == "(L*q1' a1) x b2");
  CHECK(kane::to_string(kane::angular_velocity<N, C>()) == "^N w^C");
  CHECK(kane::to_string(kane::dt<N>(l * e<A, 1>)) == "^N w^A x (L a1)");
  CHECK(kane::to_string(kane::dt(kane::invoke(ramp{}, q<3>))) == "ramp'(q3)*q3'");
  CHECK(kane::to_string(e<E::tree_parent, 3>) == "d''3");
  CHECK(kane::to_string(kane::position<P0, P1>()) ==
        "0.5 a1");  // a number moved into the type prints as written
  std::ostringstream os;
  os << kane::dt<A>(kane::angular_velocity<N, B>());
  CHECK(os.str() == "^N alpha^B - ^N w^A x ^N w^B");
}

TEST_CASE("print: crosses with one atomic left operand merge at compile time") {
  using kane::e;
  constexpr L l;
  const auto w = kane::angular_velocity<N, A>();
  static_assert(std::is_same_v<decltype(l * kane::cross(w, e<A, 1>) + 2.0 * kane::cross(w, e<B, 2>)),
                               kane::vcross<kane::angular_velocity_of<N, A>,
                                            kane::vsum<kane::scaled<L, kane::unit<A, 1>>,
                                                       kane::scaled<kane::literal, kane::unit<B, 2>>>>>);
  CHECK(kane::to_string(l * kane::cross(w, e<A, 1>) + 2.0 * kane::cross(w, e<B, 2>)) ==
        "^N w^A x (L a1 + 2 b2)");
}

TEST_CASE("print: partial velocities under general speeds print W_sr = dq_s'/du_r and X_s = q_s' at u = 0") {
  using kane::e;
  using kane::q;
  using kane::u;
  // The rolling disc: q1' = u3 / cos q2 and q3' = u2 - tan q2 u3, so W_13 and W_33 are numbers.
  namespace disc = models::disc;
  CHECK(kane::to_string(kane::partial_velocity<disc::speeds3>(disc::w, u<3>)) == "W1_3 y3 + W3_3 r2");
  CHECK(kane::to_string(kane::partial_velocity<disc::speeds5>(kane::dot(disc::v_below, e<disc::N, 1>),
                                                              u<3>)) == "-r_*cos(q1)*W3_3");
  // u1 = q1' + q2', u2 = q2' + t: q1' = u1 - u2 + t, q2' = u2 - t; W_12 = -1 is a number of the
  // evaluator, W_11 = W_22 = 1 and W_21 = 0 are types.
  using sp = kane::speeds<kane::dt(q<1>) + kane::dt(q<2>), kane::dt(q<2>) + kane::t>;
  constexpr auto v = kane::dt(q<1>) * e<A, 1> + kane::dt(q<2>) * e<A, 2>;
  CHECK(kane::to_string(kane::partial_velocity<sp>(v, u<1>)) == "a1");
  CHECK(kane::to_string(kane::partial_velocity<sp>(v, u<2>)) == "W1_2 a1 + a2");
  std::ostringstream os;
  os << kane::velocity_remainder<sp>(v);
  CHECK(os.str() == "X1 a1 + X2 a2");
}

TEST_CASE("print: parameters and inputs named in one line print by their names") {
  static constexpr kane::named_parameter<2, "m"> m;
  static constexpr kane::named_input<1, "T"> T;
  CHECK(kane::to_string(m * kane::q<1> + T) == "m*q1 + T");
  kane::state<double, 1, 1, 2, 1> s;
  s[m] = 3.0;  // p[1]
  s[T] = 0.5;  // r[0]
  s.q = {2.0};
  kane::evaluator<decltype(s), kane::frames<A>, kane::level::pose> ev;
  ev.update(s);
  CHECK(kane::evaluate(m * kane::q<1> + T, ev) == 6.5);
  STATIC_REQUIRE(
      (kane::Parameter<std::remove_cv_t<decltype(m)>> && kane::Input<std::remove_cv_t<decltype(T)>>));
}
