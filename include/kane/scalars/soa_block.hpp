// W states of a structure-of-arrays buffer as x or dx/dt of a right-hand side over lanes. Number i of
// state k lies at data[i * stride + k]; entry i of the block is the W numbers of states first ..
// first + W - 1, loaded and stored in place by the call, with no copy of x or dx/dt in between.
//
//   using L = kane::lanes<double, 8>;
//   double x[14 * 64], xd[14 * 64];                // 64 states of 14 numbers
//   for (std::size_t k = 0; k < 64; k += 8)
//     rhs(kane::soa_block<L>(x, 64, k), kane::soa_block<L>(xd, 64, k), t);
//
// A buffer's rows hold a multiple of W numbers: a batch of other size pads its last block.
#pragma once

#include <cstddef>
#include <type_traits>

#include "kane/detail/inline.hpp"
#include "kane/scalars/lanes.hpp"

namespace kane {
namespace detail {
// The view: T, the lanes' real numbers (const: x alone)
template <class L, class T>
class soa_view {
  T* p_;
  std::size_t stride_;

 public:
  // a view: it writes through copies of itself (a temporary as dx/dt)
  static constexpr bool writes_through = true;
  // entry i as an lvalue: written by a store, read by a load
  struct entry {
    T* p;
    template <class V>
    KANE_ALWAYS_INLINE entry& operator=(const V& v) {
      static_assert(!std::is_const_v<T>,
                    "kane: a soa_block of const numbers is read only (x); give dx/dt a buffer one may write");
      L(v).store(p);
      return *this;
    }
    KANE_ALWAYS_INLINE entry& operator=(const entry& e) { return *this = L(e); }
    KANE_ALWAYS_INLINE operator L() const { return L::load(p); }  // NOLINT: reads as a number
  };
  KANE_ALWAYS_INLINE soa_view(T* data, std::size_t stride, std::size_t first)
      : p_(data + first), stride_(stride) {}
  KANE_ALWAYS_INLINE L operator[](std::size_t i) const { return L::load(p_ + i * stride_); }
  KANE_ALWAYS_INLINE entry operator[](std::size_t i) { return {p_ + i * stride_}; }
};
}  // namespace detail

// The block of states first .. first + W - 1 of the buffer data (rows of stride numbers), W the
// width of L: as x if T is const, as x or dx/dt otherwise.
template <class L, class T>
KANE_ALWAYS_INLINE detail::soa_view<L, T> soa_block(T* data, std::size_t stride, std::size_t first) {
  static_assert(
      lane_traits<L>::width > 1 && std::is_same_v<std::remove_const_t<T>, typename real_type<L>::type>,
      "kane: soa_block<L> takes lanes L (kane::lanes<S, W>) and a buffer of their numbers S");
  return {data, stride, first};
}

}  // namespace kane
