/// @file Writing the body of one generated C++ function: the model's symbols read
/// from the plain arrays x, p and u, common subexpressions as local constants.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "derive/equations.hpp"
#include "symbolic/cse.hpp"

namespace eomgen {

/// C++ name of a model name that may be a C++ keyword.
std::string cpp_name(const std::string& name);
/// A parameter's member name in the header's Parameters struct: cpp_name, and a trailing _
/// for the names the struct uses itself (Scalar, values, Parameters).
std::string parameter_member_name(const std::string& name);

/// "a", "b", … as the initializer of a std::array of const char*, each name with `prefix`.
std::string quoted_list(const std::vector<std::string>& names, const std::string& prefix = "");

class BodyWriter {
 public:
  explicit BodyWriter(const Equations& e);

  /// Symbols q'' (one per velocity), printed as ddq[i].
  const std::vector<GiNaC::symbol>& accelerations() const { return accelerations_; }
  /// Prints `symbol` as `text` (a local array entry, a function argument).
  void name(const GiNaC::symbol& symbol, const std::string& text) { names_[symbol] = text; }

  /// The statements computing a batch's temporaries; the outputs are returned as C++ text.
  /// For Hamilton's equations in mass-matrix form, the first batch that needs der(q) is
  /// preceded by the solution of M der(q) = p − b into the local array qd.
  std::vector<std::string> batch(const std::vector<GiNaC::ex>& expressions);
  /// As batch, but writes the statement `assignment(k, code)` of each output k itself, right after
  /// the last temporary it uses, so that a temporary lives only until its last use.
  void assign(const std::vector<GiNaC::ex>& expressions,
              const std::function<std::string(std::size_t, const std::string&)>& assignment);
  /// As assign, each output k written as `targets[k] = code;` (an entry of M, of a table).
  void assign(const std::vector<GiNaC::ex>& expressions, const std::vector<std::string>& targets);
  /// As batch, but the outputs are returned reduced (in model symbols and temporaries), with
  /// the batch's temporaries, for code that goes on from them (a tangent sweep); `print` writes one.
  CseBatch reduced_batch(const std::vector<GiNaC::ex>& expressions);
  std::string print(const GiNaC::ex& reduced);
  /// Later batches share no temporaries with earlier ones (named `prefix`0, …): for code whose
  /// tangent sweep must not run through the earlier batches' temporaries.
  void fresh_subexpressions(const std::string& prefix) { cse_ = CommonSubexpressions(prefix); }
  /// The intermediates of recursive kinematics (not those in q'') that `expressions` use,
  /// written now with what they need, as a batch for a tangent sweep to follow.
  CseBatch write_intermediates_of(const std::vector<GiNaC::ex>& expressions);
  /// The C++ name a symbol is printed as.
  std::string name_of(const GiNaC::symbol& symbol) const;
  /// The name of the local a temporary or intermediate would have been: the one it is printed as,
  /// or its own when its value was another's name and is printed so (names derived from it, a
  /// tangent's, stay as unique as the temporaries).
  std::string own_name_of(const GiNaC::symbol& symbol) const;
  /// For sin or cos of one of the function's inputs (a coordinate, parameter, input or t): the
  /// name of its value, sin_q_phi say, which detail::sin_cos computes at the start of the
  /// function, all angles at once (two at a time for double). "" for any other call.
  std::string batched_trig(const GiNaC::ex& call);
  /// Solves M der(q) = p − b now (once); the factors are then in Lv and Dv.
  void solve_velocities();
  void line(const std::string& text) { statements_ += "  " + text + "\n"; }
  /// Declarations of the model symbols used, then the statements.
  std::string finish(const std::string& unused);
  /// finish() puts every run of statements in order of use, however short (statement_order.hpp)
  void order_every_run() { order_every_run_ = true; }

 private:
  struct Input {
    GiNaC::ex symbol;
    std::string name, source;
  };
  void note(const GiNaC::ex& e);
  std::string code(const GiNaC::ex& e);
  void define_intermediates(const std::vector<GiNaC::ex>& expressions, CseBatch& written);
  // the temporaries of a batch and the reduced expressions, before any is written
  CseBatch unwritten_batch(const std::vector<GiNaC::ex>& expressions);
  void write_temporary(const Temporary& t);
  void define_local(const GiNaC::ex& symbol, const std::string& cpp_name, const GiNaC::ex& definition);

  const Equations& equations_;
  bool velocities_solved_ = false;
  std::vector<Input> inputs_;
  GiNaC::exset angle_inputs_;  // the symbols whose sin and cos may be batched
  // those batched, and whether their sin and their cos are used
  std::map<GiNaC::ex, std::pair<bool, bool>, GiNaC::ex_is_less> trig_used_;
  std::string batched_trig_statements() const;
  std::vector<GiNaC::symbol> accelerations_;
  std::map<GiNaC::ex, std::string, GiNaC::ex_is_less> names_, own_names_;
  bool order_every_run_ = false;
  GiNaC::exset used_;
  CommonSubexpressions cse_;
  std::string statements_;
  // recursive kinematics: the intermediates (the equations', those in q'', the recursion's), each
  // one's index and the intermediates its definition uses, shared by the writers of one header; and
  // whether each has been written in this function
  struct IntermediateGraph {
    std::vector<Intermediate> all;
    std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> index;
    std::vector<std::vector<std::size_t>> uses;
  };
  static std::shared_ptr<const IntermediateGraph> intermediate_graph(const Equations& e);
  std::shared_ptr<const IntermediateGraph> graph_;
  const std::vector<Intermediate>& intermediates_;
  const std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less>& intermediate_index_;
  const std::vector<std::vector<std::size_t>>& intermediate_uses_;
  std::vector<bool> intermediate_written_;
};

/// The entries M(j,k), k >= j, row by row.
std::vector<GiNaC::ex> upper_triangle(const GiNaC::matrix& M, std::size_t n);
/// Writes M (n×n, row-major) from its upper triangle into the array `target`.
void write_symmetric(BodyWriter& w, const std::vector<std::string>& upper, std::size_t n, const std::string& target);
/// Writes only the diagonal and the lower triangle of M (n×n, row-major) from its upper triangle:
/// what ldlt_factor reads, for an M that nothing else reads.
void write_lower_triangle(BodyWriter& w, const std::vector<std::string>& upper, std::size_t n, const std::string& target);
/// A documented function template with the given signature and body.
std::string function(const std::string& doc, const std::string& signature, const std::string& body);

/// `body` without the lines `const T name = …;` whose name nothing reads (and, in turn, those
/// only they read): a sweep that differentiates τ needs τ's own temporaries only where a
/// tangent does, and an unused local is an error under -Werror.
std::string without_unused_locals(const std::string& body);
/// M and f into local arrays, M = L D L^T, then the accelerations M^-1 f into `ddq`. Returns the
/// batch, whose outputs are the upper triangle of M, row by row, then f. With `into_arguments`,
/// ddq, L and D are the function's arguments rather than locals.
CseBatch accelerations(BodyWriter& w, const Equations& e, bool into_arguments = false);

inline const char* all_unused = "(void)t; (void)x; (void)u; (void)p;";

}  // namespace eomgen
