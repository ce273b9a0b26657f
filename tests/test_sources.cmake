# The test sources, kept once: the main test binary (tests/CMakeLists.txt) compiles them all, the
# sanitizer build (CMakeLists.txt, EOMGEN_FUZZ) those marked `sanitized` (they link the generator
# alone: no executable, runtime or compiler), and each file's label is its tests' CTest label:
#   fast     unit tests, each under a second (`ctest -L fast`)
#   slow     unit tests of which some take longer (they compile generated code, run long simulations)
#   cli      tests that start the eomgen executable
#   support  not tests: helpers and the registry of generated headers
set(EOMGEN_TEST_FILES
  support/test_support.cpp                          support  sanitized
  support/expanded_oracle.cpp                       support  sanitized
  generated/header_registry.cpp                     support
  generated/scalar_types.cpp                        support
  generated/generated_header_test.cpp               fast
  generator/parse/parse_model_file_test.cpp         fast     sanitized
  generator/model/expression_parser_test.cpp        fast     sanitized
  generator/model/frames_test.cpp                   slow     sanitized
  generator/model/joints_test.cpp                   fast     sanitized
  generator/model/frame_joints_test.cpp             slow     sanitized
  generator/spatial/joint_frames_test.cpp           fast     sanitized
  generator/spatial/joint_tree_dynamics_test.cpp    fast     sanitized
  generator/spatial/joint_tree_derivatives_test.cpp slow
  generator/spatial/gradient_frames_test.cpp       fast
  generator/spatial/joint_tree_forward_dynamics_test.cpp slow
  generator/spatial/tree_constraints_test.cpp       slow     sanitized
  generator/spatial/spherical_joints_test.cpp       fast     sanitized
  generator/import/model_writer_test.cpp            fast     sanitized
  generator/import/loop_import_test.cpp             fast     sanitized
  generator/import/urdf_import_test.cpp             fast     sanitized
  generator/import/gravity_compensation_test.cpp    fast     sanitized
  generator/import/inherited_ranges_test.cpp        fast     sanitized
  generator/import/joint_force_limits_test.cpp      fast     sanitized
  generator/import/newer_mjcf_test.cpp              fast     sanitized
  generator/import/servo_damping_test.cpp           fast     sanitized
  generator/import/option_forces_test.cpp           fast     sanitized
  generator/import/joint_follower_import_test.cpp   fast     sanitized
  generator/import/missing_meshes_test.cpp          fast     sanitized
  generator/import/missing_textures_test.cpp        fast     sanitized
  generator/import/actuator_reasons_test.cpp        fast     sanitized
  generator/import/massless_bodies_test.cpp         fast     sanitized
  generator/import/unbalanced_inertias_test.cpp     fast     sanitized
  generator/import/automatic_limits_test.cpp        fast     sanitized
  generator/import/frame_elements_test.cpp          fast     sanitized
  generator/import/keyframe_text_test.cpp           fast     sanitized
  generator/import/free_base_test.cpp               fast     sanitized
  generator/import/right_angles_test.cpp            fast     sanitized
  generator/import/rounding_noise_test.cpp          fast     sanitized
  generator/symbolic/clamp_test.cpp                 fast     sanitized
  generator/symbolic/cse_test.cpp                   fast     sanitized
  generator/symbolic/expression_cost_test.cpp       fast     sanitized
  generator/symbolic/magnitude_test.cpp             fast     sanitized
  generator/symbolic/rotation_angle_test.cpp        fast     sanitized
  generator/common/independent_rows_test.cpp        fast     sanitized
  generator/common/output_file_test.cpp             fast
  generator/symbolic/simplify_test.cpp              fast     sanitized
  generator/symbolic/trig_orientation_test.cpp      fast     sanitized
  generator/symbolic/trig_rational_test.cpp         fast     sanitized
  generator/compare/equation_diff_test.cpp          fast     sanitized
  generator/kinematics/angular_velocity_test.cpp    fast     sanitized
  generator/kinematics/rolling_contact_test.cpp     fast     sanitized
  generator/derive/lagrange2_test.cpp               fast     sanitized
  generator/derive/articulated_bodies_test.cpp      slow
  generator/derive/particle_tree_terms_test.cpp     fast     sanitized
  generator/derive/constrained_derivation_test.cpp  fast     sanitized
  generator/derive/hamilton_test.cpp                slow
  generator/derive/first_integrals_test.cpp         fast     sanitized
  generator/derive/quadratic_kinetic_energy_test.cpp fast
  generator/derive/routh_test.cpp                   fast     sanitized
  generator/derive/reduced_models_test.cpp          fast     sanitized
  generator/derive/angle_coordinates_test.cpp       fast     sanitized
  runtime/constrained_simulation_test.cpp           fast
  runtime/quaternion_simulation_test.cpp            fast
  runtime/turning_symmetries_test.cpp               fast
  runtime/deviation_norms_test.cpp                  fast
  runtime/state_check_test.cpp                      fast
  runtime/reference_test.cpp                        slow
  generator/symbolic_analysis/stability_conditions_test.cpp   fast     sanitized
  generator/symbolic_analysis/hamilton_jacobi_test.cpp        fast
  generator/symbolic_analysis/exact_jordan_test.cpp           fast     sanitized
  generator/symbolic_analysis/closed_form_solution_test.cpp   fast     sanitized
  generator/symbolic_analysis/deformed_shapes_test.cpp        fast     sanitized
  generator/symbolic_analysis/term_pruning_test.cpp           fast     sanitized
  generator/emit/formats_test.cpp                   fast     sanitized
  generator/emit/cpp_constant_test.cpp              slow
  generator/emit/tangent_sweep_test.cpp             fast
  generator/emit/statement_order_test.cpp           fast
  generator/emit/math_usings_test.cpp               fast
  generator/emit/ldlt_test.cpp                      fast
  generator/emit/avx_dispatch_test.cpp              fast
  generator/emit/register_allocation_test.cpp       fast
  generator/emit/dynamics_form_test.cpp             fast
  generator/emit/zero_entries_test.cpp              fast
  generator/emit/robot_header_size_test.cpp         fast
  generator/emit/split_units_test.cpp               slow
  generator/emit/sin_cos_test.cpp                   slow
  runtime/simulate_test.cpp                         cli
  runtime/linear_system_test.cpp                    fast
  runtime/symplectic_integrators_test.cpp           fast
  runtime/linear_stability_test.cpp                 fast
  runtime/scale_free_stability_test.cpp             slow
  runtime/critical_case_runs_test.cpp               slow
  runtime/scale_free_sweeps_test.cpp                fast
  runtime/scale_free_linear_test.cpp                fast
  runtime/random_sweeps_test.cpp                    fast
  runtime/random_systems_test.cpp                   fast
  runtime/stability_map_test.cpp                    fast
  runtime/degree_colours_test.cpp                   fast
  runtime/ensemble_test.cpp                         fast
  runtime/animation_test.cpp                        fast
  runtime/step_stability_test.cpp                   fast
  runtime/excited_modes_test.cpp                    fast
  runtime/simulation_budget_test.cpp                fast
  runtime/stiffness_ratio_test.cpp                  fast
  runtime/local_power_law_test.cpp                  fast
  runtime/output_interval_test.cpp                  fast
  studies/stability_studies_test.cpp                slow
  studies/run_studies_test.cpp                      slow
  cli/equilibrium_search_test.cpp                   cli
  cli/first_order_search_test.cpp                   cli
  cli/stability_command_test.cpp                    cli
  cli/angles_beside_lengths_test.cpp                cli
  cli/at_completion_test.cpp                        cli
  cli/turning_symmetry_test.cpp                     cli
  cli/trustworthy_analysis_test.cpp                 cli
  cli/routh_stability_test.cpp                      cli
  cli/linear_command_test.cpp                       cli
  cli/linear_symbolic_test.cpp                      cli
  cli/scene_command_test.cpp                        cli
  cli/fmu_test.cpp                                  cli
  cli/eigenvalue_sweep_test.cpp                     cli
  cli/whipple_bicycle_test.cpp                      cli
  cli/hostile_input_test.cpp                        cli
  cli/definitions_test.cpp                          cli
  cli/diff_command_test.cpp                         cli
  cli/derive_command_test.cpp                       cli
  cli/bench_command_test.cpp                        cli
  cli/failure_scenes_test.cpp                       cli
  cli/determinism_test.cpp                          slow
  cli/error_files_test.cpp                          cli
  cli/distributed_runs_test.cpp                     cli
  cli/ensemble_command_test.cpp                     cli
  cli/readme_test.cpp                               cli
)

