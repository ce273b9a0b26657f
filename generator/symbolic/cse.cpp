#include "symbolic/cse.hpp"

#include <algorithm>
#include <sstream>

namespace eomgen {

using GiNaC::ex;

thread_local std::map<ex, std::uint64_t, GiNaC::ex_is_less> CommonSubexpressions::hashes_;
thread_local std::map<ex, bool, GiNaC::ex_is_less> CommonSubexpressions::orientation_;

bool is_atom(const ex& e) {
  return GiNaC::is_a<GiNaC::symbol>(e) || GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::constant>(e);
}

namespace {

std::uint64_t fnv(const std::string& s, std::uint64_t h = 1469598103934665603ull) {
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::uint64_t mix(std::uint64_t h, std::uint64_t x) {
  h ^= x + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
  return h;
}

std::string printed(const ex& e) {
  std::ostringstream s;
  s << e;
  return s.str();
}

// a power with a small integer exponent is cheap: x^2 → x*x
bool is_cheap_power(const ex& e) {
  return GiNaC::is_a<GiNaC::power>(e) && is_atom(e.op(0)) && e.op(1).info(GiNaC::info_flags::integer) &&
         GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(e.op(1))) <= 3;
}

// a small power of a sum is not kept as a temporary of its own (its base is): GiNaC holds
// (a − b)^3 or −(b − a)^3 by an order that changes between processes, and the temporary's
// sign would change with it
bool is_small_power_of_sum(const ex& e) {
  return GiNaC::is_a<GiNaC::power>(e) && GiNaC::is_a<GiNaC::add>(e.op(0)) && e.op(1).info(GiNaC::info_flags::integer) &&
         GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(e.op(1))) <= 3;
}

// a power that the printer writes as its base repeated, f*f (emit/cpp_expression.cpp), of a
// function: a call, which the compiler does not merge (std math functions may set errno), so the
// call is a temporary even where the power is its only use (a ball spring's ½ k θ² called
// atan_ratio twice)
bool repeats_a_call(const ex& e) {
  if (!GiNaC::is_a<GiNaC::power>(e) || !GiNaC::is_a<GiNaC::function>(e.op(0)) || !e.op(1).info(GiNaC::info_flags::integer)) return false;
  GiNaC::numeric k = GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(e.op(1)));
  return k >= 2 && k <= 4;
}

}  // namespace

// The sign conventions below exist because GiNaC may hold c·(a − b) as
// (−c)·(b − a), by an order that changes between processes: hashes and
// orientations are defined on a normalized view in which every sum that is a
// factor of a product is taken with its first term positive.

bool CommonSubexpressions::flips(const ex& factor) {
  if (GiNaC::is_a<GiNaC::add>(factor)) return leads_negative(factor);
  return GiNaC::is_a<GiNaC::power>(factor) && GiNaC::is_a<GiNaC::add>(factor.op(0)) &&
         factor.op(1).info(GiNaC::info_flags::odd) && leads_negative(factor.op(0));
}

GiNaC::numeric CommonSubexpressions::normalized_coefficient(const ex& term) {
  if (GiNaC::is_a<GiNaC::numeric>(term)) return GiNaC::ex_to<GiNaC::numeric>(term);
  if (!GiNaC::is_a<GiNaC::mul>(term)) return flips(term) ? -1 : 1;
  GiNaC::numeric c = 1;
  for (std::size_t i = 0; i < term.nops(); ++i) {
    const ex f = term.op(i);
    if (GiNaC::is_a<GiNaC::numeric>(f)) c *= GiNaC::ex_to<GiNaC::numeric>(f);
    else if (flips(f)) c = -c;
  }
  return c;
}

// the hash of a term without its numeric coefficient and sign
std::uint64_t CommonSubexpressions::shape_hash(const ex& term) {
  if (GiNaC::is_a<GiNaC::numeric>(term)) return fnv("#");
  // a lone factor x has the shape of the product 1·x, so that x and −x compare alike
  std::vector<std::uint64_t> factors;
  if (!GiNaC::is_a<GiNaC::mul>(term)) factors.push_back(orientation_free_hash(term));
  else
    for (std::size_t i = 0; i < term.nops(); ++i)
      if (!GiNaC::is_a<GiNaC::numeric>(term.op(i))) factors.push_back(orientation_free_hash(term.op(i)));
  std::sort(factors.begin(), factors.end());
  std::uint64_t h = fnv("*");
  for (std::uint64_t f : factors) h = mix(h, f);
  return h;
}

