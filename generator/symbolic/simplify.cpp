#include "symbolic/simplify.hpp"

#include <algorithm>
#include <map>

#include "symbolic/canonical_print.hpp"
#include "symbolic/trig_functions.hpp"

namespace eomgen {

using GiNaC::ex;
using GiNaC::ex_is_less;

bool MotionSymbols::depends(const ex& e) const {
  if (GiNaC::is_a<GiNaC::symbol>(e)) return symbols.count(e) > 0;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (depends(e.op(i))) return true;
  return false;
}

namespace {

std::vector<ex> terms_of(const ex& e) {
  std::vector<ex> terms;
  if (GiNaC::is_a<GiNaC::add>(e))
    for (std::size_t i = 0; i < e.nops(); ++i) terms.push_back(e.op(i));
  else if (!e.is_zero())
    terms.push_back(e);
  return terms;
}

std::vector<ex> factors_of(const ex& term) {
  std::vector<ex> factors;
  if (GiNaC::is_a<GiNaC::mul>(term))
    for (std::size_t i = 0; i < term.nops(); ++i) factors.push_back(term.op(i));
  else
    factors.push_back(term);
  return factors;
}

ex product(const std::vector<ex>& factors, std::size_t skip_a = SIZE_MAX, std::size_t skip_b = SIZE_MAX) {
  ex p = 1;
  for (std::size_t i = 0; i < factors.size(); ++i)
    if (i != skip_a && i != skip_b) p *= factors[i];
  return p;
}

ex sum(const std::vector<ex>& terms) {
  GiNaC::exvector v(terms.begin(), terms.end());
  return GiNaC::add(v);
}

}  // namespace

namespace {

// one of a and −a, the same for both: sin² and cos² do not see the sign of their angle, and
// GiNaC keeps sin(−φ) as it is, so that sin(−φ)² would not meet cos(φ)². Which one follows
// GiNaC's order, which may change between processes; it only keys the pairing.
ex either_sign(const ex& angle) {
  ex negated = -angle;
  return negated.compare(angle) < 0 ? negated : angle;
}

}  // namespace

ex apply_pythagoras(const ex& expanded) {
  std::vector<ex> terms = terms_of(expanded);
  for (bool changed = true; changed;) {
    changed = false;
    // key: (cofactor, angle) of a term c·sin(a)^2 or c·cos(a)^2 → index of the term
    std::map<std::pair<ex, ex>, std::size_t, bool (*)(const std::pair<ex, ex>&, const std::pair<ex, ex>&)> sines(
        [](const std::pair<ex, ex>& x, const std::pair<ex, ex>& y) {
          int c = x.first.compare(y.first);
          return c != 0 ? c < 0 : x.second.compare(y.second) < 0;
        });
    struct Cosine {
      std::size_t term;
      std::pair<ex, ex> key;
      ex angle;  // as written
    };
    std::vector<Cosine> cosines;
    for (std::size_t t = 0; t < terms.size(); ++t) {
      std::vector<ex> f = factors_of(terms[t]);
      for (std::size_t i = 0; i < f.size(); ++i) {
        // sin(a)^n with n ≥ 2 is sin(a)^2 · sin(a)^(n−2): the rest joins the cofactor
        if (!GiNaC::is_a<GiNaC::power>(f[i]) || !f[i].op(1).info(GiNaC::info_flags::integer) || f[i].op(1) < 2) continue;
        const ex base = f[i].op(0), cofactor = product(f, i) * GiNaC::pow(base, f[i].op(1) - 2);
        if (!is_sin(base) && !is_cos(base)) continue;
        std::pair<ex, ex> key{cofactor, either_sign(base.op(0))};
        if (is_sin(base)) {
          // c·sin(φ)² and c·sin(−φ)² share a key: the one of the smaller text pairs, so that the
          // one left over does not depend on GiNaC's order
          auto [at, fresh] = sines.emplace(key, t);
          if (!fresh && canonical_text(terms[t]) < canonical_text(terms[at->second])) at->second = t;
        } else {
          cosines.push_back({t, key, base.op(0)});
        }
      }
    }
    // visit candidates in canonical order: GiNaC's term order changes between processes (only
    // those with a sine partner: the text is costly, and the others are passed over anyway)
    std::vector<std::pair<std::string, std::size_t>> order;
    for (std::size_t c = 0; c < cosines.size(); ++c)
      if (sines.count(cosines[c].key))
        order.push_back({canonical_text(cosines[c].key.first * GiNaC::cos(cosines[c].angle)), c});
    std::sort(order.begin(), order.end());
    std::vector<bool> used(terms.size(), false);
    for (const auto& [text, c] : order) {
      const auto& [t, key, angle] = cosines[c];
      auto s = sines.find(key);
      if (s == sines.end() || used[t] || used[s->second] || s->second == t) continue;
      used[t] = used[s->second] = true;
      terms[t] = key.first;  // c·cos² + c·sin² = c
      terms[s->second] = 0;
      changed = true;
    }
    if (changed) terms = terms_of(sum(terms).expand());
  }
  return sum(terms);
}

namespace {

// A term c·X·f(a)·g(b) with f, g ∈ {sin, cos}, seen as one monomial of the pair (a, b).
struct PairTerm {
  std::size_t term;
  int kind;  // 0 cos a cos b, 1 sin a sin b, 2 sin a cos b, 3 cos a sin b
  ex coefficient;
};

struct PairKey {
  ex cofactor, a, b;
};

bool pair_key_less(const PairKey& x, const PairKey& y) {
  if (int c = x.cofactor.compare(y.cofactor)) return c < 0;
  if (int c = x.a.compare(y.a)) return c < 0;
  return x.b.compare(y.b) < 0;
}

int nonzero(const std::array<ex, 4>& v) {
  int n = 0;
  for (const ex& x : v) n += !x.is_zero();
  return n;
}

}  // namespace

ex combine_trig_products(const ex& expanded) {
  std::vector<ex> terms = terms_of(expanded);
  // canonical text of each angle, computed once: it orients the pairs independently of GiNaC's order
  std::map<ex, std::string, ex_is_less> angle_text;
  auto text_of = [&](const ex& a) -> const std::string& {
    auto found = angle_text.find(a);
    if (found == angle_text.end()) found = angle_text.emplace(a, canonical_text(a)).first;
    return found->second;
  };
  std::map<PairKey, std::vector<PairTerm>, bool (*)(const PairKey&, const PairKey&)> groups(pair_key_less);
  for (std::size_t t = 0; t < terms.size(); ++t) {
    std::vector<ex> f;
    ex coefficient = 1;
    for (const ex& x : factors_of(terms[t])) {
      if (GiNaC::is_a<GiNaC::numeric>(x)) coefficient *= x;
      else f.push_back(x);
    }
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (!is_sin(f[i]) && !is_cos(f[i])) continue;
      for (std::size_t j = i + 1; j < f.size(); ++j) {
        if (!is_sin(f[j]) && !is_cos(f[j])) continue;
        ex a = f[i].op(0), b = f[j].op(0);
        bool si = is_sin(f[i]), sj = is_sin(f[j]);
        if (a.is_equal(b)) continue;
        // orient the pair by the canonical text of its angles, so the result does not depend on GiNaC's order
        if (text_of(b) < text_of(a)) { std::swap(a, b); std::swap(si, sj); }
        int kind = !si && !sj ? 0 : (si && sj ? 1 : (si ? 2 : 3));
        groups[{product(f, i, j), a, b}].push_back({t, kind, coefficient});
      }
    }
  }
  std::vector<bool> used(terms.size(), false);
  std::vector<ex> extra;
  // when a term belongs to several groups, which group takes it depends on the visiting order:
  // then the groups are visited in the order of their keys' canonical text, for determinism
  std::vector<int> memberships(terms.size(), 0);
  for (const auto& g : groups)
    if (g.second.size() > 1)
      for (const PairTerm& p : g.second) ++memberships[p.term];
  bool overlapping = std::any_of(memberships.begin(), memberships.end(), [](int m) { return m > 1; });
  std::vector<std::pair<std::string, const std::pair<const PairKey, std::vector<PairTerm>>*>> order;
  for (const auto& g : groups)
    if (g.second.size() > 1)
      order.push_back({overlapping ? canonical_text(g.first.cofactor * GiNaC::sin(g.first.a) * GiNaC::cos(g.first.b)) : "", &g});
  if (overlapping) std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& [text, group] : order) {
    const PairKey& key = group->first;
    std::array<ex, 4> c{0, 0, 0, 0};
    bool free = true;
    for (const PairTerm& p : group->second) free = free && !used[p.term];
    if (!free) continue;
    for (const PairTerm& p : group->second) c[p.kind] += p.coefficient;
    // cc·cos a cos b + ss·sin a sin b + sc·sin a cos b + cs·cos a sin b
    //   = x·cos(a−b) + y·cos(a+b) + z·sin(a−b) + w·sin(a+b)
    std::array<ex, 4> folded{(c[0] + c[1]) / 2, (c[0] - c[1]) / 2, (c[2] - c[3]) / 2, (c[2] + c[3]) / 2};
    if (nonzero(folded) >= nonzero(c)) continue;
    for (const PairTerm& p : group->second) used[p.term] = true;
    ex d = key.a - key.b, s = key.a + key.b;
    extra.push_back(key.cofactor * (folded[0] * GiNaC::cos(d) + folded[1] * GiNaC::cos(s) +
                                    folded[2] * GiNaC::sin(d) + folded[3] * GiNaC::sin(s)));
  }
  if (extra.empty()) return expanded;
  for (std::size_t t = 0; t < terms.size(); ++t)
    if (!used[t]) extra.push_back(terms[t]);
  return sum(extra).expand();
}

