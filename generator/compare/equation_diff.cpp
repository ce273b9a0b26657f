#include "compare/equation_diff.hpp"

#include <algorithm>
#include <array>
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
  std::vector<std::pair<ex, ex>> intermediates;  // symbol i__k and its definition, in order
  std::vector<std::string> intermediate_names;   // as the side names them (link2.R_xx)
};

// a tree's intermediate names (link2.R_xx) as identifiers GiNaC's parser reads: i__0, i__1, …
std::string with_intermediate_placeholders(const std::string& text, const std::map<std::string, std::size_t>& index) {
  if (index.empty()) return text;
  static const std::regex name(R"([A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z_][A-Za-z0-9_]*)*)");
  std::string out;
  std::size_t last = 0;
  for (std::sregex_iterator i(text.begin(), text.end(), name), end; i != end; ++i) {
    auto it = index.find(i->str());
    if (it == index.end()) continue;
    out += text.substr(last, static_cast<std::size_t>(i->position()) - last) + fmt::format("i__{}", it->second);
    last = static_cast<std::size_t>(i->position() + i->length());
  }
  return out + text.substr(last);
}

ParsedSide parse_side(const DerivationRecord& r, GiNaC::symtab table, const Renaming& rename, Diagnostics& d) {
  ParsedSide side;
  std::map<std::string, std::size_t> index;
  for (std::size_t k = 0; k < r.intermediates.size(); ++k) {
    index[r.intermediates[k].name] = k;
    std::string placeholder = fmt::format("i__{}", k);
    table[placeholder] = GiNaC::realsymbol(placeholder);
    side.intermediate_names.push_back(r.intermediates[k].name);
  }
  GiNaC::parser reader(table, true);
  auto read = [&](const std::string& text, const std::string& key) -> std::optional<ex> {
    try {
      return reader(decimals_as_fractions(with_placeholders(with_intermediate_placeholders(text, index))));
    } catch (const std::exception& why) {
      d.error({r.path, 0, 0}, key, fmt::format("the expression '{}' does not read back: {}", text, why.what()),
              "derived-equations files are written by `eomgen derive --format json`; do not edit them by hand");
      return std::nullopt;
    }
  };
  for (std::size_t k = 0; k < r.intermediates.size(); ++k)
    if (auto definition = read(r.intermediates[k].text, r.intermediates[k].name))
      side.intermediates.emplace_back(table.at(fmt::format("i__{}", k)), *definition);
  for (const DerivedEntry& e : r.entries) {
    std::string name = rename.entry(e.name);
    if (auto value = read(e.text, e.name)) side.entries[name] = *value, side.order.push_back(name);
  }
  return side;
}

// Exact rationals of many digits, and floats of 50, as decimals of 17 significant digits, which is
// what they were: a robot's numbers, stated to 16 digits and turned by quaternions, read
// 9950041652780258727157920798041011/10000000000000001068611566764672789 exactly
struct LongNumbersAsDecimals : GiNaC::map_function {
  ex operator()(const ex& e) override {
    if (!GiNaC::is_a<GiNaC::numeric>(e)) return e.map(*this);
    const GiNaC::numeric& x = GiNaC::ex_to<GiNaC::numeric>(e);
    static const GiNaC::numeric long_digits("1000000000000");
    if (!x.is_real() || (x.is_rational() && abs(x.numer()) < long_digits && x.denom() < long_digits)) return e;
    return GiNaC::numeric(x.to_double());
  }
};

// an expression for the report: exact, but for long numbers
std::string shown_text(const ex& e) {
  LongNumbersAsDecimals decimals;
  return canonical_text(decimals(e));
}

// the placeholders back to der(q) and to the intermediates' names for the report
std::string readable(const std::string& text, const std::vector<std::string>& intermediate_names) {
  static const std::regex second(R"(\bdd__([A-Za-z_][A-Za-z0-9_]*))"), first(R"(\bd__([A-Za-z_][A-Za-z0-9_]*))"),
      intermediate(R"(\bi__([0-9]+)\b)");
  std::string out = std::regex_replace(std::regex_replace(text, second, "der(der($1))"), first, "der($1)");
  if (intermediate_names.empty()) return out;
  std::string named;
  std::size_t last = 0;
  for (std::sregex_iterator i(out.begin(), out.end(), intermediate), end; i != end; ++i) {
    std::size_t k = std::stoul((*i)[1].str());
    named += out.substr(last, static_cast<std::size_t>(i->position()) - last);
    named += k < intermediate_names.size() ? intermediate_names[k] : i->str();
    last = static_cast<std::size_t>(i->position() + i->length());
  }
  return named + out.substr(last);
}

