#include "simulation.hpp"

#include <arkode/arkode_butcher_erk.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>
#include <fmt/format.h>

#include "analyse/state_check.hpp"
#include "analyse/step_stability.hpp"
#include "analyse/work_precision.hpp"
#include "integrate/projection.hpp"
#include "integrate/quaternion_norms.hpp"
#include "integrate/stepper.hpp"

namespace eomgen::runtime {

const std::vector<std::string>& integrator_names() {
  static const std::vector<std::string> names = {"cvode-bdf", "cvode-adams", "arkode-dp5", "arkode-verner",
                                                 "arkode-dirk", "rk4", "verlet", "gauss-legendre", "ida", "reference"};
  return names;
}

const double* Problem::inputs_at(double t, std::vector<double>& scratch) const {
  if (inputs.empty()) return nullptr;
  if (!input_signal) return inputs.data();
  scratch = inputs;
  input_signal(t, scratch.data());
  return scratch.data();
}

bool is_dae_integrator(const std::string& name) { return name == "ida"; }

bool is_fixed_step_integrator(const std::string& name) {
  return name == "rk4" || name == "verlet" || name == "gauss-legendre";
}

std::string integrator_refusal(const eomgen_model_abi& m, const std::string& name) {
  if (is_dae_integrator(name) && m.num_multipliers == 0)
    return "the integrator ida solves Lagrange I models (method = \"lagrange1\") only";
  if (name == "verlet" && std::string(m.method) == "hamilton" && !m.separable_hamiltonian)
    return "Störmer–Verlet in canonical variables needs a separable H = T(p) + V(q), and this H couples them (the "
           "kinetic energy depends on the coordinates): use gauss-legendre, the implicit symplectic method";
  if (name == "verlet" && m.num_coordinates != m.num_velocities)
    return "Störmer–Verlet needs q' = v; the state of Appell's equations holds pseudo-velocities: use rk4 or an "
           "adaptive integrator";
  return {};
}

bool is_explicit_integrator(const std::string& name) {
  for (const char* e : {"cvode-adams", "arkode-dp5", "arkode-verner", "rk4", "verlet"})
    if (name == e) return true;
  return false;
}

namespace {

std::unique_ptr<Stepper> make_stepper(RightHandSide& f, const std::vector<double>& x0, const SimulationSettings& s) {
  const std::string& name = s.integrator;
  if (name == "cvode-bdf") return make_cvode(f, x0, s, false);
  if (name == "cvode-adams") return make_cvode(f, x0, s, true);
  if (name == "arkode-dp5") return make_arkode_explicit(f, x0, s, ARKODE_DORMAND_PRINCE_7_4_5);
  // ARKODE 5.4 has no Verner 8(7); Fehlberg's 13-stage 8(7) is its highest-order embedded pair
  if (name == "arkode-verner") return make_arkode_explicit(f, x0, s, ARKODE_FEHLBERG_13_7_8);
  if (name == "arkode-dirk") return make_arkode_dirk(f, x0, s);
  if (is_fixed_step_integrator(name)) return make_fixed_step(f, x0, s);
  if (name == "ida") return make_ida(f, x0, s);
  if (name == "reference") return make_reference(f, x0, s);
  throw std::invalid_argument("unknown integrator " + name);
}

void record(const Problem& p, double t, const std::vector<double>& x, Trajectory& out) {
  const ConstraintProjection measure(p);
  const eomgen_model_abi& m = *p.model;
  std::vector<double> scratch;
  const double* u = p.inputs_at(t, scratch);
  out.times.push_back(t);
  out.states.push_back(x);
  out.energies.push_back(m.kinetic_energy(t, x.data(), p.parameters.data()) +
                         m.potential_energy(t, x.data(), p.parameters.data()));
  std::vector<double> y(m.num_outputs);
  if (m.num_outputs) m.outputs(t, x.data(), u, p.parameters.data(), y.data());
  out.outputs.push_back(y);
  std::vector<double> integrals(m.num_first_integrals);
  if (m.num_first_integrals) m.first_integrals(t, x.data(), p.parameters.data(), integrals.data());
  out.first_integrals.push_back(integrals);
  if (m.num_constraints == 0) return;
  std::vector<double> lambda(m.num_multipliers);
  if (m.num_multipliers) m.multipliers(t, x.data(), u, p.parameters.data(), lambda.data());
  out.multipliers.push_back(lambda);
  auto [position, velocity] = measure.residuals(t, x.data());
  out.position_residuals.push_back(position);
  out.velocity_residuals.push_back(velocity);
}

std::string configuration(const eomgen_model_abi& m, const std::vector<double>& x) {
  std::string s;
  for (std::size_t i = 0; i < m.num_coordinates; ++i)
    s += fmt::format("{}{} = {:.6g}", i ? ", " : "", m.coordinate_names[i], x[i]);
  return s;
}

// smallest and largest eigenvalue of the mass matrix at x without its velocities' units
std::pair<double, double> mass_matrix_range(const Problem& p, double t, const std::vector<double>& x) {
  Eigen::MatrixXd M = unit_free_mass_matrix(p, t, x);
  if (M.size() == 0) return {1, 1};
  if (!M.allFinite()) return {NAN, NAN};
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(M, Eigen::EigenvaluesOnly);
  return {eigen.eigenvalues().minCoeff(), eigen.eigenvalues().maxCoeff()};
}

// the mass matrix's conditioning (smallest over largest eigenvalue, without the velocities' units)
// and the coordinates that take part in its weakest direction
struct Conditioning {
  double ratio = 1;
  std::string coordinates;
};

Conditioning conditioning(const Problem& p, double t, const std::vector<double>& x) {
  const eomgen_model_abi& m = *p.model;
  std::size_t n = m.num_velocities;
  Eigen::MatrixXd M = unit_free_mass_matrix(p, t, x);
  Conditioning c;
  if (!M.allFinite() || n == 0) return c;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(M);
  double largest = std::abs(eigen.eigenvalues().maxCoeff());
  c.ratio = largest > 0 ? eigen.eigenvalues().minCoeff() / largest : 1;
  Eigen::VectorXd weakest = eigen.eigenvectors().col(0);
  for (std::size_t i = 0; i < n; ++i)
    if (std::abs(weakest[static_cast<long>(i)]) > 0.2)
      c.coordinates += (c.coordinates.empty() ? "" : ", ") + std::string(m.state_names[m.num_coordinates + i]);
  return c;
}

// the fixed step of rk4 and verlet against the method's stability limit, at the start and
// at about a hundred output times; warns once, when it is first exceeded
class StepLimitWatch {
 public:
  StepLimitWatch(const Problem& p, const SimulationSettings& s, std::vector<std::string>& warnings)
      : p_(p), integrator_(s.integrator), warnings_(warnings) {
    fixed_ = is_fixed_step_integrator(s.integrator);
    h_ = std::min(s.step > 0 ? s.step : s.dt_out / 10, s.dt_out);
    long outputs = static_cast<long>(std::ceil((s.t_end - s.t_start) / s.dt_out));
    stride = std::max(1L, outputs / 100);
    if (fixed_ && s.step > s.dt_out * (1 + 1e-12))
      warnings_.push_back(fmt::format("the step {:g} s is longer than the output interval {:g} s: {} steps at most to "
                                      "the next output time, so its step is {:g} s; give --dt-out {:g} for steps of {:g} s",
                                      s.step, s.dt_out, s.integrator, s.dt_out, s.step, s.step));
  }
  void check(double t, const std::vector<double>& x) {
    if (!fixed_ || beyond_) return;
    StepStability s = check_step(p_, integrator_, h_, t, x);
    if (!s.beyond) return;
    beyond_ = true;
    warnings_.push_back(step_stability_warning(integrator_, h_, s, t));
  }
  bool beyond() const { return beyond_; }
  long stride = 1;

