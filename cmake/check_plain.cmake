# What a student reads is plain (docs/architecture.md): framework/, pipeline/ and parts/ hold one
# scalar definition of each operation, with no SIMD intrinsics and no instruction-set branches.
#   cmake -DPT_SOURCE_DIR=<project> -P cmake/check_plain.cmake
# Fails (a non-zero exit, each offending line named) on an intrinsics header, an _mm intrinsic or
# __builtin_ia32 call, a vector type (__m64, __m128, __m256, __m512, NEON's float32x4_t ...) or an
# instruction-set macro (__AVX*, __SSE*, __ARM_NEON, __FMA__, PT_ISA, PT_SSE2) in any of their
# .h, .hpp or .cpp files. The speed of the instructor's build lives in app/fast and app/accel.
#   cmake -DPT_SOURCE_DIR=<scratch> -DPT_SELF_TEST=ON -P cmake/check_plain.cmake
# writes one file per forbidden form under <scratch>/framework and fails unless each is caught.
cmake_minimum_required(VERSION 3.22)
if(NOT PT_SOURCE_DIR)
  message(FATAL_ERROR "check_plain.cmake: pass -DPT_SOURCE_DIR=<the project folder>")
endif()

set(forbidden
  "#[ \t]*include[ \t]*<[a-z]*intrin\\.h>"
  "#[ \t]*include[ \t]*<arm_neon\\.h>"
  "_mm[0-9]*_[a-z]"
  "__builtin_ia32_"
  "__m(64|128|256|512)"
  "(float|int|uint)(8|16|32|64)x[0-9]+_t"
  "__(AVX|SSE|FMA)[A-Z0-9_]*"
  "__ARM_NEON"
  "PT_ISA"
  "PT_SSE2")
string(JOIN "|" pattern ${forbidden})

if(PT_SELF_TEST)
  # (no semicolon inside a sample: it would split the list)
  set(samples "#include <immintrin.h>" "#include <arm_neon.h>" "x = _mm256_add_ps(a, b)"
      "__builtin_ia32_addps(a, b)" "__m128 v" "float32x4_t v" "#ifdef __AVX2__" "#if __SSE4_1__"
      "#ifdef __ARM_NEON" "#if PT_ISA_AVX2" "#if PT_SSE2")
  file(REMOVE_RECURSE ${PT_SOURCE_DIR}/framework)
  set(i 0)
  foreach(sample IN LISTS samples)
    file(WRITE ${PT_SOURCE_DIR}/framework/sample${i}.h "// a sample\n${sample}\n")
    math(EXPR i "${i} + 1")
  endforeach()
  file(WRITE ${PT_SOURCE_DIR}/framework/plain.h "// plain: glm::vec3 m128, int mm_count, SSE in prose\n")
endif()

set(violations "")
set(files_with 0)
foreach(top framework parts pipeline)
  file(GLOB_RECURSE files RELATIVE ${PT_SOURCE_DIR}
       ${PT_SOURCE_DIR}/${top}/*.h ${PT_SOURCE_DIR}/${top}/*.hpp ${PT_SOURCE_DIR}/${top}/*.cpp)
  foreach(rel ${files})
    file(STRINGS ${PT_SOURCE_DIR}/${rel} lines REGEX "${pattern}")
    if(lines)
      math(EXPR files_with "${files_with} + 1")
    endif()
    foreach(line IN LISTS lines)
      string(STRIP "${line}" line)
      list(APPEND violations "${rel}: ${line}")
    endforeach()
  endforeach()
endforeach()

if(PT_SELF_TEST)
  list(LENGTH samples want)
  if(NOT files_with EQUAL want)
    message(FATAL_ERROR "check_plain.cmake: caught ${files_with} of the ${want} forbidden samples "
                        "(and the plain file must not be caught):\n${violations}")
  endif()
  message(STATUS "check_plain.cmake: each of the ${want} forbidden forms caught, the plain file not")
  return()
endif()
if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "framework/, pipeline/ and parts/ are read by students and stay plain scalar "
                      "C++ (docs/architecture.md); the instructor's build's lanes belong in app/fast "
                      "or app/accel:\n  ${text}")
endif()
message(STATUS "check_plain.cmake: no intrinsics or instruction-set branches in framework/, "
               "pipeline/ or parts/")
