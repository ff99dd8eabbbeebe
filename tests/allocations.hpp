// The number of heap allocations so far in a test binary that links allocations.cpp: a test reads it
// before and after a call that must not allocate, with nothing else in between.
#pragma once

namespace allocations {
long count();
}
