/// @file Charts of a trajectory's named quantities: the model's outputs over time, and
/// one quantity against another (a path in the plane, a phase portrait).
#include <cmath>
#include <cstdio>
#include <fstream>

#include <fmt/format.h>

#include "report/gnuplot.hpp"
#include "report/reports.hpp"

namespace eomgen::runtime {

std::string outputs_chart_path(const std::string& png_path) { return chart_path(png_path, "_outputs"); }
std::string xy_chart_path(const std::string& png_path) { return chart_path(png_path, "_xy"); }

bool trajectory_column(const eomgen_model_abi& m, const Trajectory& tr, const std::string& name, std::vector<double>& out) {
  out.clear();
  for (std::size_t k = 0; k < tr.times.size(); ++k) {
    if (name == "t") out.push_back(tr.times[k]);
    else if (name == "energy") out.push_back(tr.energies[k]);
    else {
      bool found = false;
      for (std::size_t i = 0; i < m.num_states && !found; ++i)
        if (name == m.state_names[i]) out.push_back(tr.states[k][i]), found = true;
      for (std::size_t i = 0; i < m.num_outputs && !found; ++i)
        if (name == m.output_names[i]) out.push_back(tr.outputs[k][i]), found = true;
      if (!found) return false;
    }
  }
  return true;
}

std::string draw_outputs_chart(const eomgen_model_abi& m, const Trajectory& tr, const std::string& png_path) {
  std::string data = png_path + ".data.tmp";
  {
    std::ofstream out(data);
    for (std::size_t k = 0; k < tr.times.size(); ++k) {
      out << fmt::format("{:.17g}", tr.times[k]);
      for (double y : tr.outputs[k]) out << fmt::format(" {:.17g}", y);
      out << "\n";
    }
  }
  std::string plot = fmt::format(
      "set terminal pngcairo size 1000,560 noenhanced\nset output {}\nset title {}\nset xlabel 't [s]'\n"
      "set ylabel 'outputs'\nset grid\nset key outside right\nplot ",
      gnuplot_quoted(png_path), gnuplot_quoted(fmt::format("{}: outputs", m.name)));
  for (std::size_t i = 0; i < m.num_outputs; ++i)
    plot += fmt::format("{}{} using 1:{} with lines lw 2 title {}", i ? ", " : "", gnuplot_quoted(data), i + 2,
                        gnuplot_quoted(m.output_names[i]));
  std::string failure = run_gnuplot(plot + "\n", png_path);
  std::remove(data.c_str());
  return failure;
}

std::string draw_xy_chart(const eomgen_model_abi& m, const Trajectory& tr, const std::string& x_name,
                          const std::string& y_name, const std::string& png_path) {
  std::vector<double> x, y;
  if (!trajectory_column(m, tr, x_name, x) || !trajectory_column(m, tr, y_name, y))
    return fmt::format("no quantity named {} in the trajectory", trajectory_column(m, tr, x_name, x) ? y_name : x_name);
  std::string data = png_path + ".data.tmp";
  {
    std::ofstream out(data);
    for (std::size_t k = 0; k < x.size(); ++k) out << fmt::format("{:.17g} {:.17g}\n", x[k], y[k]);
  }
  // two outputs or two coordinates are most likely lengths of one plane: equal scales
  auto kind = [&m](const std::string& name) {
    for (std::size_t i = 0; i < m.num_outputs; ++i)
      if (name == m.output_names[i]) return 1;
    for (std::size_t i = 0; i < m.num_coordinates; ++i)
      if (name == m.coordinate_names[i]) return 2;
    return 0;
  };
  bool equal_scales = kind(x_name) != 0 && kind(x_name) == kind(y_name);
  std::string plot = fmt::format(
      "set terminal pngcairo size 800,800 noenhanced\nset output {}\nset title {}\nset xlabel {}\nset ylabel {}\n"
      "set grid\n{}unset key\nplot {} using 1:2 with lines lw 2, {} every ::0::0 using 1:2 with points "
      "pt 7 ps 1.5\n",
      gnuplot_quoted(png_path), gnuplot_quoted(fmt::format("{}: {} against {} (dot: start)", m.name, y_name, x_name)),
      gnuplot_quoted(x_name), gnuplot_quoted(y_name), equal_scales ? "set size ratio -1\n" : "", gnuplot_quoted(data),
      gnuplot_quoted(data));
  std::string failure = run_gnuplot(plot, png_path);
  std::remove(data.c_str());
  return failure;
}

}  // namespace eomgen::runtime
