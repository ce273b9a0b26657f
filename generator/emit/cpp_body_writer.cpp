#include "emit/cpp_body_writer.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "emit/cpp_expression.hpp"
#include "emit/statement_order.hpp"
#include "emit/zero_entries.hpp"
#include "model/symbols.hpp"
#include "symbolic/gradient.hpp"
#include "symbolic/trig_expansion.hpp"

namespace eomgen {

using GiNaC::ex;

std::string cpp_name(const std::string& name) { return is_cpp_identifier(name) ? name : name + "_"; }

std::string parameter_member_name(const std::string& name) {
  // the struct's own names: its template parameter, its member function and itself
  for (const char* taken : {"Scalar", "values", "Parameters"})
    if (name == taken) return name + "_";
  return cpp_name(name);
}

std::string quoted_list(const std::vector<std::string>& names, const std::string& prefix) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + ("\"" + prefix + n + "\"");
  return s;
}

namespace {

// der(q) → dq_q; a pseudo-velocity s → s_s
std::string velocity_name(const std::string& name) {
  if (name.rfind("der(", 0) == 0) return "dq_" + name.substr(4, name.size() - 5);
  return "s_" + name;
}

}  // namespace

BodyWriter::BodyWriter(const Equations& e)
    : equations_(e), graph_(intermediate_graph(e)), intermediates_(graph_->all), intermediate_index_(graph_->index),
      intermediate_uses_(graph_->uses) {
  const Symbols& s = e.symbols;
  std::size_t n = s.num_coordinates(), k = s.velocities.size();
  for (std::size_t i = 0; i < n; ++i) inputs_.push_back({s.coordinates[i], "q_" + s.coordinate_names[i], fmt::format("x[{}]", i)});
  for (std::size_t i = 0; i < k; ++i)
    inputs_.push_back({s.velocities[i], velocity_name(s.velocities[i].get_name()), fmt::format("x[{}]", n + i)});
  for (std::size_t i = 0; i < s.parameters.size(); ++i)
    inputs_.push_back({s.parameters[i], "p_" + s.parameter_names[i], fmt::format("p[{}]", i)});
  for (std::size_t i = 0; i < s.inputs.size(); ++i)
    inputs_.push_back({s.inputs[i], "u_" + s.input_names[i], fmt::format("u[{}]", i)});
  const std::vector<GiNaC::symbol>& ddq = e.acceleration_symbols();
  for (std::size_t i = 0; i < k; ++i) accelerations_.push_back(i < ddq.size() ? ddq[i] : GiNaC::symbol(fmt::format("ddq{}", i)));
  // every symbol's C++ name, looked up once per printed symbol
  names_[s.time] = "t";
  angle_inputs_.insert(s.time);
  for (const Input& in : inputs_) names_[in.symbol] = in.name, angle_inputs_.insert(in.symbol);
  for (std::size_t i = 0; i < k; ++i) names_[accelerations_[i]] = fmt::format("ddq[{}]", i);
  intermediate_written_.assign(intermediates_.size(), false);
}

// A header's dozen writers of the same equations would each find the same uses (a tenth of
// `eomgen generate` of the 12-link chain): the last graph is kept and taken again while the
// intermediates are the same symbols with the very same definitions (the same objects in memory;
// the graph holds them, so no other expression can take their place and pass for them).
std::shared_ptr<const BodyWriter::IntermediateGraph> BodyWriter::intermediate_graph(const Equations& e) {
  thread_local std::shared_ptr<const IntermediateGraph> last;
  static const std::vector<Intermediate> none;
  const NewtonEulerRecursion* recursion = e.newton_euler();
  const std::vector<Intermediate>* parts[] = {
      &e.intermediates, recursion ? &recursion->acceleration_intermediates : &none,
      e.articulated() ? &e.articulated()->intermediates : &none,
      recursion && recursion->joint_tree_accelerations ? &recursion->joint_tree_accelerations->intermediates : &none};
  auto unchanged = [&] {
    std::size_t at = 0;
    for (const std::vector<Intermediate>* part : parts)
      for (const Intermediate& i : *part) {
        if (at == last->all.size()) return false;
        const Intermediate& kept = last->all[at++];
        if (i.symbol.compare(kept.symbol) != 0 || !GiNaC::are_ex_trivially_equal(i.definition, kept.definition) ||
            i.cpp_name != kept.cpp_name)
          return false;
      }
    return at == last->all.size();
  };
  if (last && unchanged()) return last;
  std::vector<Intermediate> all;
  for (const std::vector<Intermediate>* part : parts) all.insert(all.end(), part->begin(), part->end());
  auto graph = std::make_shared<IntermediateGraph>();
  graph->all = std::move(all);
  // two quantities of one C++ name would be a header that does not compile: said here instead
  std::set<std::string> cpp_names;
  for (const Intermediate& i : graph->all)
    if (!cpp_names.insert(i.cpp_name).second)
      throw std::logic_error("two intermediate quantities are both named '" + i.cpp_name + "' in C++");
  for (std::size_t i = 0; i < graph->all.size(); ++i) graph->index[graph->all[i].symbol] = i;
  for (const Intermediate& i : graph->all) {
    GiNaC::exset used;
    collect_symbols(i.definition, used);
    graph->uses.emplace_back();
    for (const ex& u : used)
      if (auto found = graph->index.find(u); found != graph->index.end()) graph->uses.back().push_back(found->second);
  }
  last = graph;
  return graph;
}

