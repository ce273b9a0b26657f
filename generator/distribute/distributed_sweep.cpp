#include "distribute/distributed_sweep.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace eomgen::distribute {

namespace {

// A point of a map travels as [has equilibrium, degree, state...]: a fixed width.
std::vector<double> pack_map_rows(const runtime::StabilityMap& map, Block rows, std::size_t states) {
  std::vector<double> out;
  for (long j = rows.begin; j < rows.end; ++j)
    for (int i = 0; i < map.x.count; ++i) {
      std::size_t at = static_cast<std::size_t>(j) * map.x.count + i;
      out.push_back(map.states[at].empty() ? 0.0 : 1.0);
      out.push_back(map.degree[at]);
      for (std::size_t k = 0; k < states; ++k) out.push_back(map.states[at].empty() ? NAN : map.states[at][k]);
    }
  return out;
}

void unpack_map(const std::vector<double>& all, std::size_t states, runtime::StabilityMap& map) {
  std::size_t width = 2 + states, points = map.degree.size();
  if (all.size() != width * points) throw std::logic_error("gathered map has the wrong size");
  map.computed = 0;
  for (std::size_t at = 0; at < points; ++at) {
    const double* p = all.data() + at * width;
    map.degree[at] = p[1];
    map.states[at] = p[0] != 0 ? std::vector<double>(p + 2, p + width) : std::vector<double>{};
    map.computed += !std::isnan(p[1]);
  }
}

// The verdicts a point can have; a point travels as [verdict index (−1: none), tolerance,
// count, Re λ1, Im λ1, ...].
const std::vector<std::string>& verdict_names() {
  static const std::vector<std::string> names{"asymptotically_stable", "marginally_stable", "unstable"};
  return names;
}

std::vector<double> pack_points(const runtime::EigenvalueSweep& s, Block points) {
  std::vector<double> out;
  for (long k = points.begin; k < points.end; ++k) {
    const std::string& verdict = s.verdicts[std::size_t(k)];
    long code = -1;
    for (std::size_t v = 0; v < verdict_names().size(); ++v)
      if (verdict_names()[v] == verdict) code = long(v);
    if (code < 0 && !verdict.empty()) throw std::logic_error("unknown verdict " + verdict);
    out.push_back(double(code));
    out.push_back(s.tolerances[std::size_t(k)]);
    out.push_back(double(s.eigenvalues[std::size_t(k)].size()));
    for (auto l : s.eigenvalues[std::size_t(k)]) {
      out.push_back(l.real());
      out.push_back(l.imag());
    }
  }
  return out;
}

void unpack_points(const std::vector<double>& all, runtime::EigenvalueSweep& s) {
  std::size_t at = 0;
  for (std::size_t k = 0; k < std::size_t(s.axis.count); ++k) {
    if (at + 3 > all.size()) throw std::logic_error("gathered sweep is too short");
    long code = long(all[at]);
    s.verdicts[k] = code < 0 ? "" : verdict_names().at(std::size_t(code));
    s.tolerances[k] = all[at + 1];
    std::size_t count = std::size_t(all[at + 2]);
    at += 3;
    s.eigenvalues[k].clear();
    for (std::size_t e = 0; e < count; ++e, at += 2) s.eigenvalues[k].emplace_back(all.at(at), all.at(at + 1));
  }
}

}  // namespace

runtime::StabilityMap distributed_map(const Ranks& ranks, const runtime::Problem& base, const std::vector<double>& start,
                                      bool fixed, runtime::SweepAxis x, runtime::SweepAxis y, unsigned threads,
                                      const std::function<void(long, long)>& progress, const std::atomic<bool>& stop) {
  auto started = std::chrono::steady_clock::now();
  Block rows = ranks.share(y.count);
  runtime::StabilityMap map =
      runtime::sweep(base, start, fixed, x, y, threads, progress, stop, runtime::PointRange{rows.begin, rows.end});
  if (ranks.size() == 1) return map;
  std::size_t states = base.model->num_states;
  std::vector<double> all = ranks.gather(pack_map_rows(map, rows, states));
  map.interrupted = ranks.any(map.interrupted);
  if (ranks.is_root()) unpack_map(all, states, map);
  map.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return map;
}

runtime::EigenvalueSweep distributed_eigenvalue_sweep(const Ranks& ranks, const runtime::Problem& base,
                                                      const runtime::StartState& start, bool fixed, runtime::SweepAxis axis,
                                                      double resolution, unsigned threads,
                                                      const std::function<void(long, long)>& progress,
                                                      const std::atomic<bool>& stop) {
  auto started = std::chrono::steady_clock::now();
  Block points = ranks.share(axis.count);
  runtime::EigenvalueSweep s = runtime::sweep_eigenvalues(base, start, fixed, axis, resolution, threads, progress, stop,
                                                          runtime::PointRange{points.begin, points.end});
  if (ranks.size() == 1) return s;
  std::vector<double> all = ranks.gather(pack_points(s, points));
  s.interrupted = ranks.any(s.interrupted);
  if (ranks.is_root()) {
    unpack_points(all, s);
    if (!s.interrupted) runtime::locate_axis_crossings(s, base, start, fixed, resolution);
  }
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return s;
}

}  // namespace eomgen::distribute
