#include "compare/equation_diff.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <regex>
#include <set>

#include <fmt/format.h>

#include "compare/same_motion.hpp"
#include "symbolic/canonical_print.hpp"
#include "symbolic/decimal_numbers.hpp"

namespace eomgen {

namespace {

using GiNaC::ex;

const std::set<std::string>& entry_words() {
  static const std::set<std::string> words{"M", "f", "T", "V", "R", "S", "y", "g", "C", "b", "s", "der"};
  return words;
}

// der(der(q)) → dd__q and der(q) → d__q, so that GiNaC's parser reads velocities and accelerations as symbols
std::string with_placeholders(const std::string& text) {
  static const std::regex second(R"(der\(\s*der\(\s*([A-Za-z_][A-Za-z0-9_]*)\s*\)\s*\))"), first(R"(der\(\s*([A-Za-z_][A-Za-z0-9_]*)\s*\))");
  return std::regex_replace(std::regex_replace(text, second, "dd__$1"), first, "d__$1");
}

class Renaming {
 public:
  explicit Renaming(const std::vector<std::pair<std::string, std::string>>& pairs) : map_(pairs.begin(), pairs.end()) {}
  std::string operator()(const std::string& name) const {
    auto it = map_.find(name);
    return it == map_.end() ? name : it->second;
  }
  // the identifiers inside an entry name (y[tip], C[c][q], der(q))
  std::string entry(const std::string& name) const {
    static const std::regex word(R"([A-Za-z_][A-Za-z0-9_]*)");
    std::string out;
    std::size_t last = 0;
    for (std::sregex_iterator i(name.begin(), name.end(), word), end; i != end; ++i) {
      out += name.substr(last, static_cast<std::size_t>(i->position()) - last);
      std::string w = i->str();
      out += entry_words().count(w) && i->position() == 0 ? w : (*this)(w);
      last = static_cast<std::size_t>(i->position() + i->length());
    }
    return out + name.substr(last);
  }

 private:
  std::map<std::string, std::string> map_;
};

// one symbol per name of the new side's vocabulary, and a parser table for each side
class SymbolSpace {
 public:
  GiNaC::ex symbol(const std::string& name) {
    auto it = symbols_.find(name);
    if (it != symbols_.end()) return it->second;
    return symbols_.emplace(name, GiNaC::realsymbol(name)).first->second;
  }
  // the names a side's expressions may use, each mapped through `rename`
  GiNaC::symtab table(const DerivationRecord& r, const Renaming& rename) {
    GiNaC::symtab t{{"Pi", GiNaC::Pi}};
    auto add = [&](const std::string& name) { t[name] = symbol(rename(name)); };
    auto add_motion = [&](const std::string& name) {
      add(name);
      t["d__" + name] = symbol("d__" + rename(name));
      t["dd__" + name] = symbol("dd__" + rename(name));
    };
    t["t"] = symbol("t");
    for (const std::string& q : r.coordinates) add_motion(q);
    for (const std::string& v : r.velocities)
      if (v.rfind("der(", 0) != 0) add_motion(v);
    for (const auto& p : r.parameters) add(p.first);
    for (const auto& u : r.inputs) add(u.first);
    for (const std::string& l : r.multipliers) add(l);
    return t;
  }
  const std::map<std::string, GiNaC::ex>& all() const { return symbols_; }

