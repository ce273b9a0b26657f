#include "studies/linear_charts.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

#include <fmt/format.h>

#include "report/gnuplot.hpp"
#include "report/reports.hpp"

namespace eomgen::studies {

namespace {

using runtime::gnuplot_quoted;

std::string draw_modes(const eomgen_model_abi& m, const LinearReport& r, const std::string& png) {
  std::string data = png + ".data.tmp";
  {
    std::ofstream out(data);
    for (std::size_t k = 0; k < m.num_coordinates; ++k) {
      out << k + 1;
      for (const runtime::NaturalMode& mode : r.modes.modes) out << fmt::format(" {:.17g}", mode.shape(static_cast<Eigen::Index>(k)));
      out << "\n";
    }
  }
  std::string tics;
  for (std::size_t k = 0; k < m.num_coordinates; ++k) tics += fmt::format("{}{} {}", k ? ", " : "", gnuplot_quoted(m.coordinate_names[k]), k + 1);
  std::string plot = fmt::format("set terminal pngcairo size 1000,560 noenhanced\nset output {}\nset title {}\n"
                                 "set xtics ({})\nset ylabel 'mass-normalized shape'\nset grid\nset key outside right\n"
                                 "set xrange [0.5:{}.5]\nplot ",
                                 gnuplot_quoted(png), gnuplot_quoted(fmt::format("{}: mode shapes", m.name)), tics,
                                 m.num_coordinates);
  for (std::size_t i = 0; i < r.modes.modes.size(); ++i) {
    const runtime::NaturalMode& mode = r.modes.modes[i];
    std::string title = mode.rigid_body ? fmt::format("mode {}: rigid body", i + 1)
                                        : fmt::format("mode {}: {:.4g} rad/s", i + 1, mode.omega);
    plot += fmt::format("{}{} using 1:{} with linespoints lw 2 pt 7 title {}", i ? ", " : "", gnuplot_quoted(data), i + 2,
                        gnuplot_quoted(title));
  }
  std::string failure = runtime::run_gnuplot(plot + "\n", png);
  std::remove(data.c_str());
  return failure;
}

// one panel per mode: the bodies at rest (grey) and displaced along the mode
std::string draw_deformed(const eomgen_model_abi& m, const LinearReport& r, const std::string& png) {
  const DeformedShapes& d = r.deformed;
  std::string data = png + ".data.tmp";
  {
    std::ofstream out(data);
    for (std::size_t i = 0; i < d.modes.size(); ++i) {
      for (std::size_t b = 0; b < d.rest.size(); ++b)
        out << fmt::format("{:.17g} {:.17g} {:.17g} {:.17g}\n", d.rest[b][0], d.rest[b][1], d.modes[i][b][0], d.modes[i][b][1]);
      out << "\n\n";  // one gnuplot index per mode
    }
  }
  std::size_t panels = d.modes.size();
  std::string plot = fmt::format("set terminal pngcairo size {},480 noenhanced\nset output {}\nset multiplot layout 1,{} title {}\n"
                                 "set grid\nset key bottom right\nset xlabel {}\nset ylabel {}\n{}",
                                 std::min<std::size_t>(1800, 120 + 360 * panels), gnuplot_quoted(png), panels,
                                 gnuplot_quoted(fmt::format("{}: deformed shapes of the modes", m.name)),
                                 gnuplot_quoted(d.horizontal), gnuplot_quoted(d.vertical),
                                 d.stations ? "set offsets 0.5, 0.5, 0.1, 0.1\n" : "set size ratio -1\nset offsets graph 0.1, 0.1, 0.1, 0.1\n");
  for (std::size_t i = 0; i < panels; ++i) {
    const runtime::NaturalMode& mode = r.modes.modes[i];
    plot += fmt::format("set title {}\nplot {} index {} using 1:2 with linespoints lc rgb 'gray60' dt 2 pt 6 title 'rest', "
                        "'' index {} using 3:4 with linespoints lw 2 pt 7 title 'mode'\n",
                        gnuplot_quoted(mode.rigid_body ? fmt::format("mode {}: rigid body", i + 1)
                                                       : fmt::format("mode {}: {:.4g} rad/s", i + 1, mode.omega)),
                        gnuplot_quoted(data), i, i);
  }
  std::string failure = runtime::run_gnuplot(plot + "unset multiplot\n", png);
  std::remove(data.c_str());
  return failure;
}

// |G(iω)| in dB and arg G(iω) in degrees over four decades around the poles and zeros
std::string draw_bode(const eomgen_model_abi& m, const LinearReport::Pair& p, const std::string& png) {
  double low = INFINITY, high = 0;
  for (const auto& roots : {p.g.poles, p.g.zeros})
    for (const auto& z : roots) high = std::max(high, std::abs(z));
  // roots at zero (within rounding of the largest) set no frequency
  for (const auto& roots : {p.g.poles, p.g.zeros})
    for (const auto& z : roots)
      if (std::abs(z) > 1e-9 * high) low = std::min(low, std::abs(z));
  if (!std::isfinite(low)) low = high = 1;
  double from = std::log10(low) - 1.5, to = std::log10(high) + 1.5;
  std::string data = png + ".data.tmp";
  {
    std::ofstream out(data);
    for (int k = 0; k <= 800; ++k) {
      double w = std::pow(10.0, from + (to - from) * k / 800.0);
      std::complex<double> g = p.g.at({0.0, w});
      out << fmt::format("{:.17g} {:.17g} {:.17g}\n", w, 20 * std::log10(std::max(std::abs(g), 1e-300)), std::arg(g) * 180 / M_PI);
    }
  }
  std::string plot = fmt::format(
      "set terminal pngcairo size 1000,720 noenhanced\nset output {}\nset multiplot layout 2,1 title {}\n"
      "set logscale x\nset grid\nset ylabel '|G| [dB]'\nunset key\nplot {} using 1:2 with lines lw 2\n"
      "set ylabel 'phase [deg]'\nset xlabel 'omega [rad/s]'\nplot {} using 1:3 with lines lw 2\nunset multiplot\n",
      gnuplot_quoted(png), gnuplot_quoted(fmt::format("{}: Bode chart {} -> {}", m.name, p.input, p.output)),
      gnuplot_quoted(data), gnuplot_quoted(data));
  std::string failure = runtime::run_gnuplot(plot, png);
  std::remove(data.c_str());
  return failure;
}

}  // namespace

void draw_linear_charts(const eomgen_model_abi& m, const LinearReport& r, const std::string& png,
                        const std::vector<std::pair<std::string, std::string>>& bode) {
  std::vector<std::string> drawn;
  auto report = [&drawn](const std::string& failure, const std::string& path) {
    if (failure.empty()) drawn.push_back(path);
    else std::cerr << "eomgen: warning: no chart " << path << ": " << failure << "\n";
  };
  if (!r.modes.modes.empty()) report(draw_modes(m, r, runtime::chart_path(png, "_modes")), runtime::chart_path(png, "_modes"));
  if (!r.deformed.modes.empty())
    report(draw_deformed(m, r, runtime::chart_path(png, "_shapes")), runtime::chart_path(png, "_shapes"));
  for (const auto& [u, y] : bode)
    for (const LinearReport::Pair& p : r.transfer)
      if (p.input == u && p.output == y) {
        std::string path = runtime::chart_path(png, "_bode_" + u + "_" + y);
        report(draw_bode(m, p, path), path);
      }
  std::string list;
  for (const std::string& path : drawn) list += (list.empty() ? "" : ", ") + path;
  if (!list.empty()) std::cerr << "eomgen: charts in " << list << "\n";
}

}  // namespace eomgen::studies
