/// @file Common-subexpression elimination on the expression DAG. Expressions
/// that are small as graphs can be huge as trees; every subexpression used
/// more than once becomes a temporary, computed once.
///
/// The result is data: temporaries (name = definition in earlier temporaries)
/// and the reduced outputs. Temporaries are numbered in a post-order traversal
/// that visits operands in an order fixed by a structural hash of names and
/// values, not by GiNaC's address-dependent order, so the numbering is the same
/// in every process.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace eomgen {

struct Temporary {
  GiNaC::symbol name;
  GiNaC::ex definition;  // in terms of model symbols and earlier temporaries
};

struct CseBatch {
  std::vector<Temporary> temporaries;  // new in this batch, in evaluation order
  std::vector<GiNaC::ex> outputs;      // the batch's expressions, reduced
};

/// Eliminates common subexpressions batch by batch: a later batch reuses the
/// temporaries of earlier ones (for code that computes in stages, such as
/// forming M and f, solving, then forming Jacobian terms that use the solution).
class CommonSubexpressions {
 public:
  explicit CommonSubexpressions(std::string prefix = "c") : prefix_(std::move(prefix)) {}

  CseBatch add(const std::vector<GiNaC::ex>& expressions);

 private:
  std::uint64_t structural_hash(const GiNaC::ex& e);
  std::vector<GiNaC::ex> ordered_operands(const GiNaC::ex& e);
  bool leads_negative(const GiNaC::ex& e);
  bool flips(const GiNaC::ex& factor);
  GiNaC::numeric normalized_coefficient(const GiNaC::ex& term);
  std::uint64_t shape_hash(const GiNaC::ex& term);
  std::uint64_t orientation_free_hash(const GiNaC::ex& e);
  void count(const GiNaC::ex& e, std::map<GiNaC::ex, int, GiNaC::ex_is_less>& uses);
  GiNaC::ex reduce(const GiNaC::ex& e, const std::map<GiNaC::ex, int, GiNaC::ex_is_less>& uses, CseBatch& batch);
  void nest_shared_sums(const std::map<GiNaC::ex, int, GiNaC::ex_is_less>& uses, CseBatch& batch);

  std::string prefix_;
  std::size_t next_ = 0;
  // depend only on an expression's structure and names, so they are shared by every
  // instance in the thread (the functions of a header share most subexpressions)
  static thread_local std::map<GiNaC::ex, std::uint64_t, GiNaC::ex_is_less> hashes_;
  static thread_local std::map<GiNaC::ex, bool, GiNaC::ex_is_less> orientation_;
  std::map<GiNaC::ex, GiNaC::ex, GiNaC::ex_is_less> known_;  // subexpression → its temporary
  struct NestedSum {
    GiNaC::exset terms;
    GiNaC::ex temporary;
  };
  std::vector<NestedSum> sums_;  // shared sums of atoms, for nesting larger sums around them
};

/// True for expressions that are never worth a temporary: symbols and numbers.
bool is_atom(const GiNaC::ex& e);

}  // namespace eomgen
