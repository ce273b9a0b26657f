/// @file With p = ∂S/∂q substituted into H(q, p, t), the Hamilton–Jacobi equation
/// ∂S/∂t + H = 0 (Hiller §3.8.5) holds for every q, t and constant α when S is a
/// complete integral. The residual is simplified; roots (sqrt, asin of the separated
/// S) often defeat GiNaC's normal form, so it is then evaluated at random real points.
#include "symbolic_analysis/hamilton_jacobi.hpp"

#include <cmath>
#include <map>
#include <random>
#include <sstream>

#include <fmt/format.h>

#include "kinematics/mechanics.hpp"
#include "model/expression_parser.hpp"
#include "symbolic/canonical_print.hpp"
#include "symbolic/evaluate.hpp"
#include "symbolic/simplify.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// the expression without comments, and where it starts (line, column) in the file
ExpressionText expression_of(const std::string& text, const std::string& path) {
  std::istringstream lines(text);
  std::string joined;
  int first = 0, number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    line = line.substr(0, line.find('#'));
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (!first) first = number;
    joined += (joined.empty() ? "" : " ") + line;
  }
  return {joined, {path, first ? first : 1, 1}, "action"};
}

// identifiers of S that name no symbol of the model and no function: the constants α
std::vector<std::string> constants_of(const std::string& text, const Symbols& s) {
  std::vector<std::string> found;
  for (std::size_t i = 0; i < text.size();) {
    char c = text[i];
    bool starts = std::isalpha(static_cast<unsigned char>(c)) || c == '_';
    bool after_number = i > 0 && (std::isdigit(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '.');
    if (!starts) { ++i; continue; }
    std::size_t end = i;
    while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_')) ++end;
    std::string name = text.substr(i, end - i);
    i = end;
    if (after_number || is_reserved_name(name) || s.by_name.count(name)) continue;
    if (std::find(found.begin(), found.end(), name) == found.end()) found.push_back(name);
  }
  return found;
}

// forces that H does not account for: the canonical equations' p' differs from −∂H/∂q
std::string nonconservative(const Equations& e) {
  MotionSymbols motion = motion_symbols(e.symbols);
  for (std::size_t j = 0; j < e.forcing.size(); ++j)
    if (!tidy(e.forcing[j] + e.hamiltonian.diff(e.symbols.coordinates[j]), motion).is_zero())
      return e.symbols.coordinate_names[j];
  return "";
}

struct Evaluation {
  double residual, scale;
};

// the residual at random real points: parameters and constants in [0.5, 2], coordinates in
// [−0.5, 0.5], t in [0, 2]; points where S is not real (a root of a negative number) are skipped
void check_at_points(const Symbols& s, const ex& dS_dt, const ex& H_of_S, HamiltonJacobiCheck& c) {
  std::mt19937 random(20261123);
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(random); };
  for (int attempt = 0; attempt < 2000 && c.points < 40; ++attempt) {
    std::map<std::string, double> at;
    for (const auto& p : s.parameters) at[p.get_name()] = uniform(0.5, 2);
    for (const auto& q : s.coordinates) at[q.get_name()] = uniform(-0.5, 0.5);
    at[s.time.get_name()] = uniform(0, 2);
    for (const auto& u : s.inputs) at[u.get_name()] = 0;
    auto value_of = [&](const GiNaC::symbol& x) { return at.count(x.get_name()) ? at[x.get_name()] : NAN; };
    Evaluation v{NAN, NAN};
    try {
      double a = evaluate(dS_dt, value_of), b = evaluate(H_of_S, value_of);
      v = {a + b, std::abs(a) + std::abs(b)};
    } catch (const std::exception&) {
      continue;
    }
    if (!std::isfinite(v.residual)) continue;
    ++c.points;
    double relative = std::abs(v.residual) / std::max(v.scale, 1e-300);
    c.largest_relative_residual = std::max(c.largest_relative_residual, relative);
    if (relative > 1e-12 && c.failure.empty()) {
      std::string where;
      for (const auto& [name, value] : at) where += fmt::format("{}{} = {:.6g}", where.empty() ? "" : ", ", name, value);
      c.failure = fmt::format("dS/dt + H = {:.6g} (relative to its terms {:.3g}) at {}", v.residual, relative, where);
    }
  }
  if (c.points == 0) c.failure = "S is not real at any of 2000 random points: no check was possible";
}

}  // namespace

std::optional<HamiltonJacobiCheck> check_hamilton_jacobi(const Equations& e, const std::string& text,
                                                         const std::string& path, Diagnostics& diagnostics) {
  ExpressionText source = expression_of(text, path);
  if (source.text.empty()) {
    diagnostics.error({path, 1, 1}, "action", "the file holds no expression for S", "write S(q, alpha, t) on one line");
    return std::nullopt;
  }
  if (std::string q = nonconservative(e); !q.empty()) {
    diagnostics.error({path, 1, 1}, "action",
                      fmt::format("the model's forces on {} do not derive from H (dissipation or applied forces), and "
                                  "the Hamilton–Jacobi equation describes conservative systems only", q),
                      "remove the dissipation and forces, or set them to zero in a copy of the model");
    return std::nullopt;
  }
  // the constants become parameters of a copy of the symbols, so the model's parser reads S
  HamiltonJacobiCheck c;
  Symbols s = e.symbols;
  c.constants = constants_of(source.text, s);
  for (const std::string& name : c.constants) {
    s.by_name[name] = {SymbolKind::parameter, s.parameters.size()};
    s.parameter_names.push_back(name);
    s.parameters.emplace_back(name);
    s.parameter_defaults.push_back(1);
  }
  auto action = parse_expression(source, s, {allow_configuration, "the action S"}, diagnostics);
  if (!action) return std::nullopt;
  c.action = *action;
  GiNaC::exmap momenta;
  for (std::size_t j = 0; j < s.coordinates.size(); ++j) {
    ex p = c.action.diff(s.coordinates[j]);
    c.momenta.push_back({e.symbols.velocities[j].get_name(), p});
    momenta[e.symbols.velocities[j]] = p;
  }
  ex dS_dt = c.action.diff(s.time), H_of_S = e.hamiltonian.subs(momenta);
  MotionSymbols motion = motion_symbols(s);
  c.residual = tidy((dS_dt + H_of_S).normal(), motion);
  c.symbolic = c.residual.is_zero();
  if (!c.symbolic) check_at_points(s, dS_dt, H_of_S, c);
  return c;
}

}  // namespace eomgen
