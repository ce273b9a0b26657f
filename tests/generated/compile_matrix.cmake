# Every header in generated/ compiles alone, with every function instantiated
# for double and the right-hand side for long double (the wide path of the
# constants that no small fraction states, detail::constant), with each compiler
# in COMPILERS and each standard in STANDARDS, under -Wall -Wextra -Wpedantic
# -Werror. No header is skipped, however large (the bicycle's is 0.9 MB).
#   cmake -DHEADERS_DIR=generated -DCOMPILERS="g++;clang++" -DSTANDARDS="c++17;c++20" -DWORK_DIR=... -P compile_matrix.cmake
cmake_minimum_required(VERSION 3.25)
file(GLOB headers "${HEADERS_DIR}/*.hpp")
list(SORT headers)
file(MAKE_DIRECTORY "${WORK_DIR}")
set(failures 0)
set(count 0)
foreach(header IN LISTS headers)
  get_filename_component(name "${header}" NAME_WE)
  set(source "${WORK_DIR}/${name}_alone.cpp")
  file(WRITE "${source}" "#include \"${header}\"
namespace m = eomgen::models::${name};
template void m::mass_matrix<double>(double, const double*, const double*, double*);
template void m::forcing<double>(double, const double*, const double*, const double*, double*);
template void m::rhs<double>(double, const double*, const double*, const double*, double*);
template void m::rhs<long double>(long double, const long double*, const long double*, const long double*, long double*);
template void m::jacobian_state<double>(double, const double*, const double*, const double*, double*);
template void m::jacobian_input<double>(double, const double*, const double*, const double*, double*);
template double m::kinetic_energy<double>(double, const double*, const double*);
template double m::potential_energy<double>(double, const double*, const double*);
template void m::outputs<double>(double, const double*, const double*, const double*, double*);
template void m::linearization<double>(double, const double*, const double*, const double*, double*, double*, double*);
template void m::first_integrals<double>(double, const double*, const double*, double*);
template void m::body_poses<double>(double, const double*, const double*, double*);
template void m::drawn_shapes<double>(const double*, double*);
template void m::gravity<double>(const double*, double*);
template struct m::Parameters<double>;
")
  foreach(compiler IN LISTS COMPILERS)
    foreach(standard IN LISTS STANDARDS)
      execute_process(
        COMMAND ${compiler} -std=${standard} -Wall -Wextra -Wpedantic -Werror -fsyntax-only "${source}"
        RESULT_VARIABLE status ERROR_VARIABLE errors)
      math(EXPR count "${count} + 1")
      if(NOT status EQUAL 0)
        message(NOTICE "${name}.hpp with ${compiler} -std=${standard}:\n${errors}")
        math(EXPR failures "${failures} + 1")
      endif()
    endforeach()
  endforeach()
endforeach()
if(failures GREATER 0)
  message(FATAL_ERROR "${failures} of ${count} header compilations failed")
endif()
message(STATUS "${count} header compilations passed (${COMPILERS} x ${STANDARDS})")
