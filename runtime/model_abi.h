/* @file The plain-C interface of a compiled model: what `eomgen simulate`
 * loads from the shared object it builds around a generated header. The same
 * text is embedded in eomgen and written beside each driver, so a driver
 * needs nothing but the generated header and this file. */
#ifndef EOMGEN_MODEL_ABI_H
#define EOMGEN_MODEL_ABI_H

#include <stddef.h>

#define EOMGEN_MODEL_ABI_VERSION 7

#ifdef __cplusplus
extern "C" {
#endif

typedef void (*eomgen_state_function)(double t, const double* x, const double* u, const double* p, double* out);
typedef void (*eomgen_configuration_function)(double t, const double* x, const double* p, double* out);
typedef double (*eomgen_energy_function)(double t, const double* x, const double* p);
typedef void (*eomgen_stabilized_function)(double t, const double* x, const double* u, const double* p, double alpha,
                                           double beta, double* out);
typedef void (*eomgen_residual_function)(double t, const double* x, const double* p, double* position, double* velocity);
typedef void (*eomgen_parameter_function)(const double* p, double* out);
typedef void (*eomgen_linearization_function)(double t, const double* x, const double* u, const double* p, double* P,
                                              double* Q, double* B);

struct eomgen_model_abi {
  int abi_version;
  const char* name;
  const char* build_key; /* the cache key the shared object was built for */
  size_t num_coordinates, num_velocities, num_states, num_parameters, num_inputs, num_outputs;
  const char* const* parameter_names;
  const char* const* coordinate_names;
  const char* const* state_names;
  const char* const* velocity_definitions; /* each velocity of the state in der(q): der(q), or a pseudo-velocity's definition */
  const char* const* input_names;
  const char* const* output_names;
  const double* default_parameters;
  const double* default_state;
  const double* default_inputs;
  int conserves_energy_without_inputs;
  const bool* is_cyclic;
  const bool* is_angle; /* sized one radian in any units (the analyses' tolerances) */
  eomgen_state_function rhs, jacobian_state, jacobian_input, forcing, outputs;
  eomgen_configuration_function mass_matrix;
  eomgen_energy_function kinetic_energy, potential_energy;
  eomgen_linearization_function linearization;
  /* constraints (num_constraints = 0 without them); multipliers of Lagrange I */
  const char* method;
  size_t num_constraints, num_multipliers;
  const char* const* constraint_names;
  const bool* constraint_is_holonomic;
  const char* const* multiplier_names;
  double baumgarte_alpha, baumgarte_beta;
  eomgen_configuration_function constraint_jacobian;
  eomgen_residual_function constraint_residuals;
  eomgen_state_function multipliers;
  eomgen_stabilized_function rhs_stabilized, jacobian_state_stabilized;
  /* the first integrals at zero inputs: generalized energy, momenta of cyclic coordinates */
  size_t num_first_integrals;
  const char* const* first_integral_names;
  eomgen_configuration_function first_integrals;
  int separable_hamiltonian; /* Hamilton's equations with H = T(p) + V(q) */
  /* ball and free joints: the coordinates w, x, y, z of each quaternion, 4 per quaternion */
  size_t num_quaternions;
  const size_t* quaternion_coordinates;
  /* what `eomgen animate` draws: bodies (12 numbers of body_poses each: position, R row by row),
     their kinds and parents (-1: the ground), shapes on them (18 numbers each), and gravity (3) */
  size_t num_drawn_bodies;
  const char* const* drawn_body_names;
  const int* drawn_body_kinds;
  const int* drawn_body_parents;
  size_t num_drawn_shapes;
  const int* drawn_shape_bodies;
  const int* drawn_shape_types;
  eomgen_configuration_function body_poses;
  eomgen_parameter_function drawn_shapes, gravity;
};

#ifdef __cplusplus
}

/* The interface of the model in namespace eomgen::models::NAME, built for cache key KEY. */
#define EOMGEN_MODEL_ABI_OF(NAME, KEY)                                                                 \
  namespace m = eomgen::models::NAME;                                                                  \
  static const eomgen_model_abi abi = {EOMGEN_MODEL_ABI_VERSION, #NAME, KEY, m::num_coordinates,       \
      m::num_velocities, m::num_states, m::num_parameters, m::num_inputs, m::num_outputs,              \
      m::parameter_names.data(), m::coordinate_names.data(), m::state_names.data(),                    \
      m::velocity_definitions.data(),                                                                  \
      m::input_names.data(), m::output_names.data(), m::default_parameters.data(),                     \
      m::default_state.data(), m::default_inputs.data(), m::conserves_energy_without_inputs ? 1 : 0,   \
      m::is_cyclic.data(), m::is_angle.data(), m::rhs<double>, m::jacobian_state<double>,              \
      m::jacobian_input<double>, m::forcing<double>, m::outputs<double>, m::mass_matrix<double>,       \
      m::kinetic_energy<double>, m::potential_energy<double>, m::linearization<double>, m::method,     \
      m::num_constraints, m::num_multipliers, m::constraint_names.data(),                              \
      m::constraint_is_holonomic.data(),                                                               \
      m::multiplier_names.data(), m::baumgarte_alpha, m::baumgarte_beta, m::constraint_jacobian<double>, \
      m::constraint_residuals<double>, m::multipliers<double>, m::rhs_stabilized<double>,              \
      m::jacobian_state_stabilized<double>, m::num_first_integrals, m::first_integral_names.data(),      \
      m::first_integrals<double>, m::separable_hamiltonian ? 1 : 0, m::num_quaternions,                \
      m::quaternion_coordinates.data(), m::num_drawn_bodies, m::drawn_body_names.data(),               \
      m::drawn_body_kinds.data(), m::drawn_body_parents.data(), m::num_drawn_shapes,                   \
      m::drawn_shape_bodies.data(), m::drawn_shape_types.data(), m::body_poses<double>,                \
      m::drawn_shapes<double>, m::gravity<double>};                                                    \
  return &abi;

/* Defines `eomgen_model()`, the entry point of a compiled model's shared object. */
#define EOMGEN_MODEL_ENTRY(NAME, KEY) \
  extern "C" const eomgen_model_abi* eomgen_model() { EOMGEN_MODEL_ABI_OF(NAME, KEY) }

/* The same, as a function with another name, for linking a model into a program. */
#define EOMGEN_MODEL_FUNCTION(FUNCTION, NAME) \
  inline const eomgen_model_abi* FUNCTION() { EOMGEN_MODEL_ABI_OF(NAME, "") }
#endif

#endif /* EOMGEN_MODEL_ABI_H */
