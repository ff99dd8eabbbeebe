#include <catch2/catch.hpp>

#include <sstream>

#include <kane/io.hpp>

#include "trees.hpp"

using namespace trees;

TEST_CASE("io: frames print by name, vectors and dcms in Kane's notation") {
  STATIC_REQUIRE(kane::frame_name<N>() == "N");
  STATIC_REQUIRE(kane::frame_name<E>() == "E");
  std::ostringstream os;
  os << kane::vec<B>(1, -2, 0.5);
  CHECK(os.str() == "^B(1, -2, 0.5)");
  os.str("");
  state6 s;
  s.q[0] = 0.0;
  os << kane::direction_cosines<N, A>(s);
  CHECK(os.str() == "^N P^A [[1, 0, 0], [-0, 1, 0], [0, 0, 1]]");
}