// the intermediates that `expressions` need and that are not written yet, in dependency
// levels: each level's definitions use only model symbols and earlier levels, so that their
// common subexpressions (batched per level) come before every use
void BodyWriter::define_intermediates(const std::vector<ex>& expressions, CseBatch& written) {
  const std::vector<Intermediate>& all = intermediates_;
  if (all.empty()) return;
  std::vector<bool> needed(all.size(), false);
  for (const ex& x : expressions) {
    GiNaC::exset used;
    collect_symbols(x, used);
    for (const ex& u : used)
      if (auto found = intermediate_index_.find(u); found != intermediate_index_.end()) needed[found->second] = true;
  }
  std::vector<std::size_t> level(all.size(), 0);
  std::size_t deepest = 0;
  for (std::size_t i = all.size(); i-- > 0;)
    if (needed[i] && !intermediate_written_[i])
      for (std::size_t u : intermediate_uses_[i]) needed[u] = true;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (!needed[i] || intermediate_written_[i]) continue;
    for (std::size_t u : intermediate_uses_[i])
      if (!intermediate_written_[u]) level[i] = std::max(level[i], level[u] + 1);
    deepest = std::max(deepest, level[i]);
  }
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < all.size(); ++i)
    if (needed[i] && !intermediate_written_[i]) pending.push_back(i);
  for (std::size_t at = 0; at <= deepest && !pending.empty(); ++at) {
    std::vector<std::size_t> these;
    std::vector<ex> definitions;
    for (std::size_t i : pending)
      if (level[i] == at) these.push_back(i), definitions.push_back(expand_trig_of_sums(all[i].definition));
    CseBatch b = cse_.add(definitions);
    for (const Temporary& t : b.temporaries) {
      define_local(t.name, t.name.get_name(), t.definition);
      written.temporaries.push_back(t);
    }
    for (std::size_t k = 0; k < these.size(); ++k) {
      const Intermediate& i = all[these[k]];
      define_local(i.symbol, i.cpp_name, b.outputs[k]);
      intermediate_written_[these[k]] = true;
      written.temporaries.push_back({i.symbol, b.outputs[k]});
    }
  }
}

CseBatch BodyWriter::write_intermediates_of(const std::vector<ex>& expressions) {
  GiNaC::exset used;
  for (const ex& x : expressions) collect_symbols(x, used);
  if (const NewtonEulerRecursion* recursion = equations_.newton_euler())
    for (const Intermediate& i : recursion->acceleration_intermediates) collect_symbols(i.definition, used);
  std::vector<ex> regular;
  for (const Intermediate& i : equations_.intermediates)
    if (used.count(i.symbol)) regular.push_back(i.symbol);
  CseBatch written;
  define_intermediates(regular, written);
  return written;
}

std::string BodyWriter::batched_trig(const ex& call) {
  bool is_sin = GiNaC::is_the_function<GiNaC::sin_SERIAL>(call);
  if ((!is_sin && !GiNaC::is_the_function<GiNaC::cos_SERIAL>(call)) || !angle_inputs_.count(call.op(0))) return "";
  std::pair<bool, bool>& used = trig_used_[call.op(0)];
  (is_sin ? used.first : used.second) = true;
  return (is_sin ? "sin_" : "cos_") + names_.at(call.op(0));
}

