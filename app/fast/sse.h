// Whether the build targets SSE2 (every x86-64 build does): the one test each SIMD path of the
// instructor's build asks (app/fast, app/accel), so that they all agree on when lanes exist.
// SOLUTION-ONLY FILE: not in the student handout, since it is the instructor's build's speed.
#pragma once

#if defined(__SSE2__) || defined(_M_X64) || (defined(_M_IX86_FP) && _M_IX86_FP >= 2)
#define PT_SSE2 1
#include <emmintrin.h>
#else
#define PT_SSE2 0
#endif
