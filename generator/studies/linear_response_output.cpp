#include "studies/linear_response_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <regex>
#include <fstream>
#include <iostream>
#include <sstream>

#include <fmt/format.h>

#include "analyse/linear_response.hpp"
#include "analyse/output_interval.hpp"
#include "studies/exit_status.hpp"
#include "studies/loaded_problem.hpp"
#include "common/output_file.hpp"
#include "report/gnuplot.hpp"

namespace eomgen::studies {

namespace {

std::optional<runtime::ResponseRequest> parse_response(const eomgen_model_abi& m, const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream s(text);
  for (std::string part; std::getline(s, part, ':');) parts.push_back(part);
  runtime::ResponseRequest r;
  const std::string hint = "expected initial, impulse:INPUT, step:INPUT or harmonic:INPUT:OMEGA";
  if (parts.empty()) return std::nullopt;
  if (parts[0] == "initial" && parts.size() == 1) return r;
  bool harmonic = parts[0] == "harmonic";
  if (!(parts[0] == "impulse" || parts[0] == "step" || harmonic) || parts.size() != (harmonic ? 3u : 2u)) {
    std::cerr << fmt::format("eomgen: error: --response {}: {}\n", text, hint);
    return std::nullopt;
  }
  int input = index_of(m.input_names, m.num_inputs, parts[1]);
  if (input < 0) {
    std::cerr << fmt::format("eomgen: error: --response {}: {} is not an input of {}\n", text, parts[1], m.name);
    return std::nullopt;
  }
  r.kind = parts[0] == "impulse" ? runtime::Excitation::impulse : parts[0] == "step" ? runtime::Excitation::step
                                                                                     : runtime::Excitation::harmonic;
  r.input = input;
  if (harmonic) {
    char* end = nullptr;
    r.omega = std::strtod(parts[2].c_str(), &end);
    if (*end != '\0' || !(r.omega > 0)) {
      std::cerr << fmt::format("eomgen: error: --response {}: OMEGA must be a positive number (rad/s)\n", text);
      return std::nullopt;
    }
  }
  return r;
}

// NAME=EXPR with EXPR one of A*step(T0), A*impulse(T0), A*sin(W*t), A*cos(W*t) (A* optional)
std::optional<runtime::ResponseRequest> parse_input(const eomgen_model_abi& m, const std::string& text) {
  const std::string number = "([-+]?[0-9]*\\.?[0-9]+(?:[eE][-+]?[0-9]+)?)";
  std::smatch match;
  std::size_t eq = text.find('=');
  std::string name = text.substr(0, eq), expression = eq == std::string::npos ? "" : text.substr(eq + 1);
  expression.erase(std::remove(expression.begin(), expression.end(), ' '), expression.end());
  int input = index_of(m.input_names, m.num_inputs, name);
  if (eq == std::string::npos || input < 0) {
    std::cerr << fmt::format("eomgen: error: --input {}: expected INPUT=EXPRESSION with INPUT an input of {}\n", text, m.name);
    return std::nullopt;
  }
  runtime::ResponseRequest r;
  r.input = input;
  auto amplitude = [](const std::ssub_match& a) { return a.matched ? std::stod(a.str()) : 1.0; };
  if (std::regex_match(expression, match, std::regex("(?:" + number + "\\*)?(step|impulse)\\(" + number + "\\)"))) {
    r.kind = match[2] == "step" ? runtime::Excitation::step : runtime::Excitation::impulse;
    r.amplitude = amplitude(match[1]), r.start = std::stod(match[3].str());
    if (r.start >= 0) return r;
  } else if (std::regex_match(expression, match, std::regex("(?:" + number + "\\*)?(sin|cos)\\(" + number + "\\*t\\)"))) {
    r.kind = runtime::Excitation::harmonic;
    r.amplitude = amplitude(match[1]), r.omega = std::stod(match[3].str());
    r.phase = match[2] == "cos" ? M_PI / 2 : 0;
    if (r.omega > 0) return r;
  }
  std::cerr << fmt::format("eomgen: error: --input {}: expected A*step(T0), A*impulse(T0), A*sin(W*t) or A*cos(W*t) "
                           "(A optional, T0 >= 0, W > 0), e.g. --input '{}=step(2)'\n", text, name);
  return std::nullopt;
}

std::string response_csv(const LinearReport& r, const runtime::LinearResponse& response) {
  std::string out = "t";
  for (const std::string& s : r.state_names) out += "," + s;
  out += "\n";
  for (std::size_t k = 0; k < response.times.size(); ++k) {
    out += fmt::format("{:.17g}", response.times[k]);
    for (Eigen::Index i = 0; i < response.states[k].size(); ++i) out += fmt::format(",{:.17g}", response.states[k](i));
    out += "\n";
  }
  return out;
}

std::string draw(const eomgen_model_abi& m, const runtime::LinearResponse& response, const std::string& title,
                 const std::string& png) {
  std::string data = png + ".data.tmp";
  {
    std::ofstream out(data);
    for (std::size_t k = 0; k < response.times.size(); ++k) {
      out << fmt::format("{:.17g}", response.times[k]);
      for (std::size_t i = 0; i < m.num_coordinates; ++i) out << fmt::format(" {:.17g}", response.states[k](static_cast<Eigen::Index>(i)));
      out << "\n";
    }
  }
  std::string plot = fmt::format("set terminal pngcairo size 1000,560 noenhanced\nset output {}\nset title {}\nset xlabel 't [s]'\n"
                                 "set ylabel 'deviation from the equilibrium'\nset grid\nset key outside right\nplot ",
                                 runtime::gnuplot_quoted(png), runtime::gnuplot_quoted(title));
  for (std::size_t i = 0; i < m.num_coordinates; ++i)
    plot += fmt::format("{}{} using 1:{} with lines lw 2 title {}", i ? ", " : "", runtime::gnuplot_quoted(data), i + 2,
                        runtime::gnuplot_quoted(m.coordinate_names[i]));
  std::string failure = runtime::run_gnuplot(plot + "\n", png);
  std::remove(data.c_str());
  return failure;
}

// the default interval and end, 0.01 s and 10 s, against the system's own times: a 1e7 rad/s
// absorber's rows were 1e4 periods apart, and a 1e-5 rad/s one's 10 s showed nothing of it
void warn_where_the_defaults_miss_the_motion(const Eigen::MatrixXd& A, const runtime::ResponseRequest& request,
                                             const ResponseOptions& o) {
  if (!o.dt_out_given) {
    double period = runtime::fastest_period(A);
    bool forcing = request.omega > 0 && 2 * M_PI / request.omega < period;
    if (forcing) period = 2 * M_PI / request.omega;
    if (auto w = runtime::aliasing_warning(period, o.dt_out, forcing ? "the forcing" : "the fastest mode"))
      std::cerr << "eomgen: warning: " << *w << "\n";
  }
  if (!o.t_end_given)
    if (auto w = runtime::span_warning(runtime::slowest_time(A), o.t_end, o.dt_out)) std::cerr << "eomgen: warning: " << *w << "\n";
}

}  // namespace

std::optional<int> write_linear_response(const eomgen_model_abi& m, const LinearReport& r, const ResponseOptions& o) {
  if (!wants_response(o)) return std::nullopt;
  if (!o.response.empty() && !o.input.empty()) {
    std::cerr << "eomgen: error: give either --response or --input, not both\n";
    return exit_user_error;
  }
  auto request = o.input.empty() ? parse_response(m, o.response) : parse_input(m, o.input);
  if (!request) return exit_user_error;
  if (!(o.t_end > 0) || !(o.dt_out > 0)) {
    std::cerr << "eomgen: error: --response needs --t-end > 0 and --dt-out > 0\n";
    return exit_user_error;
  }
  std::vector<double> x0(m.num_states, 0.0);
  if (!assign_states(m, o.initials, "--initial", x0)) return exit_user_error;
  request->x0 = Eigen::Map<Eigen::VectorXd>(x0.data(), static_cast<Eigen::Index>(x0.size()));
  request->t_end = o.t_end, request->dt_out = o.dt_out;
  warn_where_the_defaults_miss_the_motion(r.A, *request, o);
  runtime::LinearResponse response = runtime::linear_response(r.A, r.B, *request);
  std::string csv = response_csv(r, response);
  if (o.csv.empty()) {
    std::cout << csv;
  } else if (std::string failure = write_file_atomically(o.csv, csv); !failure.empty()) {
    std::cerr << "eomgen: " << failure << "\n";
    return exit_user_error;
  }
  if (!o.plot.empty()) {
    std::string failure = draw(m, response, fmt::format("{}: linear response, {}", m.name, o.input.empty() ? o.response : o.input), o.plot);
    if (failure.empty()) std::cerr << "eomgen: chart in " << o.plot << "\n";
    else std::cerr << "eomgen: warning: no chart " << o.plot << ": " << failure << "\n";
  }
  return exit_success;
}

}  // namespace eomgen::studies
