// How evaluation code is inlined in optimized builds (g++ and clang).
#pragma once

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
#ifndef KANE_ALWAYS_INLINE
#if defined(__GNUC__) && defined(__OPTIMIZE__)
#define KANE_ALWAYS_INLINE [[gnu::always_inline]] inline
#else
#define KANE_ALWAYS_INLINE inline
#endif
#endif
