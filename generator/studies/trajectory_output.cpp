#include "studies/trajectory_output.hpp"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <iostream>

#include <fmt/format.h>
#include <unistd.h>

#include "common/output_file.hpp"
#include "report/reports.hpp"

namespace eomgen::studies {

namespace {

constexpr std::size_t chart_rows_at_most = 20000;

void append_row(runtime::Trajectory& to, const runtime::Trajectory& from, std::size_t k) {
  to.times.push_back(from.times[k]);
  to.states.push_back(from.states[k]);
  to.energies.push_back(from.energies[k]);
  to.outputs.push_back(from.outputs[k]);
  to.first_integrals.push_back(from.first_integrals[k]);
  if (k < from.multipliers.size()) to.multipliers.push_back(from.multipliers[k]);
  if (k < from.position_residuals.size()) {
    to.position_residuals.push_back(from.position_residuals[k]);
    to.velocity_residuals.push_back(from.velocity_residuals[k]);
  }
}

// every other row, from the first
runtime::Trajectory halved(const runtime::Trajectory& t) {
  runtime::Trajectory out;
  for (std::size_t k = 0; k < t.times.size(); k += 2) append_row(out, t, k);
  return out;
}

double seconds_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

TrajectoryOutput::TrajectoryOutput(const eomgen_model_abi& model, std::string csv) : model_(model), csv_(std::move(csv)) {
  if (csv_.empty()) return;
  if (failure_ = output_file_refusal(csv_); !failure_.empty()) return;
  if (!is_device_or_pipe(csv_)) temporary_ = csv_ + ".tmp." + std::to_string(::getpid());
  const std::string& written = temporary_.empty() ? csv_ : temporary_;
  file_ = std::fopen(written.c_str(), "wb");
  if (!file_) failure_ = "cannot create " + written + ": " + std::strerror(errno);
  else write(runtime::trajectory_csv_header(model_));
}

bool TrajectoryOutput::write(const std::string& text) {
  if (std::fwrite(text.data(), 1, text.size(), file_) == text.size() && std::fflush(file_) == 0) return true;
  failure_ = "cannot write " + csv_ + " (the disk is full, or a file-size limit is reached): " + std::strerror(errno);
  return false;
}

TrajectoryOutput::~TrajectoryOutput() {
  if (file_) std::fclose(file_);
  if (!temporary_.empty()) std::remove(temporary_.c_str());
}

bool TrajectoryOutput::take(const runtime::Trajectory& rows) {
  for (std::size_t k = 0; k < rows.times.size(); ++k, ++seen_) {
    if (seen_ % every_ == 0) append_row(sample_, rows, k);
    if (sample_.times.size() > chart_rows_at_most) sample_ = halved(sample_), every_ *= 2;
  }
  if (!rows.times.empty()) {
    last_ = {};
    append_row(last_, rows, rows.times.size() - 1);
  }
  if (!failure_.empty()) return false;
  return !file_ || write(runtime::trajectory_csv_rows(model_, rows));
}

bool TrajectoryOutput::finish() {
  if (!file_) return failure_.empty();
  bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!closed && failure_.empty())
    failure_ = "cannot write " + csv_ + " (the disk is full, or a file-size limit is reached): " + std::strerror(errno);
  if (!failure_.empty()) return false;
  if (temporary_.empty()) return true;
  if (std::rename(temporary_.c_str(), csv_.c_str()) != 0) {
    failure_ = "cannot move the output into place at " + csv_ + ": " + std::strerror(errno);
    return false;
  }
  temporary_.clear();
  return true;
}

runtime::Trajectory TrajectoryOutput::chart_rows() const {
  runtime::Trajectory out = sample_;
  if (!last_.times.empty() && (out.times.empty() || out.times.back() != last_.times.back())) append_row(out, last_, 0);
  return out;
}

RunProgress::RunProgress(std::string label, double t_start, double t_end)
    : label_(std::move(label)), t_start_(t_start), t_end_(t_end), started_(seconds_now()), terminal_(::isatty(2)) {}

RunProgress::~RunProgress() {
  if (drawn_ && terminal_) std::cerr << "\n";
}

void RunProgress::operator()(double t) {
  double now = seconds_now(), elapsed = now - started_;
  if (elapsed < 2 || now - shown_ < (terminal_ ? 0.5 : 10)) return;
  shown_ = now, drawn_ = true;
  double done = (t - t_start_) / (t_end_ - t_start_);
  std::string line = fmt::format("eomgen: {}: t = {:.6g} of {:g} ({:.0f} %), about {:.0f} s left", label_, t, t_end_, 100 * done,
                                 done > 0 ? elapsed * (1 - done) / done : 0.0);
  std::cerr << (terminal_ ? "\r" + line + "   " : line + "\n") << std::flush;
}

}  // namespace eomgen::studies
