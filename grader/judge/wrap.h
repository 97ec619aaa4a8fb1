// How a probe reaches the student's functions and a test's calls reach the probe's recorders:
// the probe is linked with --wrap=SYMBOL for every graded function (cmake/PtJudge.cmake reads the
// symbols from the PT_WRAP labels of record_partN.cpp), so the linker sends every call made from
// outside the function's own object to __wrap_SYMBOL, and __real_SYMBOL is the student's
// definition. The labels are the functions' C++ names as the compiler spells them in objects.
#pragma once

#define PT_WRAP(symbol) asm("__wrap_" symbol)
#define PT_REAL(symbol) asm("__real_" symbol)
