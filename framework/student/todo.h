// Not needed for the assignment.
// The stub a student function starts with: say once, by name and place, that it is not written yet.
#pragma once

#include <atomic>
#include <cstdio>
#include <string_view>

namespace pt::student {

/// A stub's file from the project's root ("parts/1-raygen/camera_ray.cpp"): the compiler's
/// __FILE__ is an absolute path of the build machine, and stubs live only under parts/.
inline const char* project_relative(const char* file) {
  const std::string_view path(file);
  const size_t at = path.rfind("/parts/");
  if (at != std::string_view::npos) return file + at + 1;
  return file;  // already relative (or not a part: said as it is)
}

}  // namespace pt::student

/// The line a stub prints (part, name, file, line): the grader quotes a line of the student's
/// output only when it equals one of the handout's stubs' lines in this form.
#define PT_STUDENT_TODO_FORMAT "%s not implemented: %s at %s:%d (see the STUDENT comment there)"

/// Put at the top of a stub. Prints "part N not implemented: NAME at FILE:LINE" to stderr the
/// first time the stub runs (once per stub, not once per pixel), FILE relative to the project,
/// then the stub returns its neutral value.
#define PT_STUDENT_TODO(part, name)                                                           \
  do {                                                                                        \
    static std::atomic<bool> pt_warned_{false};                                               \
    if (!pt_warned_.exchange(true))                                                           \
      std::fprintf(stderr, PT_STUDENT_TODO_FORMAT "\n",                                         \
                   part, name, ::pt::student::project_relative(__FILE__), __LINE__);          \
  } while (0)
