// The stub a student function starts with: say once, by name, that it is not written yet.
#pragma once

#include <atomic>
#include <cstdio>

/// Put at the top of a stub. Prints "part N not implemented: NAME" to stderr the first time the
/// stub runs (once per stub, not once per pixel), then the stub returns its neutral value.
#define PT_STUDENT_TODO(part, name)                                                          \
  do {                                                                                       \
    static std::atomic<bool> pt_warned_{false};                                              \
    if (!pt_warned_.exchange(true))                                                          \
      std::fprintf(stderr, "%s not implemented: %s (see the STUDENT comment there)\n", part, \
                   name);                                                                    \
  } while (0)
