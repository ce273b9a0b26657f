# eomgen_generate(TARGET <target> MODELS <model.toml>... [OUTPUT_DIR <dir>])
#
# Generates the self-contained C++ header of each model file and makes it
# available to <target>: the header of models/robot.toml is robot.hpp in
# OUTPUT_DIR (default: ${CMAKE_CURRENT_BINARY_DIR}/eomgen_generated), which is
# added to the target's include path. A header is regenerated when its model
# file or the eomgen executable changes. The namespace inside is
# eomgen::models::NAME, with NAME the [model] name of the file.
#
# Example:
#   find_package(eomgen REQUIRED)
#   add_executable(controller controller.cpp)
#   eomgen_generate(TARGET controller MODELS ${CMAKE_CURRENT_SOURCE_DIR}/cart_pendulum.toml)
#   # controller.cpp: #include "cart_pendulum.hpp"
function(eomgen_generate)
  cmake_parse_arguments(EOMGEN "" "TARGET;OUTPUT_DIR" "MODELS" ${ARGN})
  if(NOT EOMGEN_TARGET)
    message(FATAL_ERROR "eomgen_generate: TARGET is required")
  endif()
  if(NOT EOMGEN_MODELS)
    message(FATAL_ERROR "eomgen_generate: MODELS needs at least one model file")
  endif()
  if(EOMGEN_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "eomgen_generate: unknown arguments ${EOMGEN_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT TARGET eomgen::eomgen)
    message(FATAL_ERROR "eomgen_generate: the eomgen::eomgen executable is not known; call find_package(eomgen) first")
  endif()
  if(NOT EOMGEN_OUTPUT_DIR)
    set(EOMGEN_OUTPUT_DIR "${CMAKE_CURRENT_BINARY_DIR}/eomgen_generated")
  endif()
  file(MAKE_DIRECTORY "${EOMGEN_OUTPUT_DIR}")
  foreach(model IN LISTS EOMGEN_MODELS)
    get_filename_component(model_path "${model}" ABSOLUTE)
    get_filename_component(stem "${model}" NAME_WE)
    set(header "${EOMGEN_OUTPUT_DIR}/${stem}.hpp")
    add_custom_command(
      OUTPUT "${header}"
      COMMAND eomgen::eomgen generate "${model_path}" --header "${header}"
      DEPENDS "${model_path}" "$<TARGET_FILE:eomgen::eomgen>"
      COMMENT "eomgen: generating ${stem}.hpp from ${model}"
      VERBATIM)
    target_sources(${EOMGEN_TARGET} PRIVATE "${header}")
  endforeach()
  target_include_directories(${EOMGEN_TARGET} PRIVATE "${EOMGEN_OUTPUT_DIR}")
endfunction()

# eomgen_add_regression_test(NAME <test> MODEL <model.toml> BASELINE <model.json>)
#
# A CTest test that derives the model and compares its equations with the committed
# baseline by `eomgen diff BASELINE MODEL`: it passes when they are identical,
# equivalent or give the same motion, and fails with the diff report (the entries
# that changed, old and new, and by how much) when they differ. The baseline is the
# JSON of `eomgen derive MODEL --format json`; after an intended change refresh it
# with the target <test>_refresh (`cmake --build build --target <test>_refresh`),
# review `git diff` of the baseline, and commit it.
function(eomgen_add_regression_test)
  cmake_parse_arguments(EOMGEN "" "NAME;MODEL;BASELINE" "" ${ARGN})
  foreach(required NAME MODEL BASELINE)
    if(NOT EOMGEN_${required})
      message(FATAL_ERROR "eomgen_add_regression_test: ${required} is required")
    endif()
  endforeach()
  if(EOMGEN_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "eomgen_add_regression_test: unknown arguments ${EOMGEN_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT TARGET eomgen::eomgen)
    message(FATAL_ERROR "eomgen_add_regression_test: the eomgen::eomgen executable is not known; call find_package(eomgen) first")
  endif()
  get_filename_component(model "${EOMGEN_MODEL}" ABSOLUTE)
  get_filename_component(baseline "${EOMGEN_BASELINE}" ABSOLUTE)
  add_test(NAME ${EOMGEN_NAME} COMMAND eomgen::eomgen diff "${baseline}" "${model}")
  add_custom_target(${EOMGEN_NAME}_refresh
    COMMAND eomgen::eomgen derive "${model}" --format json -o "${baseline}"
    COMMENT "eomgen: refreshing the baseline ${baseline} from ${model}"
    VERBATIM)
endfunction()
