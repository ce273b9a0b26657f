/// @file The band chart of an ensemble: how the spread of the samples grows over time.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include <fmt/format.h>

#include "report/gnuplot.hpp"
#include "report/reports.hpp"

namespace eomgen::runtime {

std::string draw_ensemble_bands(const std::string& title, const std::vector<double>& times,
                                const std::vector<SignalBands>& bands, const std::vector<double>& probabilities,
                                const std::string& png_path) {
  if (bands.empty()) return "no signals to draw";
  std::size_t lowest = 0, highest = 0, median = probabilities.size();
  for (std::size_t i = 0; i < probabilities.size(); ++i) {
    if (probabilities[i] < probabilities[lowest]) lowest = i;
    if (probabilities[i] > probabilities[highest]) highest = i;
    if (probabilities[i] == 0.5) median = i;
  }
  bool quantile_band = probabilities.size() >= 2;
  std::string plot = fmt::format("set terminal pngcairo size 1000,{} noenhanced\nset output {}\nset multiplot layout {},1 title {}\n",
                                 std::max<std::size_t>(420, 300 * bands.size()), gnuplot_quoted(png_path), bands.size(),
                                 gnuplot_quoted(title));
  std::vector<std::string> data_files;
  for (std::size_t b = 0; b < bands.size(); ++b) {
    std::string data = fmt::format("{}.data{}.tmp", png_path, b);
    data_files.push_back(data);
    std::ofstream out(data);
    // t, mean, mean − sd, mean + sd, lowest quantile, highest quantile, median
    for (std::size_t k = 0; k < times.size(); ++k) {
      const SampleStatistics& s = bands[b].at_time[k];
      double sd = std::isfinite(s.standard_deviation) ? s.standard_deviation : 0.0;
      auto q = [&](std::size_t i) { return i < s.quantiles.size() ? s.quantiles[i] : NAN; };
      out << fmt::format("{:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g}\n", times[k], s.mean, s.mean - sd,
                         s.mean + sd, q(lowest), q(highest), q(median));
    }
    std::string file = gnuplot_quoted(data);
    plot += fmt::format("set xlabel 't [s]'\nset ylabel {}\nset grid\nset key outside right\nplot ", gnuplot_quoted(bands[b].signal));
    if (quantile_band)
      plot += fmt::format("{} using 1:5:6 with filledcurves fc rgb '#c6dbef' title {}, ", file,
                          gnuplot_quoted(fmt::format("q{:g} … q{:g}", probabilities[lowest], probabilities[highest])));
    plot += fmt::format("{} using 1:3:4 with filledcurves fc rgb '#6baed6' title 'mean ± sd', ", file);
    plot += fmt::format("{} using 1:2 with lines lw 2 lc rgb '#08306b' title 'mean'", file);
    if (median < probabilities.size()) plot += fmt::format(", {} using 1:7 with lines lw 1 dt 2 lc rgb '#cb181d' title 'median'", file);
    plot += "\n";
  }
  plot += "unset multiplot\n";
  std::string failure = run_gnuplot(plot, png_path);
  for (const std::string& f : data_files) std::remove(f.c_str());
  return failure;
}

}  // namespace eomgen::runtime
