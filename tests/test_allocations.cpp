// The counter of heap allocations (allocations.hpp) counts.
#include <catch2/catch.hpp>

#include <memory>

#include "allocations.hpp"

TEST_CASE("allocations: the counter counts an allocation", "[allocations]") {
  const long before = allocations::count();
  const auto p = std::make_unique<double>(1.5);
  const long allocated = allocations::count() - before;
  CHECK(allocated == 1);
  CHECK(*p == 1.5);
}
