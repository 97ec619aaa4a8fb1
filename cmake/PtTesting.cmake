# pt_add_test(NAME name SOURCES a.cpp ... LABELS part1 ... [LIBS lib ...] [CGAL] [TIMEOUT s])
# One GoogleTest executable, registered with CTest test by test under the given labels, so that
# `ctest -L part1` runs one part and a failing name reads like the syllabus.
include_guard(GLOBAL)
if(PT_BUILD_TESTS)
  enable_testing()
  find_package(GTest REQUIRED)
  include(GoogleTest)
endif()

function(pt_add_test)
  if(NOT PT_BUILD_TESTS)
    return()
  endif()
  cmake_parse_arguments(T "CGAL" "NAME;TIMEOUT" "SOURCES;LABELS;LIBS" ${ARGN})
  if(NOT T_TIMEOUT)
    set(T_TIMEOUT 300)
  endif()
  add_executable(${T_NAME} ${T_SOURCES})
  target_link_libraries(${T_NAME} PRIVATE ${T_LIBS} GTest::gtest GTest::gtest_main GTest::gmock)
  if(T_CGAL)
    # CGAL is header-only and slow to compile: only the tests that check against it see it.
    find_package(CGAL REQUIRED)
    target_link_libraries(${T_NAME} PRIVATE CGAL::CGAL)
  endif()
  target_compile_definitions(${T_NAME} PRIVATE
    PT_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    PT_SHARED_SCENES_DIR="${PROJECT_SOURCE_DIR}/../shared/scenes/cs184"
    PT_SHARED_RAYS_DIR="${PROJECT_SOURCE_DIR}/../shared/rays"
    PT_BINARY_DIR="${PROJECT_BINARY_DIR}")
  gtest_discover_tests(${T_NAME}
    PROPERTIES LABELS "${T_LABELS}" TIMEOUT ${T_TIMEOUT}
    DISCOVERY_TIMEOUT 60)
endfunction()

# pt_add_tests_in(DIR dir LABEL label LIBS lib ... [EXCLUDE regex ...])
# Every *_test.cpp under dir becomes a test executable of its own, labelled `label`;
# *_stress_test.cpp is also labelled `stress`; *_exact_test.cpp is linked with CGAL (and only it,
# since CGAL costs seconds per file to compile). EXCLUDE leaves out a subfolder that builds its
# own tests against other libraries.
function(pt_add_tests_in)
  cmake_parse_arguments(A "" "DIR;LABEL" "LIBS;EXCLUDE" ${ARGN})
  file(GLOB_RECURSE tests CONFIGURE_DEPENDS ${A_DIR}/*_test.cpp)
  foreach(regex ${A_EXCLUDE})
    list(FILTER tests EXCLUDE REGEX "${regex}")
  endforeach()
  foreach(src ${tests})
    get_filename_component(stem ${src} NAME_WE)
    set(labels ${A_LABEL})
    set(extra "")
    if(stem MATCHES "_stress_test$")
      list(APPEND labels stress)
    endif()
    if(stem MATCHES "_exact")
      set(extra CGAL)
    endif()
    pt_add_test(NAME ${A_LABEL}_${stem} SOURCES ${src} LABELS ${labels} LIBS ${A_LIBS} ${extra})
  endforeach()
endfunction()

# pt_add_library_in(NAME lib DIR dir INCLUDE root LIBS dep ... [EXCLUDE regex ...]): a static
# library of every .cpp under dir except tests, application mains and EXCLUDEd subfolders; its
# headers are included relative to `root`.
function(pt_add_library_in)
  cmake_parse_arguments(A "" "NAME;DIR;INCLUDE" "LIBS;EXCLUDE" ${ARGN})
  file(GLOB_RECURSE srcs CONFIGURE_DEPENDS ${A_DIR}/*.cpp)
  list(FILTER srcs EXCLUDE REGEX "_test\\.cpp$")
  list(FILTER srcs EXCLUDE REGEX "/app/")
  list(FILTER srcs EXCLUDE REGEX "/tests/")
  foreach(regex ${A_EXCLUDE})
    list(FILTER srcs EXCLUDE REGEX "${regex}")
  endforeach()
  add_library(${A_NAME} STATIC ${srcs})
  pt_lto_objects(${A_NAME})
  target_include_directories(${A_NAME} PUBLIC ${A_INCLUDE})
  target_link_libraries(${A_NAME} PUBLIC ${A_LIBS})
endfunction()
