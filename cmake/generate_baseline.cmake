cmake_minimum_required(VERSION 3.25)
# Writes or checks the regression baseline: for every models/NAME.toml, the
# canonical equations NAME.txt and the JSON NAME.json, each from its own
# eomgen process (as a user would run it), and the C++ header NAME.hpp.
#
#   cmake -DEOMGEN=path/to/eomgen -DMODELS_DIR=models -DOUT_DIR=generated -P generate_baseline.cmake
#   cmake ... -DCHECK_AGAINST=generated -P generate_baseline.cmake   # regression test
#
# With CHECK_AGAINST, OUT_DIR is a scratch folder; any difference from the
# committed files fails, with the `eomgen diff` report of the equations that changed.
foreach(required EOMGEN MODELS_DIR OUT_DIR)
  if(NOT DEFINED ${required})
    message(FATAL_ERROR "generate_baseline.cmake needs -D${required}=...")
  endif()
endforeach()

file(MAKE_DIRECTORY "${OUT_DIR}")
file(GLOB models RELATIVE "${MODELS_DIR}" "${MODELS_DIR}/*.toml")
list(SORT models)
set(failures 0)
set(expected_files "")
foreach(model_file IN LISTS models)
  get_filename_component(name "${model_file}" NAME_WE)
  foreach(format_ext "text;txt" "json;json" "header;hpp")
    list(GET format_ext 0 format)
    list(GET format_ext 1 ext)
    list(APPEND expected_files "${name}.${ext}")
    if(format STREQUAL "header")
      set(command "${EOMGEN}" generate "models/${model_file}" -o "${OUT_DIR}")
    else()
      set(command "${EOMGEN}" derive "models/${model_file}" --format ${format} -o "${OUT_DIR}/${name}.${ext}")
    endif()
    execute_process(
      COMMAND ${command}
      WORKING_DIRECTORY "${MODELS_DIR}/.."
      RESULT_VARIABLE status ERROR_VARIABLE errors OUTPUT_QUIET)
    if(NOT status EQUAL 0)
      message(SEND_ERROR "eomgen derive models/${model_file} failed (${status}):\n${errors}")
      math(EXPR failures "${failures} + 1")
      continue()
    endif()
    if(DEFINED CHECK_AGAINST)
      if(NOT EXISTS "${CHECK_AGAINST}/${name}.${ext}")
        message(SEND_ERROR "generated/${name}.${ext} is missing: run `cmake --build build --target regenerate` and commit it")
        math(EXPR failures "${failures} + 1")
        continue()
      endif()
      execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${CHECK_AGAINST}/${name}.${ext}" "${OUT_DIR}/${name}.${ext}"
                      RESULT_VARIABLE differs)
      if(NOT differs EQUAL 0)
        if(ext STREQUAL "json")
          # the equations that changed, entry by entry, with old and new and the size of the difference
          execute_process(COMMAND "${EOMGEN}" diff "${CHECK_AGAINST}/${name}.json" "${OUT_DIR}/${name}.json"
                          OUTPUT_VARIABLE report ERROR_VARIABLE report_errors)
          message(NOTICE "generated/${name}.json is out of date:\n${report}${report_errors}")
        else()
          message(NOTICE "generated/${name}.${ext} is out of date (the equations are compared in the report of ${name}.json)")
        endif()
        message(SEND_ERROR "generated/${name}.${ext} differs from what eomgen derives now")
        math(EXPR failures "${failures} + 1")
      endif()
    endif()
  endforeach()
endforeach()

if(DEFINED CHECK_AGAINST)
  file(GLOB committed RELATIVE "${CHECK_AGAINST}" "${CHECK_AGAINST}/*.txt" "${CHECK_AGAINST}/*.json" "${CHECK_AGAINST}/*.hpp")
  foreach(file IN LISTS committed)
    if(NOT file IN_LIST expected_files)
      message(SEND_ERROR "generated/${file} has no model in models/: delete it")
      math(EXPR failures "${failures} + 1")
    endif()
  endforeach()
  if(failures GREATER 0)
    message(FATAL_ERROR "${failures} baseline file(s) differ. If the change is intended, run "
                        "`cmake --build build --target regenerate`, review `git diff generated/` and commit it.")
  endif()
  list(LENGTH models count)
  message(STATUS "generated/ is in sync with all ${count} models")
endif()