# EOMGEN_TEST_SOURCES_<LABEL>: the files of a label; EOMGEN_SANITIZED_TEST_SOURCES: the sanitizer build's
set(EOMGEN_SANITIZED_TEST_SOURCES "")
set(entries ${EOMGEN_TEST_FILES})
while(entries)
  list(POP_FRONT entries file label)
  string(TOUPPER ${label} label)
  list(APPEND EOMGEN_TEST_SOURCES_${label} ${file})
  list(LENGTH entries left)
  if(left GREATER 0)
    list(GET entries 0 next)
    if(next STREQUAL "sanitized")
      list(POP_FRONT entries)
      list(APPEND EOMGEN_SANITIZED_TEST_SOURCES ${file})
    endif()
  endif()
endwhile()

# The gtest filter of the files' suites: TEST(Suite, …), TEST_F, TEST_P and instantiations Prefix/Suite.
# A suite in files of two labels would be discovered twice: refused.
function(eomgen_test_filter label out)
  set(patterns "")
  foreach(file IN LISTS EOMGEN_TEST_SOURCES_${label})
    file(STRINGS ${CMAKE_CURRENT_LIST_DIR}/${file} lines REGEX "^ *TEST(_F|_P)?\\( *[A-Za-z0-9_]+ *,")
    foreach(line IN LISTS lines)
      string(REGEX REPLACE "^ *TEST(_F|_P)?\\( *([A-Za-z0-9_]+) *,.*" "\\2" suite "${line}")
      if(DEFINED eomgen_suite_label_${suite} AND NOT eomgen_suite_label_${suite} STREQUAL label)
        message(FATAL_ERROR "test suite ${suite} is in ${label} and ${eomgen_suite_label_${suite}} files of "
                            "tests/test_sources.cmake: give it one label, or rename it")
      endif()
      set(eomgen_suite_label_${suite} ${label} PARENT_SCOPE)
      set(eomgen_suite_label_${suite} ${label})
      list(APPEND patterns "${suite}.*" "*/${suite}.*")
    endforeach()
  endforeach()
  list(REMOVE_DUPLICATES patterns)
  string(REPLACE ";" ":" filter "${patterns}")
  set(${out} "${filter}" PARENT_SCOPE)
endfunction()
