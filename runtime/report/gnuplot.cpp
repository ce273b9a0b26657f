#include "report/gnuplot.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

namespace eomgen::runtime {

std::string gnuplot_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string run_gnuplot(const std::string& script, const std::string& stem) {
  std::string file = stem + ".gp.tmp", log = stem + ".gp.log";
  std::ofstream(file) << script;
  int status = std::system(fmt::format("gnuplot {} 2> {}", gnuplot_quoted(file), gnuplot_quoted(log)).c_str());
  std::ifstream in(log);
  std::string why((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::remove(file.c_str());
  std::remove(log.c_str());
  if (status == 0) return {};
  return "gnuplot failed" + (why.empty() ? std::string(" (is gnuplot installed?)") : ": " + why);
}

}  // namespace eomgen::runtime
