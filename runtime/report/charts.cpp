#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include <fmt/format.h>

#include "report/reports.hpp"

namespace eomgen::runtime {

std::string energy_chart_path(const std::string& png_path) {
  std::string base = png_path.size() > 4 && png_path.substr(png_path.size() - 4) == ".png"
                         ? png_path.substr(0, png_path.size() - 4)
                         : png_path;
  return base + "_energy.png";
}

namespace {
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}
}  // namespace

std::string draw_charts(const eomgen_model_abi& m, const Trajectory& trajectory, const std::string& png_path,
                        bool energy_chart) {
  std::string data = png_path + ".data.tmp", script = png_path + ".gp.tmp";
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
      quoted(png_path), quoted(fmt::format("{}: coordinates", m.name)));
  for (std::size_t i = 0; i < m.num_coordinates; ++i)
    plot += fmt::format("{}{} using 1:{} with lines lw 2 title {}", i ? ", " : "", quoted(data), i + 2,
                        quoted(m.coordinate_names[i]));
  plot += "\n";
  if (energy_chart)
    plot += fmt::format(
        "set output {}\nset title {}\nset key inside top left\nset ylabel '|E(t) - E(0)| / |E(0)|'\nset logscale y\nset format y '%.0e'\n"
        "plot {} using 1:{} with lines lw 2 title 'relative energy error'\n",
        quoted(energy_chart_path(png_path)), quoted(fmt::format("{}: energy error", m.name)), quoted(data),
        m.num_coordinates + 2);
  std::ofstream(script) << plot;
  int status = std::system(fmt::format("gnuplot {} 2> {}.log", quoted(script), quoted(script)).c_str());
  std::remove(data.c_str());
  std::string log = script + ".log";
  std::remove(script.c_str());
  if (status != 0) {
    std::ifstream in(log);
    std::string why((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::remove(log.c_str());
    return "gnuplot failed" + (why.empty() ? std::string(" (is gnuplot installed?)") : ": " + why);
  }
  std::remove(log.c_str());
  return {};
}

}  // namespace eomgen::runtime
