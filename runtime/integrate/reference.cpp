/// @file `--integrator reference`: the model's extrapolation integrator in a wide
/// scalar (reference/reference_solution.hpp), run at a macro step H and at H/2 and
/// halved until two runs agree to 1e-14; the difference of the last two runs is the
/// reported error estimate (an upper bound for the finer run, which is kept).
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "analyse/accuracy.hpp"
#include "integrate/stepper.hpp"

namespace eomgen::runtime {
namespace {

class Reference : public Stepper {
 public:
  Reference(RightHandSide& f, const std::vector<double>& x0, const SimulationSettings& s) : n_(x0.size()) {
    const Problem& p = f.problem();
    if (!p.reference) throw std::invalid_argument("this model was built without the reference integrator");
    auto started = std::chrono::steady_clock::now();
    for (long k = 1;; ++k) {
      double t = s.t_start + k * s.dt_out;
      bool last = t >= s.t_end * (1 - 1e-14) - 1e-300;
      times_.push_back(last ? s.t_end : t);
      if (last) break;
    }
    // halve until two successive runs agree; a run that is not finite (an explicit method on a
    // stiff model at too long a step) is only a reason to halve again
    double step = std::min(s.dt_out, (s.t_end - s.t_start) / 50);
    std::vector<std::vector<double>> previous;
    bool have_previous = false;
    for (int halving = 0; halving < 16; ++halving, step /= 2) {
      std::vector<std::vector<double>> rows;
      if (!run(p, x0, s.t_start, step, rows)) {
        have_previous = false;
        continue;
      }
      ok_ = true;
      rows_ = rows;
      step_ = step;
      if (have_previous) {
        estimate_ = trajectory_error(previous, rows_);
        if (estimate_ <= 1e-14 || halving >= 6 + first_finite_) break;
      } else {
        first_finite_ = halving;
      }
      previous = std::move(rows);
      have_previous = true;
    }
    wall_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  }

  bool advance(double t_out, std::vector<double>& x) override {
    if (!ok_ || next_ >= rows_.size()) {
      failure_time = t_out;
      flag = -1;
      reason = fmt::format("the reference integrator stopped: the state is not finite before t = {:.9g}", failure_at_);
      return false;
    }
    x = rows_[next_++];
    return true;
  }

  SolverStatistics statistics() const override {
    SolverStatistics s;
    s.steps = steps_;
    s.rhs_evaluations = evaluations_;
    s.wall_seconds = wall_;
    return s;
  }

  double error_estimate() const override { return estimate_; }
  bool projects_after_every_step() const override { return false; }
  double reference_step() const override { return step_; }

 private:
  bool run(const Problem& p, const std::vector<double>& x0, double t0, double step, std::vector<std::vector<double>>& rows) {
    std::vector<double> out(times_.size() * n_);
    long used = p.reference(p.parameters.data(), p.held_inputs(), t0, x0.data(),
                            times_.data(), times_.size(), step, out.data());
    rows.clear();
    if (used < 0) {
      failure_at_ = times_[static_cast<std::size_t>(-1 - used)];
      return false;
    }
    evaluations_ += used;
    steps_ = static_cast<long>(std::ceil((times_.back() - t0) / step));
    for (std::size_t k = 0; k < times_.size(); ++k)
      rows.emplace_back(out.begin() + static_cast<long>(k * n_), out.begin() + static_cast<long>((k + 1) * n_));
    return true;
  }

  std::size_t n_, next_ = 0;
  std::vector<double> times_;
  std::vector<std::vector<double>> rows_;
  bool ok_ = false;
  double estimate_ = NAN, step_ = 0, wall_ = 0, failure_at_ = 0;
  int first_finite_ = 0;
  long evaluations_ = 0, steps_ = 0;
};

}  // namespace

std::unique_ptr<Stepper> make_reference(RightHandSide& f, const std::vector<double>& x0, const SimulationSettings& s) {
  return std::make_unique<Reference>(f, x0, s);
}

}  // namespace eomgen::runtime
