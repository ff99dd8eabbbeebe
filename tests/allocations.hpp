// The number of heap allocations so far in the unit-test binary (allocations.cpp): a test reads it before
// and after a call that must not allocate, with no test macro in between.
#pragma once

namespace allocations {
long count();
}
