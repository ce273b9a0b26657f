#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include <fmt/format.h>

#include "report/degree_colours.hpp"
#include "report/gnuplot.hpp"
#include "report/reports.hpp"

namespace eomgen::runtime {

namespace {

// a logarithmic axis drawn in log10 of its values: the image's cells are then even on the page
double map_coordinate(const SweepAxis& axis, int k) { return axis.logarithmic ? std::log10(axis.value(k)) : axis.value(k); }
double map_coordinate(const SweepAxis& axis, double value) { return axis.logarithmic ? std::log10(value) : value; }
std::string map_axis_label(const SweepAxis& axis, const std::string& name) { return axis.logarithmic ? "log10(" + name + ")" : name; }

void write_grid(const std::string& path, const StabilityMap& map, const std::vector<double>& values) {
  std::ofstream out(path);
  for (int j = 0; j < map.y.count; ++j) {
    for (int i = 0; i < map.x.count; ++i) {
      double v = values[static_cast<std::size_t>(j) * map.x.count + i];
      out << fmt::format("{:.12g} {:.12g} {}\n", map_coordinate(map.x, i), map_coordinate(map.y, j), std::isnan(v) ? "NaN" : fmt::format("{:.9g}", v));
    }
    out << "\n";
  }
}
}  // namespace

std::string draw_stability_map(const StabilityMap& map, const std::string& x_name, const std::string& y_name,
                               const std::string& title, const std::vector<double>& symbolic_margin,
                               const std::string& png_path) {
  std::string base = png_path + ".tmp", data = base + ".map", boundary = base + ".boundary", symbolic = base + ".symbolic",
              symbolic_boundary = base + ".symbolic_boundary";
  // a colour scale symmetric about zero, stable blue, unstable red; the colours keep the degrees'
  // signs, so the zero contour is the same in them
  DegreeColours colours = degree_colours(map.degree);
  std::vector<double> coloured;
  for (double d : map.degree) coloured.push_back(colours.colour(d));
  write_grid(data, map, coloured);
  bool with_symbolic = !symbolic_margin.empty();
  if (with_symbolic) write_grid(symbolic, map, symbolic_margin);
  double range = colours.range();
  std::string colour_bar =
      colours.knee > 0 ? fmt::format("set cbtics {}\nset cblabel 'largest real part of the eigenvalues, log. beyond ±{:.2g}'\n",
                                     colours.tics(), colours.knee)
                       : "set cblabel 'largest real part of the eigenvalues'\n";
  std::string contour = fmt::format(
      "set contour base\nset cntrparam levels discrete 0\nunset surface\nset view map\n"
      "set table {}\nsplot {} using 1:2:3 with lines\nunset table\n",
      gnuplot_quoted(boundary), gnuplot_quoted(data));
  if (with_symbolic)
    contour += fmt::format("set table {}\nsplot {} using 1:2:3 with lines\nunset table\n", gnuplot_quoted(symbolic_boundary),
                           gnuplot_quoted(symbolic));
  std::string plot = fmt::format(
      "set terminal pngcairo size 900,720 noenhanced\nset output {}\n{}"
      "unset contour\nset title {}\nset xlabel {}\nset ylabel {}\n"
      "set palette defined (-1 '#2166ac', -0.15 '#92c5de', 0 '#f7f7f7', 0.15 '#f4a582', 1 '#b2182b')\n"
      "set cbrange [{}:{}]\n{}set rmargin 14\nset key outside top center horizontal\n"
      "set xrange [{}:{}]\nset yrange [{}:{}]\n"
      "plot {} using 1:2:3 with image notitle, {} using 1:2 with lines lw 2 lc rgb 'black' title 'stability boundary (eigenvalues)'",
      gnuplot_quoted(png_path), contour, gnuplot_quoted(title), gnuplot_quoted(map_axis_label(map.x, x_name)),
      gnuplot_quoted(map_axis_label(map.y, y_name)), -range, range, colour_bar, map_coordinate(map.x, map.x.low), map_coordinate(map.x, map.x.high),
      map_coordinate(map.y, map.y.low), map_coordinate(map.y, map.y.high), gnuplot_quoted(data), gnuplot_quoted(boundary));
  if (with_symbolic)
    plot += fmt::format(", {} using 1:2 with lines lw 3 dt 2 lc rgb '#1b7837' title 'Hurwitz conditions (symbolic)'",
                        gnuplot_quoted(symbolic_boundary));
  plot += "\n";
  std::string failure = run_gnuplot(plot, png_path);
  for (const std::string& f : {data, boundary, symbolic, symbolic_boundary}) std::remove(f.c_str());
  return failure;
}

}  // namespace eomgen::runtime
