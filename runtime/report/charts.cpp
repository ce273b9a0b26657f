#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include <fmt/format.h>

#include "report/gnuplot.hpp"
#include "report/reports.hpp"

namespace eomgen::runtime {

std::string chart_path(const std::string& png_path, const std::string& suffix) {
  std::string base = png_path.size() > 4 && png_path.substr(png_path.size() - 4) == ".png"
                         ? png_path.substr(0, png_path.size() - 4)
                         : png_path;
  return base + suffix + ".png";
}

std::string energy_chart_path(const std::string& png_path) { return chart_path(png_path, "_energy"); }


std::string draw_charts(const eomgen_model_abi& m, const Trajectory& trajectory, const std::string& png_path,
                        bool energy_chart) {
  std::string data = png_path + ".data.tmp";
  {
    std::ofstream out(data);
    double e0 = trajectory.energies.empty() ? 0 : trajectory.energies.front();
    for (std::size_t k = 0; k < trajectory.times.size(); ++k) {
      out << fmt::format("{:.17g}", trajectory.times[k]);
      for (std::size_t i = 0; i < m.num_coordinates; ++i) out << fmt::format(" {:.17g}", trajectory.states[k][i]);
      double error = std::abs(trajectory.energies[k] - e0) / std::max(std::abs(e0), 1e-300);
      out << fmt::format(" {:.17g}\n", std::max(error, 1e-17));
    }
  }
  std::string plot = fmt::format(
      "set terminal pngcairo size 1000,560 noenhanced\nset output {}\nset title {}\nset xlabel 't [s]'\n"
      "set ylabel 'coordinates'\nset grid\nset key outside right\nplot ",
      gnuplot_quoted(png_path), gnuplot_quoted(fmt::format("{}: coordinates", m.name)));
  for (std::size_t i = 0; i < m.num_coordinates; ++i)
    plot += fmt::format("{}{} using 1:{} with lines lw 2 title {}", i ? ", " : "", gnuplot_quoted(data), i + 2,
                        gnuplot_quoted(m.coordinate_names[i]));
  plot += "\n";
  if (energy_chart)
    plot += fmt::format(
        "set output {}\nset title {}\nset key inside top left\nset ylabel '|E(t) - E(0)| / |E(0)|'\nset logscale y\nset format y '%.0e'\n"
        "plot {} using 1:{} with lines lw 2 title 'relative energy error'\n",
        gnuplot_quoted(energy_chart_path(png_path)), gnuplot_quoted(fmt::format("{}: energy error", m.name)), gnuplot_quoted(data),
        m.num_coordinates + 2);
  std::string failure = run_gnuplot(plot, png_path);
  std::remove(data.c_str());
  return failure;
}

}  // namespace eomgen::runtime
