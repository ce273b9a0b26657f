# Installs eomgen from BUILD_DIR into a scratch prefix, then configures, builds
# and runs the consumer project in tests/package against that install tree.
cmake_minimum_required(VERSION 3.25)
set(prefix "${WORK_DIR}/install")
file(REMOVE_RECURSE "${WORK_DIR}")
foreach(step
    "${CMAKE_COMMAND};--install;${BUILD_DIR};--prefix;${prefix}"
    "${CMAKE_COMMAND};-S;${SOURCE_DIR};-B;${WORK_DIR}/consumer;-DCMAKE_PREFIX_PATH=${prefix}"
    "${CMAKE_COMMAND};--build;${WORK_DIR}/consumer"
    "${WORK_DIR}/consumer/consumer"
    "${WORK_DIR}/consumer/runtime_consumer")
  execute_process(COMMAND ${step} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${out}")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "package test step failed: ${step}\n${out}\n${err}")
  endif()
endforeach()

# the regression test passes on the model of its baseline, and fails, with the diff
# report, on a model whose gravity term changed
execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --output-on-failure WORKING_DIRECTORY "${WORK_DIR}/consumer"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the regression test failed on its own baseline:\n${out}\n${err}")
endif()
file(READ "${SOURCE_DIR}/swing.toml" swing)
string(REPLACE "\"-l*cos(phi)\"" "\"-1.01*l*cos(phi)\"" changed "${swing}")
file(WRITE "${WORK_DIR}/changed_swing.toml" "${changed}")
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/consumer -DSWING_MODEL=${WORK_DIR}/changed_swing.toml
                OUTPUT_QUIET)
execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --output-on-failure WORKING_DIRECTORY "${WORK_DIR}/consumer"
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(FIND "${out}" "different: V" names_the_entry)
if(status EQUAL 0 OR names_the_entry EQUAL -1)
  message(FATAL_ERROR "the regression test did not fail on a changed model (status ${status}):\n${out}\n${err}")
endif()
message(STATUS "the regression test fails on a changed model:\n${out}")

# the installed eomgen finds its default model in the install tree's share folder, not in
# the source tree it was built from (run from a folder without models/)
file(MAKE_DIRECTORY "${WORK_DIR}/elsewhere")
execute_process(COMMAND "${prefix}/bin/eomgen" run -o "${WORK_DIR}/elsewhere/run"
                WORKING_DIRECTORY "${WORK_DIR}/elsewhere" RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(FIND "${err}" "eomgen run: ${prefix}/share/eomgen/models/double_pendulum.toml" installed_model)
if(NOT status EQUAL 0 OR installed_model EQUAL -1)
  message(FATAL_ERROR "the installed eomgen run did not use the installed default model (status ${status}):\n${err}")
endif()
message(STATUS "installed eomgen run used ${prefix}/share/eomgen/models/double_pendulum.toml")
