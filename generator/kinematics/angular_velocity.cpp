#include "kinematics/mechanics.hpp"

namespace eomgen {

using GiNaC::ex;

Vector3 angular_velocity_of_sequence(const std::vector<ElementaryRotation>& sequence, const Symbols& symbols) {
  // Q = (R_{i+1}⋯R_k)ᵀ, built from the right: Q_{i-1} = Q_i · R_iᵀ
  GiNaC::matrix Q = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3));
  Vector3 omega{0, 0, 0};
  for (std::size_t i = sequence.size(); i-- > 0;) {
    const ElementaryRotation& r = sequence[i];
    ex rate = time_derivative(r.angle, symbols);
    Vector3 e = rotation_axis(r);
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned b = 0; b < 3; ++b)
        if (!e[b].is_zero()) omega[a] += Q(a, b) * e[b] * rate;
    Q = Q.mul(rotation_matrix(r).transpose());
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned b = 0; b < 3; ++b) Q(a, b) = Q(a, b).expand();
  }
  for (ex& w : omega) w = w.expand();
  return omega;
}

Vector3 angular_velocity_of_matrix(const GiNaC::matrix& R, const Symbols& symbols, const MotionSymbols& motion) {
  GiNaC::matrix Rdot(3, 3);
  for (unsigned a = 0; a < 3; ++a)
    for (unsigned b = 0; b < 3; ++b) Rdot(a, b) = time_derivative(R(a, b), symbols);
  GiNaC::matrix W = R.transpose().mul(Rdot);
  // skew(ω) = [[0, −ω_z, ω_y], [ω_z, 0, −ω_x], [−ω_y, ω_x, 0]]
  return {tidy(W(2, 1), motion), tidy(W(0, 2), motion), tidy(W(1, 0), motion)};
}

}  // namespace eomgen
