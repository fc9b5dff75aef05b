# cmake -DRT_EXE=path/to/rt -DSCENES_DIR=path/to/scenes -P ExportScenes.cmake
#
# Writes every built-in scene of `rt list` to SCENES_DIR/NAME.json with `rt export`, and removes
# the .json files of scenes that no longer exist, so that scenes/ is exactly the built-in set and
# the scene files written by hand that SCENES_DIR/hand-written.txt lists.
cmake_policy(VERSION 3.20)

foreach(var RT_EXE SCENES_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "ExportScenes.cmake: -D${var}=... is required")
  endif()
endforeach()

execute_process(COMMAND "${RT_EXE}" list OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "'${RT_EXE} list' failed (${rc})")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(names "")
foreach(line IN LISTS lines)
  if(line MATCHES "^([^ ]+)")
    list(APPEND names "${CMAKE_MATCH_1}")
  endif()
endforeach()

file(MAKE_DIRECTORY "${SCENES_DIR}")
foreach(name IN LISTS names)
  execute_process(COMMAND "${RT_EXE}" export "${name}" -o "${SCENES_DIR}/${name}.json"
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "'${RT_EXE} export ${name}' failed (${rc})")
  endif()
endforeach()

set(hand_written "")
if(EXISTS "${SCENES_DIR}/hand-written.txt")
  file(STRINGS "${SCENES_DIR}/hand-written.txt" listed REGEX "^[^#]")
  foreach(file IN LISTS listed)
    string(STRIP "${file}" file)
    list(APPEND hand_written "${file}")
  endforeach()
endif()

file(GLOB existing "${SCENES_DIR}/*.json")
foreach(path IN LISTS existing)
  get_filename_component(name "${path}" NAME_WLE)
  get_filename_component(file "${path}" NAME)
  if(NOT name IN_LIST names AND NOT file IN_LIST hand_written)
    message(STATUS "Removing ${path}: no built-in scene is called ${name}")
    file(REMOVE "${path}")
  endif()
endforeach()
list(LENGTH names count)
message(STATUS "Exported ${count} built-in scenes into ${SCENES_DIR}")