 private:
  const Problem& p_;
  std::string integrator_;
  std::vector<std::string>& warnings_;
  bool fixed_ = false, beyond_ = false;
  double h_ = 0;
};

// a run that ends with a non-finite state, or that lost a conserved energy entirely, has no
// result to show: it ends as a numerical failure with its rows kept
void refuse_exploded(const Problem& p, double start_size, bool beyond_step_limit, SimulationResult& r) {
  const RunSummary& run = r.summary;
  const eomgen_model_abi& m = *p.model;
  std::string why;
  double size = 0;
  for (double v : run.last_state) size = std::isfinite(v) ? std::max(size, std::abs(v)) : INFINITY;
  bool conserved = m.conserves_energy_without_inputs && !p.input_signal &&
                   std::all_of(p.inputs.begin(), p.inputs.end(), [](double u) { return u == 0; });
  double drift = run.largest_energy_change / std::max(std::abs(run.first_energy), 1e-300);
  if (!std::isfinite(size)) why = "the state is not finite at the end";
  else if (conserved && drift > 1)
    why = fmt::format("T + V, which this model conserves, changed by {:.3g} times its initial value", drift);
  else if (beyond_step_limit && size > 1e3 * (1 + start_size))
    why = fmt::format("the state grew from {:.3g} to {:.3g}", start_size, size);
  if (why.empty()) return;
  r.failed = true;
  r.failure_time = run.last_time;
  r.failure = "the result is not a solution: " + why +
              (beyond_step_limit ? ": a numerical instability of a step beyond the method's stability limit (see the "
                                   "warning), not the mechanics"
                                 : ": the integration is unstable; use a smaller step or tolerance, or an implicit method");
}

// the row just recorded into the summary and the progress line; a streamed run hands its rows on
// every stream_rows rows (all of them when `rest`); false when the stream cannot take them
bool keep_row(const SimulationSettings& s, SimulationResult& r, bool rest = false) {
  Trajectory& tr = r.trajectory;
  if (!rest) {
    r.summary.add(tr, tr.times.size() - 1);
    if (s.progress) s.progress(tr.times.back());
  }
  if (!s.stream || tr.times.empty() || (!rest && tr.times.size() < s.stream_rows)) return true;
  bool taken = s.stream(tr);
  tr = Trajectory{};
  if (!taken) {
    r.failed = true;
    r.failure_time = r.summary.last_time;
    r.failure = fmt::format("the rows up to t = {:g} could not be written", r.summary.last_time);
  }
  return taken;
}

// what making the initial state consistent changed: the values the user gave first, by how much
void report_consistency_changes(const eomgen_model_abi& m, const std::vector<double>& before, const std::vector<double>& after,
                                const std::vector<bool>& given, std::vector<std::string>& warnings) {
  std::string user, other;
  for (std::size_t i = 0; i < m.num_states; ++i) {
    // rounding against the state's own size, as given, or the model's default where it is 0 (1
    // where both are): with 1e-12 of max(1, |x|), a 1e-13 m pendulum's given position moved by
    // 11 % unsaid
    double change = after[i] - before[i], size = before[i] != 0 ? std::abs(before[i]) : std::abs(m.default_state[i]);
    if (std::abs(change) <= 1e-12 * (size > 0 && std::isfinite(size) ? size : 1.0)) continue;
    bool by_user = i < given.size() && given[i];
    (by_user ? user : other) += fmt::format("{}{} from {:.9g} to {:.9g} (by {:+.3g})", (by_user ? user : other).empty() ? "" : ", ",
                                            m.state_names[i], before[i], after[i], change);
  }
  if (!user.empty())
    warnings.push_back("the constraints do not allow the initial values you gave: changed " + user +
                       (other.empty() ? "" : "; and " + other) + " to meet them");
}

// why the run stopped, in the words of mechanics where possible
std::string diagnose(const Problem& p, const RightHandSide& f, const Stepper& stepper, const std::vector<double>& x,
                     double scale, double start_size, const std::vector<double>& start_state, double t_start,
                     const std::string& integrator, bool beyond_step_limit) {
  std::string why = stepper.reason + fmt::format(" at t = {:.9g}", stepper.failure_time);
  double size = 0;
  for (double v : x) size = std::isfinite(v) ? std::max(size, std::abs(v)) : INFINITY;
  bool grows = size > 1e12 * (1 + start_size);
  std::string bad = grows ? std::string() : non_finite_quantities(p, stepper.failure_time, x);
  if (!bad.empty())
    return why + fmt::format(": {} {} not finite (a division by zero, or a function outside its domain) at {}", bad,
                             bad.find(',') == std::string::npos ? "is" : "are", state_text(*p.model, x));
  auto [smallest, largest] = mass_matrix_range(p, stepper.failure_time, x);
  if (smallest < -1e-8 * std::abs(largest))
    return why + fmt::format(": the mass matrix is not positive definite (eigenvalues from {:.3g} to {:.3g}) at {}: a "
                             "negative mass or moment of inertia", smallest, largest, configuration(*p.model, x));
  if (std::isnan(smallest) || smallest <= 1e-8 * scale)
    return why + fmt::format(": the mass matrix is singular (smallest eigenvalue {:.3g}) at {}", smallest,
                             configuration(*p.model, x));
  if (grows) {
    why += fmt::format(": the state grows without bound (largest |x| = {:.3g}, from {:.3g} at the start)", size, start_size);
    if (beyond_step_limit)
      return why + fmt::format(": a numerical instability, not the mechanics: the step of {} is beyond its stability "
                               "limit for this model (see the warning); a smaller step or an adaptive integrator follows "
                               "the motion", integrator);
    double stiffness = stiffness_ratio(p, start_state, t_start);
    if (is_explicit_integrator(integrator) && stiffness > 1e3)
      return why + fmt::format(": a numerical instability, not the mechanics: the model is stiff (stiffness ratio {:.2g}) "
                               "and {} is beyond its stability limit; use cvode-bdf or arkode-dirk, or a much smaller step",
                               stiffness, integrator);
    return why + fmt::format(": the solution escapes to infinity in finite time near t = {:.9g}, and no integrator can "
                             "pass that time", stepper.failure_time);
  }
  if (f.saw_non_finite())
    return why + fmt::format(": the right-hand side is not finite (a division by zero, or a function outside "
                             "its domain) at t = {:.9g}, {}",
                             f.non_finite_time(), configuration(*p.model, f.non_finite_state()));
  (void)largest;
  if (stepper.reason.find("TOO_MUCH_ACC") != std::string::npos)
    return why + fmt::format(" at {}: the tolerances ask for more accuracy than double precision gives; loosen --rtol "
                             "(or --atol), or take --integrator reference, which carries more digits",
                             configuration(*p.model, x));
  // a step that t cannot tell from zero: the error test or Newton's iteration asks for more than
  // double precision gives there (a slider-crank through its dead centre at rtol 3e-13)
  if (double h = std::abs(stepper.failure_step); h != 0 && h <= 1e-13 * std::abs(stepper.failure_time))
    return why + fmt::format(" at {}: the step fell {}, within the rounding of t: at these tolerances the integrator "
                             "cannot follow the motion there in double precision; try a looser --rtol, another "
                             "--integrator, or --integrator reference, which carries more digits",
                             configuration(*p.model, x),
                             h < 1e-300 ? std::string("to zero") : fmt::format("to {:.3g}", h));
  return why + fmt::format(" at {}", configuration(*p.model, x));
}

// The quaternions of ball and free joints at the start: one of length 0 names no orientation (an
// error, returned); with the projection on, they start unit, and a user's quaternion that was not
// unit to nine digits is named in a warning (its rotation, that of q/|q|, stays as it was)
std::string start_quaternions(const eomgen_model_abi& m, const SimulationSettings& settings, std::vector<double>& x,
                              std::vector<std::string>& warnings) {
  auto named = [&](std::size_t k) {
    const std::size_t* q = m.quaternion_coordinates + 4 * k;
    return fmt::format("({}, {}, {}, {})", m.coordinate_names[q[0]], m.coordinate_names[q[1]], m.coordinate_names[q[2]],
                       m.coordinate_names[q[3]]);
  };
  if (int k = zero_quaternion(m, x.data()); k >= 0)
    return fmt::format("the quaternion {} is 0 at the start and names no orientation: give it a unit value (w = 1 "
                       "and the rest 0 is the joint's rest orientation)", named(std::size_t(k)));
  if (!settings.projection) return "";
  for (std::size_t k = 0; k < m.num_quaternions; ++k) {
    double length = quaternion_length(m, x.data(), k);
    if (std::abs(length - 1) > 1e-9)
      warnings.push_back(fmt::format("the quaternion {} has length {:.9g} at the start; it is divided by its length, "
                                     "which keeps its orientation", named(k), length));
  }
  normalize_quaternions(m, x.data());
  return "";
}

}  // namespace

SimulationResult simulate(const Problem& problem, const std::vector<double>& x0_given, const SimulationSettings& settings) {
  SimulationResult result;
  const eomgen_model_abi& m = *problem.model;
  bool lagrange1 = m.num_multipliers > 0;
  if (std::string why = integrator_refusal(m, settings.integrator); !why.empty()) throw std::invalid_argument(why);
  if (problem.input_signal && settings.integrator == "reference")
    throw std::invalid_argument("the reference integrator is compiled for constant inputs; inputs that vary in time "
                                "need another integrator");
  bool baumgarte = lagrange1 && settings.baumgarte && !is_dae_integrator(settings.integrator);
  RightHandSide f(problem, baumgarte ? (settings.baumgarte_alpha >= 0 ? settings.baumgarte_alpha : m.baumgarte_alpha) : 0,
                  baumgarte ? (settings.baumgarte_beta >= 0 ? settings.baumgarte_beta : m.baumgarte_beta) : 0);
  ConstraintProjection projection(problem);
  std::vector<double> x = x0_given;
  // a consistent initial state: the model's, moved onto the constraints (always, for every integrator)
  if (m.num_constraints && !projection.make_consistent(settings.t_start, x.data(), settings.given_state)) {
    auto [position, velocity] = projection.residuals(settings.t_start, x0_given.data());
    result.failed = true;
    result.failure = fmt::format("no consistent initial state near the given one: Newton's method on the position "
                                 "constraints did not converge from {} (largest |g| = {:.3g}); start closer to a "
                                 "configuration that meets the constraints",
                                 configuration(m, x0_given), position);
    (void)velocity;
    return result;
  }
  if (m.num_constraints) report_consistency_changes(m, x0_given, x, settings.given_state, result.warnings);
  // Appell's pseudo-velocities meet velocity constraints by construction; holonomic ones may drift
  bool holonomic = false;
  for (std::size_t i = 0; i < m.num_constraints; ++i) holonomic = holonomic || m.constraint_is_holonomic[i];
  if (std::string why = start_quaternions(m, settings, x, result.warnings); !why.empty()) {
    result.failed = true;
    result.failure = why;
    return result;
  }
  if ((lagrange1 || holonomic || m.num_quaternions) && settings.projection && !is_dae_integrator(settings.integrator))
    f.projection = &projection;
  double scale = mass_matrix_range(problem, settings.t_start, x).second, start_size = 0;
  for (double v : x) start_size = std::max(start_size, std::abs(v));
  record(problem, settings.t_start, x, result.trajectory);
  result.largest_quaternion_norm_error = quaternion_norm_error(m, x.data());
  keep_row(settings, result);
  Conditioning start = conditioning(problem, settings.t_start, x);
  bool warned_singular = false;
  StepLimitWatch limit(problem, settings, result.warnings);
  limit.check(settings.t_start, x);
  auto stepper = make_stepper(f, x, settings);
  // output times are exact multiples of dt_out, then the final time
  for (long k = 1;; ++k) {
    double t = settings.t_start + k * settings.dt_out;
    bool last = t >= settings.t_end * (1 - 1e-14) - 1e-300;
    if (last) t = settings.t_end;
    if (!stepper->advance(t, x)) {
      result.failed = true;
      result.failure_time = stepper->failure_time;
      result.solver_flag = stepper->flag;
      result.failure = diagnose(problem, f, *stepper, x, std::isfinite(scale) ? scale : 1.0, start_size,
                                result.summary.first_state, settings.t_start, settings.integrator,
                                limit.beyond());
      if (stepper->failure_time > result.summary.last_time) {
        record(problem, stepper->failure_time, x, result.trajectory);
        keep_row(settings, result);
      }
      break;
    }
    // an output between steps is interpolated, and the interpolant does not keep |q|
    if (f.projection)
      result.largest_quaternion_correction = std::max(result.largest_quaternion_correction, normalize_quaternions(m, x.data()));
    record(problem, t, x, result.trajectory);
    result.largest_quaternion_norm_error = std::max(result.largest_quaternion_norm_error, quaternion_norm_error(m, x.data()));
    if (!keep_row(settings, result)) break;
    if (settings.stop && *settings.stop && !last) {
      result.failed = result.interrupted = true;
      result.failure_time = t;
      result.failure = fmt::format("interrupted at t = {:g} (SIGINT or SIGTERM): the run is partial", t);
      break;
    }
    if (settings.max_rhs_evaluations > 0 && f.evaluations() > settings.max_rhs_evaluations && !last) {
      result.failed = result.over_budget = true;
      result.failure_time = t;
      result.failure = fmt::format("stopped at t = {:g} after {} right-hand-side evaluations, the budget of this run",
                                   t, f.evaluations());
      break;
    }
    if (k % limit.stride == 0) limit.check(t, x);
    // a coordinate singularity ahead: M a thousand times worse conditioned than at the start
    if (!warned_singular) {
      Conditioning now = conditioning(problem, t, x);
      if (now.ratio < 1e-3 * start.ratio) {
        warned_singular = true;
        result.warnings.push_back(fmt::format(
            "the mass matrix is nearly singular at t = {:.9g} (smallest over largest eigenvalue {:.2e}, {:.2e} at the "
            "start) at {}: the velocities {} are losing their independence. This is a singularity of the coordinates "
            "(Euler angles at nutation 0 or pi, Cardan angles at beta = ±pi/2), not of the mechanics: expect large "
            "rates and small steps; choose coordinates that are regular along this motion",
            t, now.ratio, start.ratio, configuration(*problem.model, x), now.coordinates));
      }
    }
    if (last) break;
  }
  result.statistics = stepper->statistics();
  result.error_estimate = stepper->error_estimate();
  result.reference_step = stepper->reference_step();
  result.max_position_residual = result.summary.largest_position_residual;
  result.max_velocity_residual = result.summary.largest_velocity_residual;
  result.projections = projection.projections();
  result.largest_quaternion_correction = std::max(result.largest_quaternion_correction, projection.largest_quaternion_correction());
  if (m.num_quaternions && f.projection)
    result.quaternions_normalized = stepper->projects_after_every_step() ? "after every step" : "at the output times";
  if (!result.failed) refuse_exploded(problem, start_size, limit.beyond(), result);
  keep_row(settings, result, true);
  return result;
}

}  // namespace eomgen::runtime
