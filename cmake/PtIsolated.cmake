# pt_add_isolated_grading(): the targets `grader --part N --isolated` builds, so that only part
# N's student code is graded and a bug in one part never costs points in another.
#
#   grade_partN_isolated  part N's objects from parts/ (the student's), every earlier part's
#                         compiled from the complete solution in PT_SOLUTION_DIR/parts/, every
#                         later part's from the handout's stubs in PT_STUB_DIR/parts/ (or, without
#                         stubs, from the solution too), the given code (framework, pipeline/,
#                         app/) from this tree, linked into pt_isolatedN; on it
#                         pathtracer_isolatedN, with which part N's renders are graded (its tests
#                         are graded by their probes and judges, grader/judge/CMakeLists.txt,
#                         which link the earlier parts the same way and no later one)
#   pathtracer_solution   every part from the solution: the references of the renders' variants
#
# PT_SOLUTION_DIR is a copy of the project with the complete solution, kept where the student's
# code cannot change it (the autograder bundle's own copy; a mutant run's pristine tree). Left
# empty, or naming this tree, the solution is this tree: every part is already the solution's,
# so grade_partN_isolated is grade_partN and the grader grades the ordinary targets.
#
# A part's renders use no later part (Part 1's are normals by brute force; Part 3's are direct
# light, with no path and no adaptive loop), so the bundle (PT_STUB_DIR set) links the later parts'
# stubs: a process that runs part N's code holds no solution of a part its checks do not use.
#
# The solution's part files are compiled against this tree's headers (the given headers are the
# same in both: they hold no solution), so the objects of every other layer are reused as they
# are and only part files and links are added.
include_guard(GLOBAL)

set(PT_SOLUTION_DIR "" CACHE PATH
    "A copy of the project holding the complete solution, for `grader --isolated` (empty: this tree)")
# The link options of a program that links a student's objects: no link-time compile of anything
# an object carries (GCC's linker plugin would run the compiler on it with the grader's rights).
set(PT_NO_LINK_TIME_CODE $<$<CXX_COMPILER_ID:GNU>:-fno-lto>)
set(PT_STUB_DIR "" CACHE PATH
    "A folder holding the handout's stubs under parts/, linked for the parts after the graded one")

function(pt_add_isolated_grading)
  get_property(parts GLOBAL PROPERTY PT_PARTS)
  set(solution "")
  if(PT_SOLUTION_DIR)
    get_filename_component(solution "${PT_SOLUTION_DIR}" REALPATH)
    get_filename_component(here "${PROJECT_SOURCE_DIR}" REALPATH)
    if(solution STREQUAL here)
      set(solution "")
    elseif(NOT EXISTS "${solution}/parts")
      message(FATAL_ERROR "PT_SOLUTION_DIR=${PT_SOLUTION_DIR}: no parts/ folder there")
    endif()
  endif()
  if(NOT solution)
    foreach(n ${parts})
      add_custom_target(grade_part${n}_isolated)
      add_dependencies(grade_part${n}_isolated grade_part${n})
    endforeach()
    return()
  endif()

  set(stubs "")
  if(PT_STUB_DIR)
    get_filename_component(stubs "${PT_STUB_DIR}" REALPATH)
  endif()

  # The solution's part objects, and the stubs' where there are stubs, once per part.
  set(below pt_framework)
  foreach(k ${parts})
    get_property(dir GLOBAL PROPERTY PT_PART${k}_DIR)
    set(kinds solution)
    if(stubs)
      list(APPEND kinds stub)
    endif()
    foreach(kind ${kinds})
      if(kind STREQUAL "solution")
        set(from ${solution})
      else()
        set(from ${stubs})
      endif()
      file(GLOB srcs CONFIGURE_DEPENDS ${from}/parts/${dir}/*.cpp)
      if(NOT srcs)
        string(TOUPPER "PT_${kind}_DIR" variable)
        message(FATAL_ERROR "${variable}: ${from}/parts/${dir} has no sources")
      endif()
      add_library(pt_${kind}_part${k}_obj OBJECT ${srcs})
      target_include_directories(pt_${kind}_part${k}_obj PUBLIC ${PROJECT_SOURCE_DIR})
      target_link_libraries(pt_${kind}_part${k}_obj PUBLIC ${below})
    endforeach()
    get_property(pipeline GLOBAL PROPERTY PT_PART${k}_PIPELINE)
    set(below pt_part${k})
    if(pipeline)
      set(below ${pipeline})
    endif()
  endforeach()

  # A renderer of the parts' objects `part_objects`: the given code's layers on them (the app, the
  # wide tree, the fast light sampling), linked into an archive `lib` and the executable `exe`.
  function(pt_renderer_of lib exe)
    set(objects ${ARGN})
    set(defines "")
    if(TARGET pt_accel)
      list(APPEND objects $<TARGET_OBJECTS:pt_accel_obj>)
      list(APPEND defines PT_HAVE_WIDE_BVH=1)
    endif()
    if(TARGET pt_fast)
      list(APPEND objects $<TARGET_OBJECTS:pt_fast_obj>)
      list(APPEND defines PT_HAVE_FAST_LIGHTS=1)
    endif()
    list(APPEND objects $<TARGET_OBJECTS:pt_app_obj>)
    # One archive of every layer above the framework: the linker takes from it what is called.
    add_library(${lib} STATIC ${objects})
    target_include_directories(${lib} PUBLIC ${PROJECT_SOURCE_DIR})
    target_link_libraries(${lib} PUBLIC pt_framework CLI11::CLI11)
    target_compile_definitions(${lib} PUBLIC ${defines})
    add_executable(${exe} ${PROJECT_SOURCE_DIR}/app/pathtracer_main.cpp
                          ${PROJECT_SOURCE_DIR}/app/command_line.cpp)
    target_link_libraries(${exe} PRIVATE ${lib})
    target_link_options(${exe} PRIVATE ${PT_NO_LINK_TIME_CODE})  # it links the student's objects
  endfunction()

  set(solution_objects "")
  foreach(n ${parts})
    set(objects "")
    foreach(k ${parts})
      if(k EQUAL n)
        list(APPEND objects $<TARGET_OBJECTS:pt_part${k}_obj>)
      elseif(k GREATER n AND stubs)
        list(APPEND objects $<TARGET_OBJECTS:pt_stub_part${k}_obj>)
      else()
        list(APPEND objects $<TARGET_OBJECTS:pt_solution_part${k}_obj>)
      endif()
      get_property(pipeline GLOBAL PROPERTY PT_PART${k}_PIPELINE)
      if(pipeline)
        list(APPEND objects $<TARGET_OBJECTS:${pipeline}_obj>)
        if(k EQUAL n)
          list(APPEND solution_objects $<TARGET_OBJECTS:${pipeline}_obj>)
        endif()
      endif()
    endforeach()
    list(APPEND solution_objects $<TARGET_OBJECTS:pt_solution_part${n}_obj>)
    pt_renderer_of(pt_isolated${n} pathtracer_isolated${n} ${objects})
    add_custom_target(grade_part${n}_isolated)
    add_dependencies(grade_part${n}_isolated pathtracer_isolated${n})
  endforeach()

  # The complete solution's renderer: the references of a graded render's variant are rendered
  # with it at grading time (grader/scene_variant.h).
  pt_renderer_of(pt_solution pathtracer_solution ${solution_objects})
endfunction()
