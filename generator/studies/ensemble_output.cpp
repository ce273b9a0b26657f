#include "studies/ensemble_output.hpp"

#include <cmath>
#include <iostream>

#include <fmt/format.h>

#include "studies/exit_status.hpp"
#include "studies/report_text.hpp"
#include "emit/formats.hpp"

namespace eomgen::studies {

namespace {

std::string field(double v) { return std::isfinite(v) ? fmt::format("{:.17g}", v) : ""; }

std::string quantiles_text(const runtime::SampleStatistics& s, const std::vector<double>& probabilities) {
  std::string text;
  for (std::size_t i = 0; i < probabilities.size(); ++i)
    text += fmt::format("{}q{:g} {:.6g}", i ? ", " : "", probabilities[i], s.quantiles[i]);
  return text;
}

std::string statistics_json(const runtime::SampleStatistics& s, const std::vector<double>& probabilities) {
  std::string quantiles;
  for (std::size_t i = 0; i < probabilities.size(); ++i)
    quantiles += fmt::format("{}{{\"p\": {}, \"value\": {}}}", i ? ", " : "", json_number(probabilities[i]), json_number(s.quantiles[i]));
  return fmt::format("\"count\": {}, \"mean\": {}, \"standard_deviation\": {}, \"standard_error\": {}, \"quantiles\": [{}]",
                     s.count, json_number(s.mean), json_number(s.standard_deviation), json_number(s.standard_error), quantiles);
}

}  // namespace

std::string ensemble_csv(const distribute::EnsembleResult& result, const std::vector<double>& probabilities) {
  std::string text = "t";
  for (const runtime::SignalBands& b : result.bands) {
    text += fmt::format(",{0}.mean,{0}.sd", b.signal);
    for (double p : probabilities) text += fmt::format(",{}.q{:g}", b.signal, p);
  }
  text += "\n";
  for (std::size_t k = 0; k < result.times.size(); ++k) {
    text += fmt::format("{:.17g}", result.times[k]);
    for (const runtime::SignalBands& b : result.bands) {
      const runtime::SampleStatistics& s = b.at_time[k];
      text += "," + field(s.mean) + "," + field(s.standard_deviation);
      for (double q : s.quantiles) text += "," + field(q);
    }
    text += "\n";
  }
  return text;
}

namespace {

long left_out(const distribute::EnsembleResult& r, std::size_t measure) {
  return measure < r.measures_left_out.size() ? r.measures_left_out[measure] : 0;
}

// "": the left-out samples look like the rest in every drawn value
std::string bias_text(const distribute::EnsembleResult& r, const runtime::EnsembleSetup& setup, std::size_t measure) {
  if (measure >= r.measures_bias.size() || r.measures_bias[measure].variable < 0) return "";
  const runtime::SelectionDependence& b = r.measures_bias[measure];
  return fmt::format("; they have {} {} than the rest (Welch t = {:.3g}): the statistics over the rest are biased",
                     b.t > 0 ? "larger" : "smaller", setup.variations[std::size_t(b.variable)].name, b.t);
}

// said on standard error too, so that a JSON reader's log shows it
void warn_left_out(const distribute::EnsembleResult& r, const runtime::EnsembleSetup& setup) {
  for (std::size_t i = 0; i < r.measures.size(); ++i)
    if (long left = left_out(r, i); left > 0)
      std::cerr << fmt::format("eomgen: warning: {}: {} of the {} finished samples left out (undefined for them){}\n",
                               setup.measures[i].text(), left, r.samples - r.failed, bias_text(r, setup, i));
}

}  // namespace

void print_ensemble_text(const distribute::EnsembleResult& r, const EnsembleDescription& d) {
  const runtime::EnsembleSetup& setup = *d.setup;
  std::cout << fmt::format("{}: ensemble of {} samples over t = {:g} … {:g} s ({} output times) with {} on {} in {:.3f} s, "
                           "seed {}\n",
                           d.model, r.samples, setup.settings.t_start, setup.settings.t_end, r.times.size(), d.integrator,
                           d.ranks, r.seconds, setup.seed);
  for (const runtime::Variation& v : setup.variations)
    std::cout << fmt::format("  {} ~ {}\n", v.name, v.distribution.text());
  std::cout << fmt::format("  {} runs finished, {} failed\n", r.samples - r.failed, r.failed);
  for (std::size_t i = 0; i < r.measures.size(); ++i) {
    const runtime::SampleStatistics& s = r.measures[i];
    std::cout << fmt::format("  {}: mean {:.10g}, sd {:.6g}, standard error of the mean {:.3g} ({} samples); {}\n",
                             setup.measures[i].text(), s.mean, s.standard_deviation, s.standard_error, s.count,
                             quantiles_text(s, d.probabilities));
    if (long left = left_out(r, i); left > 0)
      std::cout << fmt::format("    {} of the {} finished samples left out: {} is undefined for them{}\n", left,
                               r.samples - r.failed, setup.measures[i].text(), bias_text(r, setup, i));
  }
  for (const runtime::SignalBands& b : r.bands) {
    const runtime::SampleStatistics& s = b.at_time.back();
    std::cout << fmt::format("  {} at t = {:g}: mean {:.6g}, sd {:.6g}; {}\n", b.signal, r.times.back(), s.mean,
                             s.standard_deviation, quantiles_text(s, d.probabilities));
  }
}

void print_ensemble_json(const distribute::EnsembleResult& r, const EnsembleDescription& d) {
  const runtime::EnsembleSetup& setup = *d.setup;
  std::string variations, measures, finals;
  for (std::size_t i = 0; i < setup.variations.size(); ++i)
    variations += fmt::format("{}{{\"name\": {}, \"distribution\": \"{}\"}}", i ? ", " : "",
                              json_quoted(setup.variations[i].name), setup.variations[i].distribution.text());
  warn_left_out(r, setup);
  for (std::size_t i = 0; i < r.measures.size(); ++i)
    measures += fmt::format("{}{{\"measure\": {}, {}, \"left_out\": {}, \"biased\": {}}}", i ? ", " : "",
                            json_quoted(setup.measures[i].text()), statistics_json(r.measures[i], d.probabilities),
                            left_out(r, i), bias_text(r, setup, i).empty() ? "false" : "true");
  for (std::size_t i = 0; i < r.bands.size(); ++i)
    finals += fmt::format("{}{{\"signal\": {}, {}}}", i ? ", " : "", json_quoted(r.bands[i].signal),
                          statistics_json(r.bands[i].at_time.back(), d.probabilities));
  std::cout << fmt::format("{{\"model\": {}, \"samples\": {}, \"failed\": {}, \"seed\": {}, \"integrator\": \"{}\", "
                           "\"t_end\": {}, \"ranks\": {}, \"seconds\": {}, \"interrupted\": {}, \"variations\": [{}], "
                           "\"measures\": [{}], \"at_end\": [{}]}}\n",
                           json_quoted(d.model), r.samples, r.failed, setup.seed, d.integrator, json_number(setup.settings.t_end),
                           d.rank_count, json_number(r.seconds), r.interrupted ? "true" : "false", variations, measures, finals);
}

}  // namespace eomgen::studies
