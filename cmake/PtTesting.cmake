# The project's build helpers: a library of a folder, the test executables of a folder.
#
# pt_add_library_in(NAME lib DIR dir LIBS dep ... [EXCLUDE regex ...])
# pt_add_tests_in(DIR dir LABEL label LIBS lib ... [EXCLUDE regex ...] [STEPS] [OUT var])
include_guard(GLOBAL)
# When a test program's tests are listed: at its link (POST_BUILD, a developer's build), or when
# ctest runs (PRE_TEST: the autograder bundle's build, where the program holds the student's code,
# which must not run while the student's user owns the build tree it could rewrite).
set(PT_TEST_DISCOVERY POST_BUILD CACHE STRING "POST_BUILD or PRE_TEST: when gtest_discover_tests lists a test program")
if(PT_BUILD_TESTS)
  enable_testing()
  find_package(GTest REQUIRED)
  include(GoogleTest)
  # Every test executable's main, compiled once (framework/testing/test_main.cpp), and the tree's
  # paths (framework/testing/test_paths.h): the one object that names them, so that the tests'
  # own objects are the same in every tree and a compiler cache shares them. With them, the flag
  # a grader's probe sets (framework/testing/probe_mode.h).
  add_library(pt_test_paths OBJECT ${PROJECT_SOURCE_DIR}/framework/testing/test_paths.cpp
    ${PROJECT_SOURCE_DIR}/framework/testing/probe_mode.cpp)
  target_include_directories(pt_test_paths PRIVATE ${PROJECT_SOURCE_DIR})
  add_library(pt_test_main OBJECT ${PROJECT_SOURCE_DIR}/framework/testing/test_main.cpp)
  target_include_directories(pt_test_main PRIVATE ${PROJECT_SOURCE_DIR})
  target_link_libraries(pt_test_main PUBLIC GTest::gtest)
  set_source_files_properties(${PROJECT_SOURCE_DIR}/framework/testing/test_paths.cpp PROPERTIES
    COMPILE_DEFINITIONS "PT_TEST_SOURCE_DIR=\"${PROJECT_SOURCE_DIR}\";PT_TEST_BINARY_DIR=\"${PROJECT_BINARY_DIR}\"")
endif()