 private:
  std::map<std::string, GiNaC::ex> symbols_;
};

struct ParsedSide {
  std::map<std::string, ex> entries;  // by (renamed) entry name
  std::vector<std::string> order;
};

ParsedSide parse_side(const DerivationRecord& r, const GiNaC::symtab& table, const Renaming& rename, Diagnostics& d) {
  ParsedSide side;
  GiNaC::parser reader(table, true);
  for (const DerivedEntry& e : r.entries) {
    std::string name = rename.entry(e.name);
    try {
      side.entries[name] = reader(decimals_as_fractions(with_placeholders(e.text)));
      side.order.push_back(name);
    } catch (const std::exception& why) {
      d.error({r.path, 0, 0}, e.name, fmt::format("the expression '{}' does not read back: {}", e.text, why.what()),
              "derived-equations files are written by `eomgen derive --format json`; do not edit them by hand");
    }
  }
  return side;
}

// random values of every symbol: parameters about their defaults, velocities of both signs, and
// coordinates alternately away from 0 in (0.2, 1.3) (where square roots of the kinematics are real)
// and over (−4, 4), past ±π and negative (where −l·√(1 − sin²φ) and −l·cos φ part, or x³ and |x|³)
std::vector<GiNaC::exmap> sample_points(const SymbolSpace& space, const std::map<std::string, double>& defaults,
                                        const DiffOptions& o) {
  std::mt19937 random(o.seed);
  std::uniform_real_distribution<double> scale(0.5, 2), near(0.2, 1.3), wide(-4, 4), velocity(-2, 2), time(0, 2);
  std::vector<GiNaC::exmap> points(static_cast<std::size_t>(std::max(o.samples, 1)));
  for (std::size_t k = 0; k < points.size(); ++k)
    for (const auto& [name, symbol] : space.all()) {
      double v;
      if (auto it = defaults.find(name); it != defaults.end()) v = (it->second != 0 ? it->second : 1) * scale(random);
      else if (name == "t") v = time(random);
      else if (name.rfind("d__", 0) == 0 || name.rfind("dd__", 0) == 0) v = velocity(random);
      else v = k % 2 == 0 ? near(random) : wide(random);
      points[k][symbol] = GiNaC::numeric(v);
    }
  return points;
}

// abs, atan2 or a fractional power: a function with branches, where agreement at sampled
// points says nothing about the points between the branches
bool has_branches(const ex& e) {
  if (GiNaC::is_the_function<GiNaC::abs_SERIAL>(e) || GiNaC::is_the_function<GiNaC::atan2_SERIAL>(e)) return true;
  if (GiNaC::is_a<GiNaC::power>(e) && !e.op(1).info(GiNaC::info_flags::integer)) return true;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (has_branches(e.op(i))) return true;
  return false;
}

std::optional<double> value_at(const ex& e, const GiNaC::exmap& point) {
  try {
    ex v = e.subs(point).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return std::nullopt;
    return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
  } catch (const std::exception&) {
    return std::nullopt;  // a pole at this point
  }
}

// the placeholders back to der(q) for the report
std::string readable(const std::string& text) {
  static const std::regex second(R"(\bdd__([A-Za-z_][A-Za-z0-9_]*))"), first(R"(\bd__([A-Za-z_][A-Za-z0-9_]*))");
  return std::regex_replace(std::regex_replace(text, second, "der(der($1))"), first, "der($1)");
}

// the entry levels: text, then exact simplification, then 50-digit evaluation
void decide(EntryComparison& c, const ex& old_e, const ex& new_e, const std::vector<GiNaC::exmap>& points, double tolerance) {
  c.old_text = readable(canonical_text(old_e)), c.new_text = readable(canonical_text(new_e));
  if (c.old_text == c.new_text) {
    c.status = "identical", c.decided_by = "text";
    return;
  }
  ex difference = (old_e - new_e).expand();
  bool zero = difference.is_zero();
  if (!zero && c.old_text.size() + c.new_text.size() < 4000) zero = difference.normal().is_zero();
  if (zero) {
    c.status = "equivalent", c.decided_by = "symbolic";
    return;
  }
  c.decided_by = "numeric";
  int evaluated = 0;
  bool equal = true;
  for (const GiNaC::exmap& p : points) {
    ex d = (old_e - new_e).subs(p).evalf();
    auto a = value_at(old_e, p), b = value_at(new_e, p);
    if (!a || !b || !GiNaC::is_a<GiNaC::numeric>(d)) continue;
    ++evaluated;
    double size = std::max({1.0, std::abs(*a), std::abs(*b)});
    double abs = std::abs(GiNaC::ex_to<GiNaC::numeric>(d).to_double());
    c.max_abs_difference = std::max(c.max_abs_difference, abs);
    c.max_rel_difference = std::max(c.max_rel_difference, abs / size);
    equal = equal && abs <= tolerance * size;
  }
  c.status = equal && evaluated > 0 ? "equivalent" : "different";
  if (evaluated == 0) c.max_abs_difference = c.max_rel_difference = NAN;
  if (c.status == "equivalent" && (has_branches(old_e) || has_branches(new_e))) c.decided_by = "numeric on the samples";
}

void compare_names(const std::string& kind, std::vector<std::string> old_names, const std::vector<std::string>& new_names,
                   const Renaming& rename, EquationDiff& out) {
  for (std::string& n : old_names) n = rename(n);
  for (const std::string& n : new_names)
    if (std::find(old_names.begin(), old_names.end(), n) == old_names.end()) out.added.push_back(kind + " " + n);
  for (const std::string& n : old_names)
    if (std::find(new_names.begin(), new_names.end(), n) == new_names.end()) out.removed.push_back(kind + " " + n);
}

std::vector<std::string> first_of(const std::vector<std::pair<std::string, double>>& v) {
  std::vector<std::string> out;
  for (const auto& x : v) out.push_back(x.first);
  return out;
}

std::vector<std::string> old_symbol_names(const DerivationRecord& a) {
  std::vector<std::string> names = a.coordinates;
  for (const auto& p : a.parameters) names.push_back(p.first);
  for (const auto& u : a.inputs) names.push_back(u.first);
  names.insert(names.end(), a.outputs.begin(), a.outputs.end());
  names.insert(names.end(), a.velocities.begin(), a.velocities.end());
  names.insert(names.end(), a.multipliers.begin(), a.multipliers.end());
  // the names inside entry names: constraints (g[c], C[c][q]), pseudo-velocities (s[w])
  static const std::regex inside(R"(\[([A-Za-z_][A-Za-z0-9_]*)\])");
  for (const DerivedEntry& e : a.entries)
    for (std::sregex_iterator i(e.name.begin(), e.name.end(), inside), end; i != end; ++i) names.push_back((*i)[1].str());
  return names;
}

// a rename of a name the old side does not have would be silently ignored: a mistake
bool renames_name_old_symbols(const DerivationRecord& a, const DiffOptions& o, Diagnostics& d) {
  std::vector<std::string> names = old_symbol_names(a);
  for (const auto& [from, to] : o.renames)
    if (std::find(names.begin(), names.end(), from) == names.end())
      d.error({a.path, 0, 0}, "--rename " + from + "=" + to, from + " is not a symbol of " + a.path,
              suggest(from, names, "symbols"));
  return d.empty();
}

void compare_symbols(const DerivationRecord& a, const DerivationRecord& b, const Renaming& rename, const DiffOptions& o,
                     EquationDiff& out) {
  compare_names("coordinate", a.coordinates, b.coordinates, rename, out);
  compare_names("parameter", first_of(a.parameters), first_of(b.parameters), rename, out);
  compare_names("input", first_of(a.inputs), first_of(b.inputs), rename, out);
  compare_names("output", a.outputs, b.outputs, rename, out);
  compare_names("multiplier", a.multipliers, b.multipliers, rename, out);
  std::vector<std::string> old_names = old_symbol_names(a);
  for (const auto& [from, to] : o.renames)
    if (std::find(old_names.begin(), old_names.end(), from) != old_names.end()) out.renamed.emplace_back(from, to);
  auto defaults = [&](const auto& old_list, const auto& new_list) {
    for (const auto& [name, value] : old_list)
      for (const auto& [other, new_value] : new_list)
        if (rename(name) == other && value != new_value) out.defaults_changed.push_back({other, value, new_value});
  };
  defaults(a.parameters, b.parameters);
  defaults(a.inputs, b.inputs);
}

}  // namespace

// one side's M, f and kinematic equations in the shared symbols
MotionForm motion_form(const DerivationRecord& r, const ParsedSide& side, SymbolSpace& space, const Renaming& rename) {
  MotionForm m;
  m.time = space.symbol("t");
  for (const std::string& q : r.coordinates) {
    m.coordinates.push_back(space.symbol(rename(q)));
    m.coordinate_rates.push_back(space.symbol("d__" + rename(q)));
  }
  std::size_t k = r.velocities.size();
  for (const std::string& v : r.velocities)
    m.velocities.push_back(v.rfind("der(", 0) == 0 ? space.symbol("d__" + rename(v.substr(4, v.size() - 5))) : space.symbol(rename(v)));
  m.mass_matrix = GiNaC::matrix(static_cast<unsigned>(k), static_cast<unsigned>(k));
  for (std::size_t i = 0; i < k; ++i) {
    m.forcing.push_back(side.entries.at(fmt::format("f[{}]", i)));
    for (std::size_t j = 0; j < k; ++j)
      m.mass_matrix(static_cast<unsigned>(i), static_cast<unsigned>(j)) = side.entries.at(fmt::format("M[{}][{}]", i, j));
  }
  if (!r.pseudo_velocities) return m;
  for (const std::string& q : r.coordinates) m.kinematics.push_back(side.entries.at("der(" + rename(q) + ")"));
  for (const std::string& v : r.velocities) m.definitions.push_back(side.entries.at("s[" + rename(v) + "]"));
  // the velocities of the state are symbols of their own, not q'
  for (std::size_t c = 0; c < k; ++c)
    if (r.velocities[c].rfind("der(", 0) == 0) {
      m.velocities[c] = space.symbol("s__" + rename(r.velocities[c].substr(4, r.velocities[c].size() - 5)));
      GiNaC::exmap to_state{{space.symbol("d__" + rename(r.velocities[c].substr(4, r.velocities[c].size() - 5))), m.velocities[c]}};
      for (ex& f : m.forcing) f = f.subs(to_state);
      m.mass_matrix = GiNaC::ex_to<GiNaC::matrix>(m.mass_matrix.subs(to_state));
      for (ex& x : m.kinematics) x = x.subs(to_state);
    }
  return m;
}

EquationDiff compare_derivations(const DerivationRecord& a, const DerivationRecord& b, const DiffOptions& o, Diagnostics& d) {
  EquationDiff out;
  out.old_path = a.path, out.new_path = b.path;
  Renaming rename(o.renames);
  SymbolSpace space;
  GiNaC::symtab old_table = space.table(a, rename), new_table = space.table(b, Renaming({}));
  ParsedSide old_side = parse_side(a, old_table, rename, d), new_side = parse_side(b, new_table, Renaming({}), d);
  if (!d.empty()) return out;
  if (!renames_name_old_symbols(a, o, d)) return out;
  compare_symbols(a, b, rename, o, out);
  std::map<std::string, double> defaults;
  for (const auto& p : a.parameters) defaults[rename(p.first)] = p.second;
  for (const auto& p : b.parameters) defaults[p.first] = p.second;
  int digits = GiNaC::Digits;
  GiNaC::Digits = 50;
  std::vector<GiNaC::exmap> points = sample_points(space, defaults, o);
  for (const std::string& name : new_side.order) {
    auto it = old_side.entries.find(name);
    if (it == old_side.entries.end()) {
      out.entries_only_new.push_back(name);
      continue;
    }
    EntryComparison c;
    c.entry = name;
    decide(c, it->second, new_side.entries.at(name), points, o.tolerance);
    out.entries.push_back(c);
  }
  for (const std::string& name : old_side.order)
    if (!new_side.entries.count(name)) out.entries_only_old.push_back(name);
  // verdict
  // the forms that depend on the choice of velocities and on the scaling of the equations (a Lagrangian
  // c·L gives c·T and c·V, and V + const the same motion)
  static const std::regex motion_entry(R"(^(M\[.*|f\[.*|S|T|V|R|s\[.*|der\(.*)$)");
  bool different = false, equivalent = false, only_motion_forms = true;
  for (const EntryComparison& c : out.entries) {
    different = different || c.status == "different";
    equivalent = equivalent || c.status == "equivalent";
    if (c.status == "different" && !std::regex_match(c.entry, motion_entry)) only_motion_forms = false;
  }
  for (const auto* only : {&out.entries_only_old, &out.entries_only_new})
    for (const std::string& name : *only) {
      different = true;
      if (!std::regex_match(name, motion_entry) || a.method == b.method) only_motion_forms = false;
    }
  bool symbols_differ = !out.added.empty() || !out.removed.empty() || !out.defaults_changed.empty();
  bool same = false;
  if (different && !symbols_differ && only_motion_forms && a.multipliers.empty() && b.multipliers.empty()) {
    MotionForm old_form = motion_form(a, old_side, space, rename), new_form = motion_form(b, new_side, space, Renaming({}));
    std::vector<GiNaC::exmap> states = sample_points(space, defaults, o);
    MotionComparison m = compare_accelerations(old_form, new_form, states, o.tolerance);
    same = m.same;
    out.motion = fmt::format("the accelerations q'' of both sides {} at {} random states (largest relative difference {:.3g})",
                             m.same ? "agree" : "differ", m.states, m.max_rel_difference);
  }
  GiNaC::Digits = digits;
  bool only_sampled = false;
  for (const EntryComparison& c : out.entries) only_sampled = only_sampled || c.decided_by == "numeric on the samples";
  out.verdict = symbols_differ || (different && !same) ? "different"
                : different                            ? "same_motion"
                : only_sampled                         ? "equal_on_samples"
                : equivalent                           ? "equivalent"
                                                       : "identical";
  return out;
}

}  // namespace eomgen