// the angles in the order of the function's arguments (not of first use, which follows GiNaC's
// order of terms and so changes between processes)
std::string BodyWriter::batched_trig_statements() const {
  std::vector<std::pair<ex, std::pair<bool, bool>>> angles;
  auto add = [&](const ex& symbol) {
    if (auto found = trig_used_.find(symbol); found != trig_used_.end()) angles.push_back(*found);
  };
  add(equations_.symbols.time);
  for (const Input& in : inputs_) add(in.symbol);
  if (angles.empty()) return "";
  std::string list, values;
  for (std::size_t i = 0; i < angles.size(); ++i) {
    const std::string& name = names_.at(angles[i].first);
    list += (i ? ", " : "") + name;
    if (angles[i].second.first) values += fmt::format("  const T sin_{} = trig_sin[{}];\n", name, i);
    if (angles[i].second.second) values += fmt::format("  const T cos_{} = trig_cos[{}];\n", name, i);
  }
  return fmt::format("  const T trig_angle[{0}] = {{{1}}};\n  T trig_sin[{0}], trig_cos[{0}];\n"
                     "  detail::sin_cos(trig_angle, trig_sin, trig_cos);\n{2}",
                     angles.size(), list, values);
}

std::string BodyWriter::name_of(const GiNaC::symbol& symbol) const {
  auto found = names_.find(symbol);
  return found != names_.end() ? found->second : symbol.get_name();
}

std::string BodyWriter::own_name_of(const GiNaC::symbol& symbol) const {
  auto found = own_names_.find(symbol);
  return found != own_names_.end() ? found->second : name_of(symbol);
}

void BodyWriter::solve_velocities() {
  const Equations& e = equations_;
  if (velocities_solved_ || !e.solves_for_velocities()) return;
  velocities_solved_ = true;
  const MomentumSolve& momentum = *e.momentum();
  std::size_t n = momentum.bias.size();
  std::vector<ex> exprs = upper_triangle(momentum.mass_matrix, n);
  for (std::size_t i = 0; i < n; ++i) exprs.push_back(e.symbols.velocities[i] - momentum.bias[i]);
  auto code = batch(exprs);
  line(fmt::format("// der(q) from the momenta: M(q,t) der(q) = p - b(q,t)"));
  line(fmt::format("T Mv[{}];", n * n));
  write_symmetric(*this, std::vector<std::string>(code.begin(), code.begin() + n * (n + 1) / 2), n, "Mv");
  line(fmt::format("T qd[{}];", n));
  for (std::size_t i = 0; i < n; ++i) line(fmt::format("qd[{}] = {};", i, code[n * (n + 1) / 2 + i]));
  line(fmt::format("T Lv[{}];", n * n));
  line(fmt::format("T Dv[{}];", n));
  line("detail::ldlt_factor(Mv, Lv, Dv);");
  line("detail::ldlt_solve(Lv, Dv, qd);");
  for (std::size_t i = 0; i < n; ++i) names_[e.coordinate_velocities[i]] = fmt::format("qd[{}]", i);
}

CseBatch BodyWriter::unwritten_batch(const std::vector<ex>& expressions) {
  auto needs_velocities = [&] {
    for (const ex& x : expressions)
      for (const auto& v : equations_.coordinate_velocities)
        if (x.has(v)) return true;
    return false;
  };
  if (equations_.solves_for_velocities() && !velocities_solved_ && needs_velocities()) solve_velocities();
  std::vector<ex> for_code;
  for (const ex& e : expressions) for_code.push_back(expand_trig_of_sums(e));
  CseBatch written;
  define_intermediates(for_code, written);
  CseBatch b = cse_.add(for_code);
  written.temporaries.insert(written.temporaries.end(), b.temporaries.begin(), b.temporaries.end());
  written.outputs = b.outputs;
  return written;
}

void BodyWriter::write_temporary(const Temporary& t) { define_local(t.name, t.name.get_name(), t.definition); }

// a local whose value is another's name (a joint's cos q shared by two entries of its turn) is
// that name wherever it is used: the arm's header had 115 such lines
void BodyWriter::define_local(const ex& symbol, const std::string& cpp_name, const ex& definition) {
  note(definition);
  std::string value = code(definition);
  bool alias = is_identifier(value);
  names_[symbol] = alias ? value : cpp_name;
  own_names_[symbol] = cpp_name;
  if (!alias) statements_ += fmt::format("  const T {} = {};\n", cpp_name, value);
}

// (the intermediates among the temporaries are written already, as they were defined)
CseBatch BodyWriter::reduced_batch(const std::vector<ex>& expressions) {
  CseBatch b = unwritten_batch(expressions);
  for (const Temporary& t : b.temporaries)
    if (!names_.count(t.name)) write_temporary(t);
  return b;
}