// Where both sides compute the same intermediates (the same definitions, in order), the new side
// takes the old side's symbols for them, so that an entry's text and its exact simplification decide
// as they do without intermediates; true then, or when neither side has any.
bool share_intermediates(const ParsedSide& old_side, ParsedSide& new_side) {
  if (old_side.intermediates.size() != new_side.intermediates.size()) return false;
  GiNaC::exmap to_old;
  for (std::size_t k = 0; k < old_side.intermediates.size(); ++k) {
    const auto& [old_symbol, old_definition] = old_side.intermediates[k];
    const auto& [new_symbol, new_definition] = new_side.intermediates[k];
    if (canonical_text(old_definition) != canonical_text(new_definition)) return false;
    to_old[new_symbol] = old_symbol;
  }
  if (to_old.empty()) return true;
  for (auto& [symbol, definition] : new_side.intermediates) {
    symbol = substituted(symbol, to_old);
    definition = substituted(definition, to_old);
  }
  for (auto& [name, value] : new_side.entries) value = substituted(value, to_old);
  return true;
}

// the intermediates whose definitions differ by name, as the report shows them
std::vector<IntermediateChange> changed_intermediates(const ParsedSide& old_side, const ParsedSide& new_side) {
  // by name: the exact text (which decides) and the shown one
  auto definitions = [](const ParsedSide& side) {
    std::map<std::string, std::array<std::string, 2>> out;
    for (std::size_t k = 0; k < side.intermediates.size(); ++k) {
      const ex& definition = side.intermediates[k].second;
      out[side.intermediate_names[k]] = {readable(canonical_text(definition), side.intermediate_names),
                                         readable(shown_text(definition), side.intermediate_names)};
    }
    return out;
  };
  auto old_text = definitions(old_side), new_text = definitions(new_side);
  std::vector<IntermediateChange> out;
  for (const std::string& name : new_side.intermediate_names) {
    auto it = old_text.find(name);
    if (it == old_text.end()) {
      out.push_back({name, "", new_text[name][1]});
    } else if (it->second[0] != new_text[name][0]) {
      out.push_back({name, it->second[1], new_text[name][1], it->second[1] == new_text[name][1]});
    }
  }
  for (const std::string& name : old_side.intermediate_names)
    if (!new_text.count(name)) out.push_back({name, old_text[name][1], ""});
  return out;
}

