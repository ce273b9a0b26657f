#include "compare/same_motion.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace eomgen {

namespace {

using GiNaC::ex;

std::optional<std::vector<ex>> solve(const GiNaC::matrix& M, const std::vector<ex>& f, const GiNaC::exmap& at) {
  unsigned n = M.rows();
  GiNaC::matrix A(n, n), b(n, 1), x(n, 1);
  for (unsigned i = 0; i < n; ++i) {
    b(i, 0) = substituted(f[i], at).evalf();
    x(i, 0) = GiNaC::symbol();
    for (unsigned j = 0; j < n; ++j) A(i, j) = substituted(M(i, j), at).evalf();
  }
  try {
    GiNaC::matrix s = A.solve(x, b);
    std::vector<ex> out;
    for (unsigned i = 0; i < n; ++i) {
      ex v = s(i, 0).evalf();
      if (!GiNaC::is_a<GiNaC::numeric>(v)) return std::nullopt;
      out.push_back(v);
    }
    return out;
  } catch (const std::exception&) {
    return std::nullopt;  // singular at this state
  }
}

// q'' of one side at (q, q') given in `state` (values of q, of the q' symbols, and t)
std::optional<std::vector<ex>> accelerations(const MotionForm& m, GiNaC::exmap state) {
  if (m.kinematics.empty()) return solve(m.mass_matrix, m.forcing, state);
  for (std::size_t c = 0; c < m.velocities.size(); ++c) state[m.velocities[c]] = substituted(m.definitions[c], state).evalf();
  auto s_dot = solve(m.mass_matrix, m.forcing, state);
  if (!s_dot) return std::nullopt;
  std::vector<ex> out;
  for (const ex& r : m.kinematics) {
    ex a = r.diff(GiNaC::ex_to<GiNaC::symbol>(m.time));
    for (std::size_t i = 0; i < m.coordinates.size(); ++i)
      a += r.diff(GiNaC::ex_to<GiNaC::symbol>(m.coordinates[i])) * m.coordinate_rates[i];
    for (std::size_t c = 0; c < m.velocities.size(); ++c) a += r.diff(GiNaC::ex_to<GiNaC::symbol>(m.velocities[c])) * (*s_dot)[c];
    out.push_back(substituted(a, state).evalf());
  }
  return out;
}

}  // namespace

GiNaC::ex substituted(const GiNaC::ex& e, const GiNaC::exmap& values) {
  return e.subs(values, GiNaC::subs_options::no_pattern | GiNaC::subs_options::pattern_is_not_product);
}

MotionComparison compare_accelerations(const MotionForm& a, const MotionForm& b, const std::vector<GiNaC::exmap>& a_points,
                                       const std::vector<GiNaC::exmap>& b_points, double tolerance) {
  MotionComparison out;
  if (a.coordinates.size() != b.coordinates.size()) return out;
  // a state both sides accept: for pseudo-velocities, q' from random s through the kinematic equations
  const MotionForm* appell = !a.kinematics.empty() ? &a : !b.kinematics.empty() ? &b : nullptr;
  std::vector<std::pair<double, double>> compared;  // |x − y| and max(|x|, |y|) of each component at each state
  double largest = 0;
  for (std::size_t k = 0; k < a_points.size() && k < b_points.size(); ++k) {
    GiNaC::exmap a_state = a_points[k], b_state = b_points[k];  // parameters, inputs, t and q as sampled
    for (std::size_t i = 0; i < a.coordinates.size(); ++i) {
      const GiNaC::exmap& own = appell == &a ? a_points[k] : b_points[k];
      ex rate = appell ? substituted(appell->kinematics[i], own).evalf() : a_points[k].at(a.coordinate_rates[i]);
      a_state[a.coordinate_rates[i]] = b_state[a.coordinate_rates[i]] = rate;
    }
    auto x = accelerations(a, a_state), y = accelerations(b, b_state);
    if (!x || !y) continue;
    ++out.states;
    for (std::size_t i = 0; i < x->size(); ++i) {
      double u = GiNaC::ex_to<GiNaC::numeric>((*x)[i]).to_double(), v = GiNaC::ex_to<GiNaC::numeric>((*y)[i]).to_double();
      double d = std::abs(GiNaC::ex_to<GiNaC::numeric>(((*x)[i] - (*y)[i]).evalf()).to_double());
      compared.push_back({d, std::max(std::abs(u), std::abs(v))});
      largest = std::max(largest, compared.back().second);
    }
  }
  // against the accelerations themselves, above a floor of 1e-20 of the largest for a component
  // that is zero but for the solves' rounding; no floor of one unit (a system on a time scale of
  // 1e12 s has accelerations of 1e-24, all "the same" against one)
  for (const auto& [d, size] : compared)
    if (d > 0) out.max_rel_difference = std::max(out.max_rel_difference, d / std::max(size, 1e-20 * largest));
  out.same = out.states > 0 && out.max_rel_difference <= tolerance;
  return out;
}

}  // namespace eomgen