bool CommonSubexpressions::leads_negative(const ex& e) {
  if (!GiNaC::is_a<GiNaC::add>(e)) return false;
  auto found = orientation_.find(e);
  if (found != orientation_.end()) return found->second;
  std::uint64_t first = UINT64_MAX;
  bool negative = false;
  for (std::size_t i = 0; i < e.nops(); ++i) {
    std::uint64_t h = shape_hash(e.op(i));
    if (h < first) {
      first = h;
      negative = normalized_coefficient(e.op(i)).is_negative();
    }
  }
  orientation_.emplace(e, negative);
  return negative;
}

std::uint64_t CommonSubexpressions::orientation_free_hash(const ex& e) {
  return leads_negative(e) ? structural_hash(-e) : structural_hash(e);
}

std::uint64_t CommonSubexpressions::structural_hash(const ex& e) {
  auto found = hashes_.find(e);
  if (found != hashes_.end()) return found->second;
  std::uint64_t h;
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    h = fnv("s:" + GiNaC::ex_to<GiNaC::symbol>(e).get_name());
  } else if (is_atom(e)) {
    h = fnv("n:" + printed(e));
  } else if (GiNaC::is_a<GiNaC::mul>(e)) {
    h = mix(shape_hash(e), fnv(printed(normalized_coefficient(e))));
  } else if (GiNaC::is_a<GiNaC::add>(e)) {
    std::vector<std::uint64_t> terms;
    for (std::size_t i = 0; i < e.nops(); ++i) terms.push_back(structural_hash(e.op(i)));
    std::sort(terms.begin(), terms.end());
    h = fnv("+");
    for (std::uint64_t t : terms) h = mix(h, t);
  } else if (GiNaC::is_a<GiNaC::power>(e)) {
    h = mix(mix(fnv("^"), orientation_free_hash(e.op(0))), structural_hash(e.op(1)));
  } else {
    h = fnv(GiNaC::is_a<GiNaC::function>(e) ? GiNaC::ex_to<GiNaC::function>(e).get_name() : printed(e));
    for (std::size_t i = 0; i < e.nops(); ++i) h = mix(h, structural_hash(e.op(i)));
  }
  hashes_.emplace(e, h);
  return h;
}

std::vector<ex> CommonSubexpressions::ordered_operands(const ex& e) {
  std::vector<ex> operands;
  for (std::size_t i = 0; i < e.nops(); ++i) operands.push_back(e.op(i));
  if (GiNaC::is_a<GiNaC::add>(e) || GiNaC::is_a<GiNaC::mul>(e))
    std::stable_sort(operands.begin(), operands.end(),
                     [&](const ex& a, const ex& b) { return orientation_free_hash(a) < orientation_free_hash(b); });
  return operands;
}

void CommonSubexpressions::count(const ex& original, std::map<ex, int, GiNaC::ex_is_less>& uses) {
  const ex e = leads_negative(original) ? ex(-original) : original;
  if (is_atom(e) || known_.count(e)) return;
  // such a power is never a temporary (reduce()): each of its uses is one of its base's
  if (is_small_power_of_sum(e) && uses[e] > 0) {
    ++uses[e];
    count(e.op(0), uses);
    return;
  }
  if (uses[e]++ > 0) return;  // children counted on the first visit only
  for (std::size_t i = 0; i < e.nops(); ++i) count(e.op(i), uses);
  if (repeats_a_call(e)) ++uses[e.op(0)];
}

