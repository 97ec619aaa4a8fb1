# The folders are layers, and every #include "..." goes down or stays level (docs/architecture.md).
#   cmake -DPT_SOURCE_DIR=<project> -P cmake/check_layers.cmake
# Fails (a non-zero exit, each offending line named) when a file includes a header of a layer
# above its own, or a project header by anything but its project-rooted path; or when a source
# file in a part's folder holds no student function (given code belongs in pipeline/).
#
# The layers, bottom up, and what a file in each may include besides its own layer:
#   framework/               nothing above it
#   parts/N-*/               the framework, parts/M-* and pipeline/M-* of earlier parts (M < N)
#   parts/N-*/tests/         also pipeline/N-* (a part's tests may use the given code on it)
#   pipeline/N-*/            the framework, parts/M-* and pipeline/M-* with M <= N
#   app/                     every layer above (framework, parts, pipeline)
#   grader/ website/ scenes/ the framework only (they run the pathtracer as a process), and
#                            grader/process/ (the keeper and its limits: the tools' own layer,
#                            which includes the framework only and no numbered layer includes,
#                            but a test that runs a program)
#   grader/judge/            the probes and judges of the parts' tests: every numbered layer
#                            (framework, parts, pipeline), as app/ does; nothing includes it
#   fuzz/                    the framework only (the loader under a fuzzer)
cmake_minimum_required(VERSION 3.22)
if(NOT PT_SOURCE_DIR)
  message(FATAL_ERROR "check_layers.cmake: pass -DPT_SOURCE_DIR=<the project folder>")
endif()

# The layer of a project path, as a number (parts and pipeline interleave: part N is 2N - 1, its
# pipeline 2N), and the top-level tool folders as a name of their own.
function(pt_layer_of path out)
  if(path MATCHES "^framework/")
    set(${out} 0 PARENT_SCOPE)
  elseif(path MATCHES "^parts/([0-9]+)-[^/]+/tests/")
    math(EXPR level "2 * ${CMAKE_MATCH_1}")
    set(${out} ${level} PARENT_SCOPE)
  elseif(path MATCHES "^parts/([0-9]+)-")
    math(EXPR level "2 * ${CMAKE_MATCH_1} - 1")
    set(${out} ${level} PARENT_SCOPE)
  elseif(path MATCHES "^pipeline/([0-9]+)-")
    math(EXPR level "2 * ${CMAKE_MATCH_1}")
    set(${out} ${level} PARENT_SCOPE)
  elseif(path MATCHES "^app/")
    set(${out} 1000 PARENT_SCOPE)
  elseif(path MATCHES "^grader/judge/")
    set(${out} 999 PARENT_SCOPE)
  elseif(path MATCHES "^grader/process/")
    set(${out} process PARENT_SCOPE)
  elseif(path MATCHES "^(grader|website|scenes|fuzz)/")
    set(${out} ${CMAKE_MATCH_1} PARENT_SCOPE)
  else()
    set(${out} "" PARENT_SCOPE)
  endif()
endfunction()

set(violations "")
set(checked 0)
foreach(top framework parts pipeline app grader website scenes fuzz)
  file(GLOB_RECURSE files RELATIVE ${PT_SOURCE_DIR}
       ${PT_SOURCE_DIR}/${top}/*.h ${PT_SOURCE_DIR}/${top}/*.hpp ${PT_SOURCE_DIR}/${top}/*.cpp)
  list(FILTER files EXCLUDE REGEX "/node_modules/")
  foreach(rel ${files})
    pt_layer_of(${rel} from)
    file(STRINGS ${PT_SOURCE_DIR}/${rel} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
    foreach(line IN LISTS lines)
      if(NOT line MATCHES "\"([^\"]+)\"")
        continue()
      endif()
      set(target ${CMAKE_MATCH_1})
      math(EXPR checked "${checked} + 1")
      pt_layer_of(${target} to)
      if(to STREQUAL "" OR NOT EXISTS ${PT_SOURCE_DIR}/${target})
        list(APPEND violations "${rel}: #include \"${target}\" is not a project-rooted path of a project header")
        continue()
      endif()
      if(from MATCHES "^(grader|website|scenes|fuzz|process)$")
        if(NOT (to STREQUAL "0" OR to STREQUAL from OR (to STREQUAL "process" AND NOT from STREQUAL "fuzz")))
          list(APPEND violations "${rel}: #include \"${target}\": ${from}/ may include only the framework, grader/process and itself")
        endif()
      elseif(to STREQUAL "process" AND rel MATCHES "_test\\.cpp$")
        # A test of any layer may run a program under the keeper (it links pt_process itself).
      elseif(to MATCHES "^(grader|website|scenes|fuzz|process)$")
        list(APPEND violations "${rel}: #include \"${target}\": the layers never include a tool (${to}/)")
      elseif(to GREATER from)
        list(APPEND violations "${rel}: #include \"${target}\": a layer above this file's own")
      endif()
    endforeach()
  endforeach()
endforeach()

# A part's folder holds the student's files: every source file there has a student function.
file(GLOB part_sources RELATIVE ${PT_SOURCE_DIR} ${PT_SOURCE_DIR}/parts/*/*.cpp)
foreach(rel ${part_sources})
  file(STRINGS ${PT_SOURCE_DIR}/${rel} marks REGEX "^[ \t]*// BEGIN SOLUTION")
  if(NOT marks)
    list(APPEND violations "${rel}: no student function (no BEGIN SOLUTION block): given code belongs in pipeline/")
  endif()
endforeach()

list(LENGTH violations count)
if(count GREATER 0)
  string(REPLACE ";" "\n  " text "${violations}")
  message(FATAL_ERROR "${count} line(s) go against the layers:\n  ${text}")
endif()
message(STATUS "layers: ${checked} includes checked, none goes up")
