# cmake -DMAKE_MODEL=path/to/make-model -DMODELS_DIR=path/to/scenes/models [-DCHECK_INTO=DIR]
#       -P ModelFiles.cmake
#
# Writes every model file the repository ships into MODELS_DIR with make-model (the target
# model-files); with CHECK_INTO, writes them there instead and fails unless each is byte for byte
# the one in MODELS_DIR (a scene-file test: the shipped models are the project's own output).
cmake_policy(VERSION 3.20)

foreach(var MAKE_MODEL MODELS_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "ModelFiles.cmake: -D${var}=... is required")
  endif()
endforeach()

# Each file and make-model's arguments for it.
set(files teapot.ply)
set(teapot.ply_args teapot 4)

foreach(file IN LISTS files)
  set(out "${MODELS_DIR}/${file}")
  if(DEFINED CHECK_INTO)
    set(out "${CHECK_INTO}/${file}")
  endif()
  execute_process(COMMAND "${MAKE_MODEL}" ${${file}_args} "${out}" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "'${MAKE_MODEL} ${${file}_args} ${out}' failed (${rc})")
  endif()
  if(DEFINED CHECK_INTO)
    execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${out}" "${MODELS_DIR}/${file}"
                    RESULT_VARIABLE differs)
    if(NOT differs EQUAL 0)
      message(FATAL_ERROR "${MODELS_DIR}/${file} is not make-model's output; run: "
                          "cmake --build BUILD --target model-files")
    endif()
  endif()
endforeach()
