# Installs eomgen from BUILD_DIR into a scratch prefix, then configures, builds
# and runs the consumer project in tests/package against that install tree.
cmake_minimum_required(VERSION 3.25)
set(prefix "${WORK_DIR}/install")
file(REMOVE_RECURSE "${WORK_DIR}")
foreach(step
    "${CMAKE_COMMAND};--install;${BUILD_DIR};--prefix;${prefix}"
    "${CMAKE_COMMAND};-S;${SOURCE_DIR};-B;${WORK_DIR}/consumer;-DCMAKE_PREFIX_PATH=${prefix}"
    "${CMAKE_COMMAND};--build;${WORK_DIR}/consumer"
    "${WORK_DIR}/consumer/consumer")
  execute_process(COMMAND ${step} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${out}")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "package test step failed: ${step}\n${out}\n${err}")
  endif()
endforeach()