# pt_add_library_in(NAME lib DIR dir LIBS dep ... [EXCLUDE regex ...]): a static library of every
# .cpp under dir except tests (*_test.cpp, tests/), application mains (*_main.cpp) and EXCLUDEd
# subfolders. Every project header is included from the project root
# ("framework/math/ray.h"), so that is the one include folder; LIBS are the layers below it.
function(pt_add_library_in)
  cmake_parse_arguments(A "" "NAME;DIR" "LIBS;EXCLUDE" ${ARGN})
  file(GLOB_RECURSE srcs CONFIGURE_DEPENDS ${A_DIR}/*.cpp)
  list(FILTER srcs EXCLUDE REGEX "_test\\.cpp$")
  list(FILTER srcs EXCLUDE REGEX "_main\\.cpp$")
  list(FILTER srcs EXCLUDE REGEX "/tests/")
  foreach(regex ${A_EXCLUDE})
    list(FILTER srcs EXCLUDE REGEX "${regex}")
  endforeach()
  if(NOT srcs)
    message(FATAL_ERROR "${A_DIR}: no sources for the library ${A_NAME}")
  endif()
  # The objects are a target of their own (NAME_obj), so that the grader's isolated builds
  # (cmake/PtParts.cmake) can put the same objects into another chain of layers without
  # compiling them again; compile options of the library go on NAME_obj.
  add_library(${A_NAME}_obj OBJECT ${srcs})
  target_include_directories(${A_NAME}_obj PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${A_NAME}_obj PUBLIC ${A_LIBS})
  add_library(${A_NAME} STATIC $<TARGET_OBJECTS:${A_NAME}_obj>)
  target_include_directories(${A_NAME} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${A_NAME} PUBLIC ${A_LIBS})
endfunction()

# pt_add_test(NAME name SOURCES a.cpp ... LABELS part1 ... [LIBS lib ...] [CGAL] [TIMEOUT s]
#             [PREFIX p])
# One GoogleTest executable, registered with CTest test by test (named PREFIX + suite.test) under
# the given labels, so that `ctest -L part1` runs one part and a failing name reads like the
# syllabus.
function(pt_add_test)
  if(NOT PT_BUILD_TESTS)
    return()
  endif()
  cmake_parse_arguments(T "CGAL" "NAME;TIMEOUT;PREFIX" "SOURCES;LABELS;LIBS" ${ARGN})
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 300)
  endif()
  # The project's own main (GoogleTest's).
  add_executable(${T_NAME} ${T_SOURCES})
  target_link_libraries(${T_NAME} PRIVATE ${T_LIBS} pt_test_main pt_test_paths GTest::gtest GTest::gmock)
  if(T_CGAL)
    # CGAL is header-only and slow to compile: only the tests that check against it see it.
    find_package(CGAL REQUIRED)
    target_link_libraries(${T_NAME} PRIVATE CGAL::CGAL)
  endif()
  gtest_discover_tests(${T_NAME}
    TEST_PREFIX "${T_PREFIX}"
    PROPERTIES LABELS "${T_LABELS}" TIMEOUT ${T_TIMEOUT}
    DISCOVERY_TIMEOUT 60
    DISCOVERY_MODE ${PT_TEST_DISCOVERY})
  list(LENGTH T_LABELS label_count)
  if(label_count GREATER 1)
    # gtest_discover_tests hands its PROPERTIES on as a flat list, so a second label arrives as
    # a property name of its own and is lost (no test carried `stress`). A file CTest reads after
    # the discovered list sets the whole list on each of this executable's tests.
    set(labels_file "${CMAKE_CURRENT_BINARY_DIR}/${T_NAME}_labels.cmake")
    file(WRITE "${labels_file}" "foreach(t IN LISTS ${T_NAME}_TESTS)\n  set_tests_properties(\"\${t}\" PROPERTIES LABELS \"${T_LABELS}\")\nendforeach()\n")
    set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${labels_file}")
  endif()
endfunction()

# pt_add_tests_in(DIR dir LABEL label LIBS lib ... [EXCLUDE regex ...] [STEPS] [OUT var]
#                 [TARGET_PREFIX t] [TEST_PREFIX p] [NO_STRESS])
# Every *_test.cpp under dir becomes a test executable of its own, labelled `label`;
# *_stress_test.cpp is labelled `stress` and `label_stress` instead (the long, exhaustive
# comparisons: the instructor's CI runs them, a grade does not); *_exact_test.cpp is linked with
# CGAL (and only it, since CGAL costs seconds per file to compile). EXCLUDE leaves out a subfolder
# that builds its own tests against other libraries. STEPS: the folder is a part's tests/, one
# file a step, stepK_NAME_test.cpp (a step's CGAL and long checks in stepK_NAME_exact_test.cpp and
# stepK_NAME_stress_test.cpp), registered as `label.stepK.NAME.test_name`; a file not named so
# is an error. OUT names a variable that receives the targets made. TARGET_PREFIX (default the
# label) starts each executable's name, TEST_PREFIX (default the label) each step test's name;
# NO_STRESS leaves the stress files out (the grader's isolated builds, cmake/PtIsolated.cmake).
# With PT_PROJECT_CHECKS off (a handout), only a part's step tests are made, without its stress
# files: the tests a student's grade runs.
function(pt_add_tests_in)
  cmake_parse_arguments(A "STEPS;NO_STRESS" "DIR;LABEL;OUT;TARGET_PREFIX;TEST_PREFIX" "LIBS;EXCLUDE" ${ARGN})
  if(NOT A_TARGET_PREFIX)
    set(A_TARGET_PREFIX ${A_LABEL})
  endif()
  if(NOT A_TEST_PREFIX)
    set(A_TEST_PREFIX ${A_LABEL})
  endif()
  file(GLOB_RECURSE tests CONFIGURE_DEPENDS ${A_DIR}/*_test.cpp)
  foreach(regex ${A_EXCLUDE})
    list(FILTER tests EXCLUDE REGEX "${regex}")
  endforeach()
  if(NOT PT_PROJECT_CHECKS AND NOT A_STEPS)
    set(tests "")
  endif()
  if(A_NO_STRESS OR NOT PT_PROJECT_CHECKS)
    list(FILTER tests EXCLUDE REGEX "_stress_test\\.cpp$")
  endif()
  set(made "")
  foreach(src ${tests})
    get_filename_component(stem ${src} NAME_WE)
    set(labels ${A_LABEL})
    set(extra "")
    set(prefix "")
    if(stem MATCHES "_stress_test$")
      set(labels stress ${A_LABEL}_stress)
    endif()
    if(stem MATCHES "_exact")
      set(extra CGAL)
    endif()
    if(A_STEPS)
      if(NOT stem MATCHES "^step([0-9]+)_[a-z0-9_]+_test$")
        message(FATAL_ERROR "${src}: a part's test file is named stepK_NAME_test.cpp "
                            "(stepK_NAME_exact_test.cpp, stepK_NAME_stress_test.cpp), after the step it checks")
      endif()
      set(prefix "${A_TEST_PREFIX}.step${CMAKE_MATCH_1}.")
    endif()
    pt_add_test(NAME ${A_TARGET_PREFIX}_${stem} SOURCES ${src} LABELS ${labels} LIBS ${A_LIBS} ${extra}
      PREFIX "${prefix}")
    if(TARGET ${A_TARGET_PREFIX}_${stem})  # none with PT_BUILD_TESTS=OFF (the fuzz tree's)
      list(APPEND made ${A_TARGET_PREFIX}_${stem})
    endif()
  endforeach()
  if(A_OUT)
    set(${A_OUT} ${made} PARENT_SCOPE)
  endif()
endfunction()
