cmake_minimum_required(VERSION 3.25)
# CI's share of the sanitizer and fuzz builds (tests/README.md, "Two builds look for what tests cannot
# see"): the generator built by clang with AddressSanitizer and UndefinedBehaviorSanitizer, its
# unit tests run under them, then the libFuzzer target for FUZZ_SECONDS from the seed corpus
# (models/ and tests/errors/). A sanitizer report, a failed test, a crash or a slow input fails.
#
#   cmake -DSOURCE_DIR=. -DWORK_DIR=build/fuzz -DCLANGXX=clang++ -DFUZZ_SECONDS=60 \
#         -P tests/fuzz/run_fuzz_and_sanitized_tests.cmake
foreach(required SOURCE_DIR WORK_DIR CLANGXX FUZZ_SECONDS)
  if(NOT DEFINED ${required})
    message(FATAL_ERROR "run_fuzz_and_sanitized_tests.cmake needs -D${required}=...")
  endif()
endforeach()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status})")
  endif()
endfunction()

set(build "${WORK_DIR}/build")
message(STATUS "building the generator with clang, ASan and UBSan in ${build}")
run("configuring the sanitizer build"
    ${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${build}" -DCMAKE_CXX_COMPILER=${CLANGXX} -DEOMGEN_FUZZ=ON
    -DCMAKE_BUILD_TYPE=Release -DEOMGEN_BUILD_TESTS=OFF)
run("building the sanitizer build" ${CMAKE_COMMAND} --build "${build}" -j 2 --target model_file_fuzzer sanitized_generator_tests)

set(sanitizers "LSAN_OPTIONS=suppressions=${SOURCE_DIR}/tests/sanitizer/lsan.supp"
               "UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1")
# the seven comparisons of long chains with their expanded derivation took 194 s of the 248 s under
# ASan (2026-11-28): each runs the code paths of the lighter tests (frames, joints, followers, tree
# constraints, which stay, with JointTree.RecursionsGiveTheExpandedEquations) on larger expressions
# for tens of seconds; the main test run keeps them. So do the three comparisons of trees read from
# rotations with their models written out, 223 s of 359 (2026-11-30; FrameJoints' lighter tests
# stay). So do the arm written with rotations, the shutter on a fixed link and three robot diffs,
# 121 s of 219 (2026-12-01; the fixed leaves' fold and the tree and robot-file diffs stay)
set(slow_under_asan
    EquationDiff.ARobotRestatedToItsRoundingIsEquivalentWithinATolerance
    EquationDiff.ARobotOnAFreeJointIsComparedInItsQuantities
    EquationDiff.RobotsAreComparedInTheirTreesQuantities
    JointTree.AFixedLinkCarryingAJointFoldsIntoItsJointsLink
    FrameJoints.AnArmWrittenWithRotationsIsTheArmWrittenWithJoints
    FrameJoints.TheTreeGivesTheExpandedDerivatives
    FrameJoints.TheTreeGivesTheExpandedEquations
    FrameJoints.RouthAndDiffTakeTheModelWrittenOut
    TreeConstraints.ThroughTheFramesTheyAreThoseOfTheExpandedDerivation
    TreeConstraints.AJointThatFollowsACoordinateGivesTheExpandedConstraints
    Frames.ChainThroughFramesEqualsTheChainWrittenOut
    Frames.RecursiveKinematicsGivesTheEquationsOfTheChainWrittenOut
    JointTree.JointsThatFollowACoordinateHaveTheExpandedDerivatives
    JointTree.JointsThatFollowACoordinateGiveTheExpandedEquations
    JointTree.ClosedFormDerivativesAreThoseOfTheExpandedEquations)
list(JOIN slow_under_asan ":" left_out)
list(LENGTH slow_under_asan left_out_count)
message(STATUS "the generator's unit tests under the sanitizers, all but ${left_out_count} long comparisons")
run("the generator's unit tests under ASan and UBSan"
    ${CMAKE_COMMAND} -E env ${sanitizers} "${build}/sanitized_generator_tests" "--gtest_filter=-${left_out}")

# a fresh corpus each run, so a finding comes from this commit's code
file(REMOVE_RECURSE "${WORK_DIR}/corpus")
file(MAKE_DIRECTORY "${WORK_DIR}/corpus" "${WORK_DIR}/findings")
message(STATUS "fuzzing for ${FUZZ_SECONDS} s; findings go to ${WORK_DIR}/findings")
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env ${sanitizers}
          "${build}/model_file_fuzzer" "${WORK_DIR}/corpus" "${SOURCE_DIR}/models" "${SOURCE_DIR}/tests/errors"
          -dict=${SOURCE_DIR}/tests/fuzz/model_file.dict -max_len=4096 -timeout=10 -rss_limit_mb=3072
          -max_total_time=${FUZZ_SECONDS} -print_final_stats=1 -artifact_prefix=${WORK_DIR}/findings/
  RESULT_VARIABLE status ERROR_VARIABLE log)
string(REGEX MATCHALL "stat::[a-z_]+: *[0-9]+" stats "${log}")
string(REGEX MATCH "#[0-9]+[ \t]+DONE[^\n]*" done "${log}")
message(STATUS "fuzz: ${done}")
foreach(line IN LISTS stats)
  message(STATUS "fuzz: ${line}")
endforeach()
if(NOT status EQUAL 0)
  file(GLOB findings "${WORK_DIR}/findings/*")
  string(LENGTH "${log}" length)
  math(EXPR from "${length} - 6000")
  if(from LESS 0)
    set(from 0)
  endif()
  string(SUBSTRING "${log}" ${from} -1 tail)
  message(FATAL_ERROR "the fuzzer found a failure (${status}): ${findings}\n${tail}\n"
                      "Make the input a file in tests/errors/ with its expected diagnostic, and fix it.")
endif()
