// How evaluation code is inlined in optimized builds (g++ and clang).
#pragma once

#include <type_traits>

#include "kane/detail/lane_traits.hpp"

// Entry points of evaluation inline their whole expression tree: common
// subexpressions of one call meet in one function body (at -O2 too).
#ifndef KANE_FLATTEN
#if defined(__GNUC__) && defined(__OPTIMIZE__)
#define KANE_FLATTEN [[gnu::flatten]]
#else
#define KANE_FLATTEN
#endif
#endif

// Small entry points whose callers gain from seeing them whole (a call would
// spill every live register): inlined into the caller as well.
#ifndef KANE_INLINE_FLATTEN
#if defined(__GNUC__) && defined(__OPTIMIZE__)
#define KANE_INLINE_FLATTEN [[gnu::flatten, gnu::always_inline]] inline
#else
#define KANE_INLINE_FLATTEN inline
#endif
#endif

// A building block that must disappear into its caller even where that
// caller is itself inlined (flatten applies only to a function's own body).
// g++ 12: only for leaves and for code whose callees are always-inline too. g++ orders
// early inlining without the calls an always-inline function makes to other
// functions, so such a callee may still lack its summary when a flattened entry
// point reaches it, and be cloned by IPA-SRA before the late flattening, which
// cannot inline a clone: it stays a call. Functions that take callbacks
// (with_common_subexpressions, Kane's sums per item) are plain inline.
#ifndef KANE_ALWAYS_INLINE
#if defined(__GNUC__) && defined(__OPTIMIZE__)
#define KANE_ALWAYS_INLINE [[gnu::always_inline]] inline
#else
#define KANE_ALWAYS_INLINE inline
#endif
#endif

// The same for a lambda: [&](auto i) KANE_ALWAYS_INLINE_LAMBDA { ... }.
#ifndef KANE_ALWAYS_INLINE_LAMBDA
#if defined(__GNUC__) && defined(__OPTIMIZE__)
#define KANE_ALWAYS_INLINE_LAMBDA __attribute__((always_inline))
#else
#define KANE_ALWAYS_INLINE_LAMBDA
#endif
#endif

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {
// b, its value hidden from the optimizer: code that selects by it is not duplicated along the
// paths where earlier branches decided it (jump threading), so stores after it stay on one path.
KANE_ALWAYS_INLINE bool opaque(bool b) {
#if defined(__GNUC__)
  int v = b;
  __asm__("" : "+r"(v));
  return v != 0;
#else
  return b;
#endif
}
// f() in one function body when S is a number or lanes of numbers; other scalars (jets) keep
// their calls, whose flattened bodies would multiply the compile's cost.
template <class S, class F>
requires(std::is_floating_point_v<S> || lane_traits<S>::width > 1) KANE_FLATTEN decltype(auto) flat(F&& f) {
  return f();
}
template <class S, class F>
decltype(auto) flat(F&& f) {
  return f();
}
}  // namespace kane::detail
#pragma GCC diagnostic pop
