// Structure-of-arrays buffers as x and dx/dt (scalars/soa_block.hpp): the lanes' own numbers, and a
// buffer one may write for dx/dt.
// Each case is a misuse (#ifdef) and its fix (#else): the file as it is compiles every fix.
// case soa_block_of_floats: kane: soa_block<L> takes lanes L .kane::lanes<S, W>. and a buffer of their numbers S
// case soa_block_written_const: kane: a soa_block of const numbers is read only .x.. give dx/dt a buffer one may write
#include <array>

#include <kane/scalars/soa_block.hpp>

using L = kane::lanes<double, 2>;

double use() {
#ifdef KANE_CASE_soa_block_of_floats
  std::array<float, 6> in{};
#else
  std::array<double, 6> in{};
#endif
  const L a = kane::soa_block<L>(in.data(), 3, 0)[1];
  std::array<double, 6> out{};
#ifdef KANE_CASE_soa_block_written_const
  const double* to = out.data();
#else
  double* to = out.data();
#endif
  auto dx = kane::soa_block<L>(to, 3, 0);
  dx[2] = a + L(1.0);
  return out[5];
}
