/// @file The classical chart of stability along a parameter (as in Meijaard et al.'s
/// figure of the bicycle's eigenvalues against speed): the real parts as filled dots,
/// the imaginary parts (|Im λ|, the damped frequencies) as open dots, the crossings of
/// the imaginary axis as vertical lines and the stable intervals shaded.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include <fmt/format.h>

#include "report/gnuplot.hpp"
#include "report/reports.hpp"

namespace eomgen::runtime {

namespace {

// a y range that shows the eigenvalues near the axis, not the one far-off fast decay
double vertical_extent(const EigenvalueSweep& s) {
  std::vector<double> sizes;
  for (const auto& point : s.eigenvalues)
    for (auto l : point) sizes.push_back(std::max(std::abs(l.real()), std::abs(l.imag())));
  if (sizes.empty()) return 1;
  std::sort(sizes.begin(), sizes.end());
  return std::max(1e-9, 1.1 * sizes[std::min(sizes.size() - 1, sizes.size() * 9 / 10)]);
}

}  // namespace

std::string draw_eigenvalue_sweep(const EigenvalueSweep& s, const std::string& parameter, const std::string& title,
                                  const std::string& png_path) {
  std::string data = png_path + ".data.tmp";
  {
    std::ofstream out(data);
    for (int k = 0; k < s.axis.count; ++k)
      for (auto l : s.eigenvalues[std::size_t(k)])
        out << fmt::format("{:.12g} {:.12g} {:.12g}\n", s.axis.value(k), l.real(), std::abs(l.imag()));
  }
  double extent = vertical_extent(s);
  std::string script = fmt::format(
      "set terminal pngcairo size 1000,640 noenhanced\nset output {}\nset title {}\nset xlabel {}\n"
      "set ylabel 'eigenvalues [1/s]'\nset grid\nset key outside top center horizontal\nset xrange [{}:{}]\n"
      "set yrange [{}:{}]\nset xzeroaxis lt -1 lw 1\n{}",
      gnuplot_quoted(png_path), gnuplot_quoted(title), gnuplot_quoted(parameter), s.axis.low, s.axis.high, -extent, extent,
      s.axis.logarithmic ? "set logscale x\n" : "");
  for (const StableInterval& i : s.stable)
    script += fmt::format("set object rect from {:.12g}, graph 0 to {:.12g}, graph 1 fc rgb '#d9f0d3' fs solid 0.6 noborder behind\n",
                          i.low, i.high);
  for (const AxisCrossing& c : s.crossings)
    script += fmt::format("set arrow from {0:.12g}, graph 0 to {0:.12g}, graph 1 nohead dt 2 lw 1.5 lc rgb '#444444'\n",
                          c.parameter);
  script += fmt::format(
      "plot {0} using 1:2 with points pt 7 ps 0.45 lc rgb '#b2182b' title 'Re λ', "
      "{0} using 1:($3 > 0 ? $3 : NaN) with points pt 6 ps 0.45 lc rgb '#2166ac' title '|Im λ|', "
      "NaN with boxes fc rgb '#d9f0d3' fs solid 0.6 title 'asymptotically stable'\n",
      gnuplot_quoted(data));
  std::string failure = run_gnuplot(script, png_path);
  std::remove(data.c_str());
  return failure;
}

}  // namespace eomgen::runtime
