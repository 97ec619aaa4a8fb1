# pt_add_part(N DIR): one part of the course and the given code that sits on it, as two layers.
#
#   pt_partN      parts/DIR/*.cpp: the student's functions; links the layer below (the previous
#                 part's pipeline library, or pt_framework for Part 1)
#   pt_pipelineN  pipeline/DIR/*.cpp (when the folder exists): the given code on Part N; links
#                 pt_partN. Its *_test.cpp files are tests labelled `pipeline`.
#   tests         parts/DIR/tests/stepK_NAME_test.cpp, labelled partN, named partN.stepK.NAME.*
#   grade_partN   what `grader --part N` builds: the renderer, the part's layers, its tests
#
# Each layer links only the layers below it, so a call the wrong way (a part calling a later
# part, the framework calling a part) fails to link. Call it once per part, in order: the list in
# parts/CMakeLists.txt is the one list of parts.
include_guard(GLOBAL)

set_property(GLOBAL PROPERTY PT_TOP_LAYER pt_framework)

function(pt_add_part index dir)
  set(part_dir ${PROJECT_SOURCE_DIR}/parts/${dir})
  set(pipeline_dir ${PROJECT_SOURCE_DIR}/pipeline/${dir})
  get_property(below GLOBAL PROPERTY PT_TOP_LAYER)

  pt_add_library_in(NAME pt_part${index} DIR ${part_dir} LIBS ${below})
  set(top pt_part${index})
  set(pipeline_tests "")
  if(EXISTS ${pipeline_dir})
    pt_add_library_in(NAME pt_pipeline${index} DIR ${pipeline_dir} LIBS pt_part${index})
    pt_add_tests_in(DIR ${pipeline_dir} LABEL pipeline LIBS pt_pipeline${index})
    set(top pt_pipeline${index})
  endif()
  # A part's tests may use the given code on it (Part 2's tests build trees with pipeline/2-bvh).
  pt_add_tests_in(DIR ${part_dir}/tests LABEL part${index} LIBS ${top} STEPS OUT part_tests)

  # The renderer is made by app/, after the parts: a target named before it exists is fine.
  add_custom_target(grade_part${index})
  add_dependencies(grade_part${index} ${top} pathtracer ${part_tests})

  set_property(GLOBAL PROPERTY PT_TOP_LAYER ${top})
  set_property(GLOBAL APPEND PROPERTY PT_PARTS ${index})
  # What the grader's isolated builds (cmake/PtIsolated.cmake) put together again.
  set_property(GLOBAL PROPERTY PT_PART${index}_DIR ${dir})
  if(EXISTS ${pipeline_dir})
    set_property(GLOBAL PROPERTY PT_PART${index}_PIPELINE pt_pipeline${index})
  endif()
endfunction()
