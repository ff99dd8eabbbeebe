// Evaluating kinematics allocates nothing: the global allocation functions
// are replaced by counting ones, and the kernels of benchmarks/embedded.cpp
// (everything of the 6-revolute arm; the rolling disc's constraints and
// nonholonomic partial velocities) run between two readings of the counter.
// A plain program (no test framework allocating in between).
#include <cstdio>
#include <cstdlib>
#include <new>

extern "C" void arm_step(const double* q, const double* qd, const double* qdd, double* out);
extern "C" int disc_step(const double* q, const double* u, double radius, double* out);

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

int main() {
  const double q[6] = {0.1, -0.4, 0.8, 0.3, -1.2, 0.6}, qd[6] = {0.5, 0.2, -0.3, 1.0, 0.4, -0.7},
               qdd[6] = {0.1, -0.2, 0.3, -0.1, 0.2, 0.05};
  const double dq[5] = {0.3, 0.2, 1.0, 2.0, -1.0}, du[5] = {0.5, -1.5, 0.8, 0, 0};
  double arm[42], disc[18];

  const long before = allocations;
  arm_step(q, qd, qdd, arm);
  const int status = disc_step(dq, du, 0.25, disc);
  const long counted = allocations - before;

  double sink = 0;
  for (double x : arm) sink += x;
  for (double x : disc) sink += x;
  std::printf("allocations during evaluation: %ld (checksum %.6f)\n", counted, sink);
  return counted == 0 && status == 0 ? 0 : 1;
}
