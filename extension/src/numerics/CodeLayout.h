// b2analytic: hints on where the compiler puts code (internal).
#pragma once

// A warm contact runs a few thousand instructions spread over many functions, once per contact
// among other contacts' code: what it costs beyond its instructions is largely the instruction
// cache lines it needs (docs/benchmarks.md has the figures). These keep a path's rare branches
// and repeated helpers from adding lines to it.
#if defined(__GNUC__)
/// Never inlined: one copy of a helper that a path calls from several places.
#define B2A_NOINLINE __attribute__((noinline))
/// Never inlined and laid out with the cold code: a rare fallback (its callers' branches to it
/// are taken as unlikely).
#define B2A_COLD __attribute__((noinline, cold))
/// Always inlined: a small step whose state would otherwise pass through memory at every call.
#define B2A_FORCE_INLINE __attribute__((always_inline))
#else
#define B2A_NOINLINE
#define B2A_COLD
#define B2A_FORCE_INLINE
#endif