// GCC's register allocation took 3.6 s of the 8.3 s that g++ -O2 spent on the 30-link chain's
// 1,800 entries of df/dx when every temporary came first and lived to the end of the function
void BodyWriter::assign(const std::vector<ex>& expressions, const std::vector<std::string>& targets) {
  assign(expressions, [&](std::size_t k, const std::string& code) { return targets[k] + " = " + code + ";"; });
}

void BodyWriter::assign(const std::vector<ex>& expressions,
                        const std::function<std::string(std::size_t, const std::string&)>& assignment) {
  CseBatch b = unwritten_batch(expressions);
  std::map<ex, std::size_t, GiNaC::ex_is_less> position;
  for (std::size_t i = 0; i < b.temporaries.size(); ++i) position[b.temporaries[i].name] = i + 1;
  std::vector<std::vector<std::size_t>> after(b.temporaries.size() + 1);
  for (std::size_t k = 0; k < b.outputs.size(); ++k) {
    GiNaC::exset used;
    collect_symbols(b.outputs[k], used);
    std::size_t last = 0;
    for (const ex& u : used)
      if (auto found = position.find(u); found != position.end()) last = std::max(last, found->second);
    after[last].push_back(k);
  }
  for (std::size_t i = 0; i <= b.temporaries.size(); ++i) {
    if (i > 0 && !names_.count(b.temporaries[i - 1].name)) write_temporary(b.temporaries[i - 1]);
    for (std::size_t k : after[i]) line(assignment(k, print(b.outputs[k])));
  }
}

std::string BodyWriter::print(const ex& reduced) {
  note(reduced);
  return code(reduced);
}

std::vector<std::string> BodyWriter::batch(const std::vector<ex>& expressions) {
  std::vector<std::string> out;
  for (const ex& o : reduced_batch(expressions).outputs) out.push_back(print(o));
  return out;
}

namespace {

// Each distinct detail::constant<T>(hi, mid, lo) of `statements` declared once as a local n0, n1, …
// in the order of first use, and the uses replaced by the names: a number of a joint frame's axes
// recurs in dozens of statements, and its 60 characters of text would be most of a header.
std::string with_named_constants(const std::string& statements) {
  static const std::string call = "detail::constant<T>(";
  std::map<std::string, std::string> names;
  std::string declarations, body;
  std::size_t at = 0;
  for (std::size_t found; (found = statements.find(call, at)) != std::string::npos;) {
    std::size_t end = statements.find(')', found) + 1;
    std::string text = statements.substr(found, end - found);
    auto [named, added] = names.emplace(text, fmt::format("n{}", names.size()));
    if (added) declarations += fmt::format("  const T {} = {};\n", named->second, text);
    body += statements.substr(at, found - at) + named->second;
    at = end;
  }
  return declarations + body + statements.substr(at);
}

}  // namespace

std::string BodyWriter::finish(const std::string& unused) {
  std::string ordered = order_every_run_ ? in_order_of_use(statements_, 0) : in_order_of_use(statements_);
  std::string body = with_named_constants(batched_trig_statements() + ordered);
  std::string head = "  " + unused + "\n";
  if (std::string usings = cpp_math_usings(body); !usings.empty()) head += "  " + usings + "\n";
  for (const auto& in : inputs_)
    if (used_.count(in.symbol)) head += fmt::format("  const T {} = {};\n", in.name, in.source);
  return head + body;
}

void BodyWriter::note(const ex& e) {
  collect_symbols(e, used_);
}

std::string BodyWriter::code(const ex& e) {
  return cpp_expression(
      e,
      [this](const GiNaC::symbol& s) -> std::string {
        auto found = names_.find(s);
        if (found != names_.end()) return found->second;
        throw std::runtime_error("no C++ name for symbol " + s.get_name());
      },
      [this](const ex& call) { return batched_trig(call); });
}

std::vector<ex> upper_triangle(const GiNaC::matrix& M, std::size_t n) {
  std::vector<ex> entries;
  for (unsigned j = 0; j < n; ++j)
    for (unsigned k = j; k < n; ++k) entries.push_back(M(j, k));
  return entries;
}