ex CommonSubexpressions::reduce(const ex& original, const std::map<ex, int, GiNaC::ex_is_less>& uses, CseBatch& batch) {
  if (leads_negative(original)) return -reduce(-original, uses, batch);
  const ex& e = original;
  if (is_atom(e)) return e;
  if (auto k = known_.find(e); k != known_.end()) return k->second;
  GiNaC::exvector operands;
  for (const ex& o : ordered_operands(e)) operands.push_back(reduce(o, uses, batch));
  ex rebuilt;
  if (GiNaC::is_a<GiNaC::add>(e)) rebuilt = GiNaC::add(operands);
  else if (GiNaC::is_a<GiNaC::mul>(e)) rebuilt = GiNaC::mul(operands);
  else if (GiNaC::is_a<GiNaC::power>(e)) rebuilt = GiNaC::pow(operands[0], operands[1]);
  else {
    // a function: substitute its reduced arguments in order
    rebuilt = e;
    for (std::size_t i = 0; i < operands.size(); ++i) rebuilt.let_op(i) = operands[i];
  }
  auto used = uses.find(e);
  bool shared = used != uses.end() && used->second > 1;
  // a number times an atom (−x, 2·x) costs no more than reading a temporary
  bool scaled_atom = GiNaC::is_a<GiNaC::mul>(e) && e.nops() == 2 &&
                     ((GiNaC::is_a<GiNaC::numeric>(e.op(0)) && is_atom(e.op(1))) ||
                      (GiNaC::is_a<GiNaC::numeric>(e.op(1)) && is_atom(e.op(0))));
  if (!shared || is_cheap_power(e) || scaled_atom || is_small_power_of_sum(e)) return rebuilt;
  GiNaC::symbol name(prefix_ + std::to_string(next_++));
  batch.temporaries.push_back({name, rebuilt});
  known_.emplace(e, name);
  return name;
}

// Sums of atoms that share terms, such as the tail masses m_k + … + m_n of a chain,
// are not common subexpressions of each other; each shared one becomes a temporary
// built on the largest shared sum it contains: m_k + (m_{k+1} + … + m_n).
void CommonSubexpressions::nest_shared_sums(const std::map<ex, int, GiNaC::ex_is_less>& uses, CseBatch& batch) {
  std::vector<ex> candidates;
  for (const auto& [e, n] : uses) {
    if (n < 2 || !GiNaC::is_a<GiNaC::add>(e) || known_.count(e)) continue;
    bool flat = true;
    for (std::size_t i = 0; i < e.nops() && flat; ++i) {
      const ex t = e.op(i);
      flat = is_atom(t) || (GiNaC::is_a<GiNaC::mul>(t) && t.nops() == 2 && is_atom(t.op(0)) && is_atom(t.op(1)));
    }
    if (flat) candidates.push_back(e);
  }
  std::sort(candidates.begin(), candidates.end(), [&](const ex& a, const ex& b) {
    return a.nops() != b.nops() ? a.nops() < b.nops() : structural_hash(a) < structural_hash(b);
  });
  for (const ex& e : candidates) {
    GiNaC::exset terms;
    for (std::size_t i = 0; i < e.nops(); ++i) terms.insert(e.op(i));
    const NestedSum* inner = nullptr;
    for (const NestedSum& s : sums_)
      if (s.terms.size() < terms.size() && (!inner || s.terms.size() > inner->terms.size()) &&
          std::includes(terms.begin(), terms.end(), s.terms.begin(), s.terms.end(), GiNaC::ex_is_less()))
        inner = &s;
    ex definition = e;
    if (inner) {
      GiNaC::exvector rest{inner->temporary};
      for (const ex& t : terms)
        if (!inner->terms.count(t)) rest.push_back(t);
      definition = GiNaC::add(rest);
    }
    GiNaC::symbol name(prefix_ + std::to_string(next_++));
    batch.temporaries.push_back({name, definition});
    known_.emplace(e, name);
    sums_.push_back({terms, name});
  }
}

CseBatch CommonSubexpressions::add(const std::vector<ex>& expressions) {
  std::map<ex, int, GiNaC::ex_is_less> uses;
  for (const ex& e : expressions) count(e, uses);
  CseBatch batch;
  nest_shared_sums(uses, batch);
  for (const ex& e : expressions) batch.outputs.push_back(reduce(e, uses, batch));
  return batch;
}

}  // namespace eomgen
