# The profile-guided build's options refuse what they cannot do, with a message naming it:
#   cmake -DPT_SOURCE_DIR=... -DPT_SCRATCH_DIR=... -P cmake/check_pgo_options.cmake
# A PT_PGO that is not empty, generate or use; a compiler that is not GCC (where clang++ is
# installed); tools/build_pgo.sh given an argument. Each must stop at once and say why.

function(expect_refusal what pattern)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 0)
    message(FATAL_ERROR "${what}: accepted (exit 0), expected a refusal\n${out}${err}")
  endif()
  if(NOT "${out}${err}" MATCHES "${pattern}")
    message(FATAL_ERROR "${what}: refused (exit ${rc}) without saying '${pattern}':\n${out}${err}")
  endif()
  message(STATUS "${what}: refused, saying '${pattern}'")
endfunction()

file(REMOVE_RECURSE ${PT_SCRATCH_DIR})
expect_refusal("PT_PGO=sometimes" "PT_PGO must be empty, generate or use, not 'sometimes'"
  ${CMAKE_COMMAND} -S ${PT_SOURCE_DIR} -B ${PT_SCRATCH_DIR}/bad-value -DPT_PGO=sometimes)

find_program(clangxx NAMES clang++)
if(clangxx)
  expect_refusal("PT_PGO=use with clang++" "set up for GCC only, not Clang"
    ${CMAKE_COMMAND} -S ${PT_SOURCE_DIR} -B ${PT_SCRATCH_DIR}/clang -DPT_PGO=use
    -DCMAKE_CXX_COMPILER=${clangxx})
else()
  message(STATUS "no clang++ here: the other-compiler case is not checked")
endif()

expect_refusal("tools/build_pgo.sh --fast" "build_pgo: takes no arguments \\(got '--fast'\\)"
  bash ${PT_SOURCE_DIR}/tools/build_pgo.sh --fast)
file(REMOVE_RECURSE ${PT_SCRATCH_DIR})
