#include "kinematics/rolling_contact.hpp"

#include "kinematics/mechanics.hpp"
#include "symbolic/evaluate.hpp"
#include "symbolic/simplify.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// e at the initial state with the parameters at their defaults
double at_initial_state(const ex& e, const Symbols& s) {
  return evaluate(e, [&](const GiNaC::symbol& x) -> double {
    for (std::size_t i = 0; i < s.coordinates.size() && i < s.initial_coordinates.size(); ++i)
      if (x == s.coordinates[i]) return s.initial_coordinates[i];
    for (std::size_t i = 0; i < s.parameters.size(); ++i)
      if (x == s.parameters[i]) return s.parameter_defaults[i];
    return 0;
  });
}

// √(1 − n_z²), exactly when n_z is ±sin a or ±cos a, with the sign it has at the initial state
ex in_plane_length(const ex& nz, const Symbols& s) {
  ex bare = nz;
  if (GiNaC::is_a<GiNaC::mul>(bare) && bare.nops() == 2 && bare.op(1).is_equal(-1)) bare = bare.op(0);
  if (GiNaC::is_a<GiNaC::mul>(bare) && bare.nops() == 2 && bare.op(0).is_equal(-1)) bare = bare.op(1);
  ex root = GiNaC::sqrt(1 - GiNaC::pow(nz, 2));
  if (GiNaC::is_exactly_a<GiNaC::function>(bare) && bare.nops() == 1) {
    if (GiNaC::is_the_function<GiNaC::sin_SERIAL>(bare)) root = GiNaC::cos(bare.op(0));
    else if (GiNaC::is_the_function<GiNaC::cos_SERIAL>(bare)) root = GiNaC::sin(bare.op(0));
  }
  return at_initial_state(root, s) < 0 ? -root : root;
}

// x/root, cancelled when root divides x
ex divided(const ex& x, const ex& root, const MotionSymbols& motion) {
  ex q = GiNaC::normal(x / root);
  return GiNaC::is_a<GiNaC::numeric>(q.denom()) ? tidy(q, motion) : tidy(x, motion) / root;
}

}  // namespace

std::optional<RollingContact> rolling_contact(const Vector3& center, const Rotation& rotation, const Vector3& axis,
                               const ex& radius, const Symbols& s) {
  MotionSymbols motion = motion_symbols(s);
  const GiNaC::matrix& R = rotation.matrix;
  ex length = GiNaC::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  Vector3 n;
  for (unsigned a = 0; a < 3; ++a) n[a] = tidy((R(a, 0) * axis[0] + R(a, 1) * axis[1] + R(a, 2) * axis[2]) / length, motion);
  ex root = in_plane_length(n[2], s);
  if (root.is_zero() || at_initial_state(root, s) == 0) return std::nullopt;
  // root·ρ = r·(n_z·n − e_z), kept free of the division until the end
  Vector3 scaled_rho;
  for (unsigned a = 0; a < 3; ++a) scaled_rho[a] = radius * (n[2] * n[a] - (a == 2 ? 1 : 0));
  RollingContact c;
  c.height = tidy(center[2] - radius * root, motion);
  for (unsigned a = 0; a < 3; ++a) c.contact[a] = center[a] + (a == 2 ? -radius * root : scaled_rho[a] / root);
  Vector3 omega_body = rotation.sequence.empty() && !ex(R).is_equal(GiNaC::unit_matrix(3))
                           ? angular_velocity_of_matrix(R, s, motion)
                           : angular_velocity_of_sequence(rotation.sequence, s);
  Vector3 omega;
  for (unsigned a = 0; a < 3; ++a) omega[a] = R(a, 0) * omega_body[0] + R(a, 1) * omega_body[1] + R(a, 2) * omega_body[2];
  // root·(v_c + ω × ρ)
  ex slip_x = root * time_derivative(center[0], s) + omega[1] * scaled_rho[2] - omega[2] * scaled_rho[1];
  ex slip_y = root * time_derivative(center[1], s) + omega[2] * scaled_rho[0] - omega[0] * scaled_rho[2];
  c.slip_x = divided(tidy(slip_x, motion), root, motion);
  c.slip_y = divided(tidy(slip_y, motion), root, motion);
  return c;
}

}  // namespace eomgen