namespace {

// the largest product of symbol powers that divides every term: Σ l1 l2 m_k → l1 l2 · Σ m_k,
// so that sums of parameters (the masses beyond a link) stand alone and can be shared
ex pull_common_factors(const ex& sum) {
  std::vector<ex> terms = terms_of(sum);
  if (terms.size() < 2) return sum;
  std::map<ex, GiNaC::numeric, ex_is_less> common;
  bool first = true;
  for (const ex& term : terms) {
    std::map<ex, GiNaC::numeric, ex_is_less> powers;
    for (const ex& f : factors_of(term)) {
      if (GiNaC::is_a<GiNaC::symbol>(f)) powers[f] += 1;
      else if (GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::symbol>(f.op(0)) && f.op(1).info(GiNaC::info_flags::posint))
        powers[f.op(0)] += GiNaC::ex_to<GiNaC::numeric>(f.op(1));
    }
    if (first) {
      common = powers;
      first = false;
      continue;
    }
    for (auto it = common.begin(); it != common.end();) {
      auto found = powers.find(it->first);
      if (found == powers.end()) it = common.erase(it);
      else {
        it->second = std::min(it->second, found->second);
        ++it;
      }
    }
  }
  if (common.empty()) return sum;
  ex factor = 1;
  for (const auto& [base, exponent] : common) factor *= GiNaC::pow(base, exponent);
  // each term divided by the factor exponent by exponent ((term / factor).expand() gives the same
  // product, through a division, and took a tenth of a long chain's derivation)
  GiNaC::exvector rest;
  for (const ex& term : terms) {
    GiNaC::exvector kept;
    for (const ex& f : factors_of(term)) {
      bool power = GiNaC::is_a<GiNaC::power>(f) && GiNaC::is_a<GiNaC::symbol>(f.op(0)) && f.op(1).info(GiNaC::info_flags::posint);
      const ex& base = power ? f.op(0) : f;
      auto found = (power || GiNaC::is_a<GiNaC::symbol>(f)) ? common.find(base) : common.end();
      if (found == common.end()) {
        kept.push_back(f);
        continue;
      }
      GiNaC::numeric left = (power ? GiNaC::ex_to<GiNaC::numeric>(f.op(1)) : GiNaC::numeric(1)) - found->second;
      if (!left.is_zero()) kept.push_back(GiNaC::pow(base, left));
    }
    rest.push_back(GiNaC::mul(kept));
  }
  return factor * GiNaC::add(rest);
}

}  // namespace

ex collect_by_motion(const ex& expanded, const MotionSymbols& motion) {
  // the terms of a group are gathered first and summed once: adding them one by one
  // rebuilds the growing sum each time, quadratic in the terms along a long chain
  std::map<ex, GiNaC::exvector, ex_is_less> groups;
  for (const ex& term : terms_of(expanded)) {
    GiNaC::exvector moving, fixed;
    for (const ex& f : factors_of(term)) (motion.depends(f) ? moving : fixed).push_back(f);
    groups[GiNaC::mul(moving)].push_back(GiNaC::mul(fixed));
  }
  GiNaC::exvector result;
  for (const auto& [moving, coefficients] : groups)
    result.push_back(pull_common_factors(GiNaC::add(coefficients)) * moving);
  return GiNaC::add(result);
}

ex tidy(const ex& e, const MotionSymbols& motion) {
  // collecting first sums the parameters of equal motion-dependent parts (the masses
  // along a chain), so that the trigonometric passes see n times fewer terms
  ex x = apply_pythagoras(collect_by_motion(e.expand(), motion));
  x = combine_trig_products(x);
  return collect_by_motion(x, motion);
}

}  // namespace eomgen