// a side's values at a random point: the point's, and its intermediates' evaluated in order (one
// with a pole there is left a symbol, and the entries that use it are not evaluated at that point)
std::vector<GiNaC::exmap> with_intermediates(std::vector<GiNaC::exmap> points, const ParsedSide& side) {
  for (GiNaC::exmap& p : points)
    for (const auto& [symbol, definition] : side.intermediates) {
      try {
        p[symbol] = substituted(definition, p).evalf();
      } catch (const std::exception&) {
        continue;
      }
    }
  return points;
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

// the value at a point in 50-digit arithmetic, or none: a pole there, or not real
std::optional<GiNaC::numeric> value_at(const ex& e, const GiNaC::exmap& point) {
  try {
    ex v = substituted(e, point).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return std::nullopt;
    return GiNaC::ex_to<GiNaC::numeric>(v);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// The size of e's terms at a point: sums and products of the absolute values of what they combine
// (powers to whole exponents likewise), anything else its absolute value. Two forms of one
// expression differ at 50 digits by rounding of that size, where the value itself may be far smaller
// (a sum that cancels); none where a part does not evaluate.
std::optional<double> term_size(const ex& e, const GiNaC::exmap& point) {
  bool sum = GiNaC::is_a<GiNaC::add>(e), product = GiNaC::is_a<GiNaC::mul>(e);
  if (sum || product) {
    double size = sum ? 0 : 1;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      std::optional<double> part = term_size(e.op(i), point);
      if (!part) return std::nullopt;
      size = sum ? size + *part : size * *part;
    }
    return size;
  }
  if (GiNaC::is_a<GiNaC::power>(e) && e.op(1).info(GiNaC::info_flags::posint)) {
    std::optional<double> base = term_size(e.op(0), point);
    if (!base) return std::nullopt;
    return std::pow(*base, GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_double());
  }
  std::optional<GiNaC::numeric> value = value_at(e, point);
  if (!value) return std::nullopt;
  return std::abs(value->to_double());
}

// One entry in levels: text, then exact simplification, then 50-digit evaluation, each side at its
// own `points` (with its intermediates' values). Where the sides' intermediates differ, equal text
// says nothing, and only the numeric level decides.
// a side's points, its intermediates evaluated at the first need (two identical robots need none)
class SidePoints {
 public:
  SidePoints(const std::vector<GiNaC::exmap>& points, const ParsedSide& side) : points_(points), side_(side) {}
  const std::vector<GiNaC::exmap>& values() {
    if (!values_) values_ = with_intermediates(points_, side_);
    return *values_;
  }

 private:
  const std::vector<GiNaC::exmap>& points_;
  const ParsedSide& side_;
  std::optional<std::vector<GiNaC::exmap>> values_;
};

struct EntrySides {
  const ParsedSide &old_side, &new_side;
  SidePoints &old_points, &new_points;
  bool text_decides;
};

void decide(EntryComparison& c, const ex& old_e, const ex& new_e, const EntrySides& s, double tolerance) {
  std::string old_exact = canonical_text(old_e), new_exact = canonical_text(new_e);
  if (s.text_decides && old_exact == new_exact) {
    c.old_text = c.new_text = readable(shown_text(old_e), s.old_side.intermediate_names);
    c.status = "identical", c.decided_by = "text";
    return;
  }
  // shown with decimals
  c.old_text = readable(shown_text(old_e), s.old_side.intermediate_names);
  c.new_text = readable(shown_text(new_e), s.new_side.intermediate_names);
  c.beyond_the_decimals = c.old_text == c.new_text && old_exact != new_exact;
  if (s.text_decides) {
    ex difference = (old_e - new_e).expand();
    bool zero = difference.is_zero();
    if (!zero && c.old_text.size() + c.new_text.size() < 4000) zero = difference.normal().is_zero();
    if (zero) {
      c.status = "equivalent", c.decided_by = "symbolic";
      return;
    }
  }
  c.decided_by = "numeric";
  int evaluated = 0;
  bool equal = true;
  const std::vector<GiNaC::exmap>&old_points = s.old_points.values(), &new_points = s.new_points.values();
  for (std::size_t k = 0; k < old_points.size(); ++k) {
    auto a = value_at(old_e, old_points[k]), b = value_at(new_e, new_points[k]);
    if (!a || !b) continue;
    ++evaluated;
    // against the values, and where they differ by more, against their terms' size (no floor of one
    // unit: entries of 1e-36, a 1e-12 kg mass on 1e-12 m, had passed for equal at twice the mass)
    double size = std::max(std::abs(a->to_double()), std::abs(b->to_double()));
    double abs = std::abs((*a - *b).to_double());
    if (abs > tolerance * size) {
      std::optional<double> old_terms = term_size(old_e, old_points[k]), new_terms = term_size(new_e, new_points[k]);
      size = std::max({size, old_terms.value_or(0.0), new_terms.value_or(0.0)});
    }
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
      for (ex& f : m.forcing) f = substituted(f, to_state);
      m.mass_matrix = GiNaC::ex_to<GiNaC::matrix>(substituted(m.mass_matrix, to_state));
      for (ex& x : m.kinematics) x = substituted(x, to_state);
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
  bool text_decides = share_intermediates(old_side, new_side);
  if (!text_decides) out.intermediates_changed = changed_intermediates(old_side, new_side);
  SidePoints old_points(points, old_side), new_points(points, new_side);
  EntrySides sides{old_side, new_side, old_points, new_points, text_decides};
  for (const std::string& name : new_side.order) {
    auto it = old_side.entries.find(name);
    if (it == old_side.entries.end()) {
      out.entries_only_new.push_back(name);
      continue;
    }
    EntryComparison c;
    c.entry = name;
    decide(c, it->second, new_side.entries.at(name), sides, o.tolerance);
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
  // (a side's intermediates are evaluated at the sampled q', not at q' = r(q, s): none with pseudo-velocities)
  bool intermediates_at_the_states = (a.intermediates.empty() || !a.pseudo_velocities) && (b.intermediates.empty() || !b.pseudo_velocities);
  if (different && !symbols_differ && only_motion_forms && a.multipliers.empty() && b.multipliers.empty() &&
      intermediates_at_the_states) {
    MotionForm old_form = motion_form(a, old_side, space, rename), new_form = motion_form(b, new_side, space, Renaming({}));
    MotionComparison m = compare_accelerations(old_form, new_form, old_points.values(), new_points.values(), o.tolerance);
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
