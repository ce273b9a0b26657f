#include "studies/eigenvalue_sweep_output.hpp"

#include <algorithm>
#include <iostream>

#include <fmt/format.h>

#include "studies/exit_status.hpp"
#include "studies/report_text.hpp"
#include "emit/formats.hpp"

namespace eomgen::studies {

namespace {

std::string crossing_text(const runtime::AxisCrossing& c, const std::string& parameter) {
  std::string what = c.oscillatory ? fmt::format("a complex pair ±{:.6g}i (frequency {:.6g} rad/s)", c.eigenvalue.imag(),
                                                 c.eigenvalue.imag())
                                   : "a real eigenvalue through 0";
  return fmt::format("{} = {:.12g}: {} crosses into the {} half-plane ({})", parameter, c.parameter, what,
                     c.destabilizing ? "right" : "left", c.destabilizing ? "stability lost" : "stability gained");
}

std::string interval_text(const runtime::StableInterval& i, const std::string& parameter) {
  return fmt::format("{}{:.12g} {} {} {} {:.12g}{}", i.open_low ? "(from the sweep's start) " : "", i.low,
                     i.open_low ? "<=" : "<", parameter, i.open_high ? "<=" : "<", i.high,
                     i.open_high ? " (to the sweep's end)" : "");
}

}  // namespace

std::string eigenvalue_sweep_csv(const runtime::EigenvalueSweep& s, const std::string& parameter) {
  std::size_t columns = 0;
  for (const auto& point : s.eigenvalues) columns = std::max(columns, point.size());
  std::string text = parameter;
  for (std::size_t i = 1; i <= columns; ++i) text += fmt::format(",re_{0},im_{0}", i);
  text += "\n";
  for (int k = 0; k < s.axis.count; ++k) {
    const auto& point = s.eigenvalues[std::size_t(k)];
    text += fmt::format("{:.17g}", s.axis.value(k));
    for (std::size_t i = 0; i < columns; ++i)
      text += i < point.size() ? fmt::format(",{:.17g},{:.17g}", point[i].real(), point[i].imag()) : ",,";
    text += "\n";
  }
  return text;
}

void print_eigenvalue_sweep_text(const runtime::EigenvalueSweep& s, const std::string& model, const std::string& parameter,
                                 const distribute::Ranks& ranks) {
  long found = std::count_if(s.verdicts.begin(), s.verdicts.end(), [](const std::string& v) { return !v.empty(); });
  std::cout << fmt::format("{}: eigenvalues over {} = {:g} … {:g} ({} points{}, {} with an equilibrium or steady motion) in "
                           "{:.3f} s on {}\n",
                           model, parameter, s.axis.low, s.axis.high, s.axis.count,
                           s.axis.logarithmic ? " a constant ratio apart" : "", found, s.seconds, ranks.description());
  if (s.crossings.empty()) std::cout << "  no eigenvalue crosses the imaginary axis in this range\n";
  else std::cout << fmt::format("  crossings of the imaginary axis (each bisected to within {:.2g}{}):\n", s.resolution,
                                s.axis.logarithmic ? " of its value" : "");
  for (const runtime::AxisCrossing& c : s.crossings) std::cout << "    " << crossing_text(c, parameter) << "\n";
  if (s.stable.empty()) std::cout << "  asymptotically stable nowhere in this range\n";
  for (const runtime::StableInterval& i : s.stable) std::cout << "  asymptotically stable for " << interval_text(i, parameter) << "\n";
  for (const runtime::StableInterval& i : s.marginal)
    std::cout << "  only marginally stable (eigenvalues on the imaginary axis, none to the right) at "
              << (i.low == i.high ? fmt::format("{} = {:.12g}", parameter, i.low)
                                  : fmt::format("the points of {:.12g} <= {} <= {:.12g}", i.low, parameter, i.high))
              << "\n";
}

void print_eigenvalue_sweep_json(const runtime::EigenvalueSweep& s, const std::string& model, const std::string& parameter,
                                 const distribute::Ranks& ranks) {
  std::string crossings, intervals;
  for (const runtime::AxisCrossing& c : s.crossings)
    crossings += fmt::format("{}{{{}: {}, \"eigenvalue\": {{\"re\": 0, \"im\": {}}}, \"kind\": \"{}\", \"direction\": \"{}\"}}",
                             crossings.empty() ? "" : ", ", json_quoted(parameter), json_number(c.parameter), json_number(c.eigenvalue.imag()),
                             c.oscillatory ? "oscillatory" : "real", c.destabilizing ? "destabilizing" : "stabilizing");
  std::string marginal;
  for (const runtime::StableInterval& i : s.stable)
    intervals += fmt::format("{}{{\"low\": {}, \"high\": {}, \"open_low\": {}, \"open_high\": {}}}", intervals.empty() ? "" : ", ",
                             json_number(i.low), json_number(i.high), i.open_low ? "true" : "false", i.open_high ? "true" : "false");
  for (const runtime::StableInterval& i : s.marginal)
    marginal += fmt::format("{}{{\"low\": {}, \"high\": {}}}", marginal.empty() ? "" : ", ", json_number(i.low), json_number(i.high));
  std::cout << fmt::format("{{\"model\": {}, \"parameter\": {}, \"from\": {}, \"to\": {}, \"points\": {}, \"logarithmic\": {}, "
                           "\"crossings\": [{}], \"crossing_resolution\": {}, \"stable_intervals\": [{}], \"marginal_intervals\": [{}], \"seconds\": {}, "
                           "\"interrupted\": {}, \"ranks\": {}}}\n",
                           json_quoted(model), json_quoted(parameter), json_number(s.axis.low), json_number(s.axis.high), s.axis.count,
                           s.axis.logarithmic ? "true" : "false", crossings, json_number(s.resolution), intervals, marginal, json_number(s.seconds), s.interrupted ? "true" : "false", ranks.size());
}

}  // namespace eomgen::studies