// writes M (n×n, row-major) from its upper triangle into `target`
// Each entry below the diagonal takes its value as the one above does, never by a load from the
// entry just stored: in one long block of straight-line code, g++ 12's SLP vectorizer (-O2, -O3)
// read some copies M[961] = M[741] before the store to M[741], as the zero that filled M, and a
// floating humanoid's accelerations were 50 % off (alex_psyonic_hands with --free-base; -O1,
// -fno-tree-slp-vectorize and clang++ gave them right). A copy in a loop after the stores made
// the 7-joint arm's rhs 10-30 % slower: M then went through memory into the factorization.
void write_symmetric(BodyWriter& w, const std::vector<std::string>& upper, std::size_t n, const std::string& target) {
  auto simple = [](const std::string& code) {
    return code.find_first_of(" +-*/(") == std::string::npos || (code.rfind("T(", 0) == 0 && code.find(')') + 1 == code.size());
  };
  std::size_t at = 0;
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t k = j; k < n; ++k, ++at) {
      std::string value = upper[at];
      if (k != j && !simple(value)) {
        w.line(fmt::format("const T sym_{}{} = {};", target, j * n + k, value));
        value = fmt::format("sym_{}{}", target, j * n + k);
      }
      w.line(fmt::format("{}[{}] = {};", target, j * n + k, value));
      if (k != j) w.line(fmt::format("{}[{}] = {};", target, k * n + j, value));
    }
}

void write_lower_triangle(BodyWriter& w, const std::vector<std::string>& upper, std::size_t n, const std::string& target) {
  std::size_t at = 0;
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t k = j; k < n; ++k, ++at) w.line(fmt::format("{}[{}] = {};", target, k * n + j, upper[at]));
}

std::string function(const std::string& doc, const std::string& signature, const std::string& body) {
  return doc + "template <class T>\n" + signature + " {\n" + with_zero_fills(signature, body) + "}\n\n";
}

std::string without_unused_locals(const std::string& body) {
  struct Line {
    std::size_t begin, end;
    std::string local;  // the name a `const T name = …;` line defines, else empty
  };
  std::vector<Line> lines;
  static const std::string head = "  const T ";
  for (std::size_t at = 0; at < body.size();) {
    std::size_t end = body.find('\n', at);
    end = end == std::string::npos ? body.size() : end + 1;
    Line l{at, end, {}};
    if (body.compare(at, head.size(), head) == 0) {
      std::size_t name_end = body.find(' ', at + head.size());
      std::string name = name_end < end ? body.substr(at + head.size(), name_end - at - head.size()) : "";
      bool plain = !name.empty() && std::all_of(name.begin(), name.end(), is_identifier_char);
      if (plain && body.compare(name_end, 3, " = ") == 0) l.local = name;
    }
    lines.push_back(l);
    at = end;
  }
  std::map<std::string, long, std::less<>> reads;
  for (const Line& l : lines)
    for_each_identifier(body, l.begin + (l.local.empty() ? 0 : head.size() + l.local.size()), l.end,
                        [&](std::string_view id) { ++reads[std::string(id)]; });
  std::vector<bool> dropped(lines.size(), false);
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t k = lines.size(); k-- > 0;) {
      const Line& l = lines[k];
      if (dropped[k] || l.local.empty() || reads[l.local] > 0) continue;
      dropped[k] = changed = true;
      for_each_identifier(body, l.begin + head.size() + l.local.size(), l.end,
                          [&](std::string_view id) { --reads.find(id)->second; });
    }
  }
  std::string out;
  for (std::size_t k = 0; k < lines.size(); ++k)
    if (!dropped[k]) out.append(body, lines[k].begin, lines[k].end - lines[k].begin);
  return out;
}

CseBatch accelerations(BodyWriter& w, const Equations& e, bool into_arguments) {
  std::size_t n = e.forcing.size();
  std::vector<ex> exprs = upper_triangle(e.mass_matrix, n);
  exprs.insert(exprs.end(), e.forcing.begin(), e.forcing.end());
  CseBatch batch = w.reduced_batch(exprs);
  std::vector<std::string> code;
  for (const ex& r : batch.outputs) code.push_back(w.print(r));
  w.line(fmt::format("T M[{}];", n * n));
  write_symmetric(w, std::vector<std::string>(code.begin(), code.begin() + n * (n + 1) / 2), n, "M");
  if (!into_arguments) w.line(fmt::format("T ddq[{}];", n));
  for (std::size_t i = 0; i < n; ++i) w.line(fmt::format("ddq[{}] = {};", i, code[n * (n + 1) / 2 + i]));
  if (!into_arguments) {
    w.line(fmt::format("T L[{}];", n * n));
    w.line(fmt::format("T D[{}];", n));
  }
  w.line("detail::ldlt_factor(M, L, D);");
  w.line("detail::ldlt_solve(L, D, ddq);");
  return batch;
}

}  // namespace eomgen
