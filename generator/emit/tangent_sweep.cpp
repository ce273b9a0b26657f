#include "emit/tangent_sweep.hpp"

#include <fmt/format.h>

#include "symbolic/gradient.hpp"

namespace eomgen {

using GiNaC::ex;

TangentSweep::TangentSweep(BodyWriter& writer, const std::vector<ex>& directions)
    : writer_(writer), num_directions_(directions.size()) {
  for (std::size_t j = 0; j < directions.size(); ++j) tangents_[directions[j]][j] = 1;
}

// the chain rule through one node: dE/dj = Σ over E's symbols s of ∂E/∂s · ds/dj
std::vector<ex> TangentSweep::derivatives(const ex& reduced) const {
  std::vector<ex> out(num_directions_, 0);
  GiNaC::exset symbols;
  collect_symbols(reduced, symbols);
  for (const ex& s : symbols) {
    auto found = tangents_.find(s);
    if (found == tangents_.end()) continue;
    ex partial = reduced.diff(GiNaC::ex_to<GiNaC::symbol>(s));
    if (partial.is_zero()) continue;
    for (const auto& [j, tangent] : found->second) out[j] += partial * tangent;
  }
  return out;
}

// X = 1/u (a quaternion's 1/|q|²) has X' = −X² u': products of X, where differentiating the
// definition gives −u'/u², a division and u formed again
std::vector<ex> TangentSweep::derivatives_of(const Temporary& t) const {
  const ex& d = t.definition;
  if (!GiNaC::is_a<GiNaC::power>(d) || !d.op(1).is_equal(-1)) return derivatives(d);
  std::vector<ex> out = derivatives(d.op(0));
  for (ex& x : out) x = -t.name * t.name * x;
  return out;
}

void TangentSweep::follow(const CseBatch& batch) {
  for (const Temporary& t : batch.temporaries) {
    std::vector<ex> d = derivatives_of(t);
    std::vector<std::size_t> written;
    std::vector<ex> values;
    auto& mine = tangents_[t.name];
    for (std::size_t j = 0; j < d.size(); ++j) {
      if (d[j].is_zero()) continue;
      // a tangent that is a symbol or a number needs no line of its own
      if (GiNaC::is_a<GiNaC::symbol>(d[j]) || GiNaC::is_a<GiNaC::numeric>(d[j])) mine[j] = d[j];
      else {
        written.push_back(j);
        values.push_back(d[j]);
      }
    }
    if (values.empty()) {
      if (mine.empty()) tangents_.erase(t.name);
      continue;
    }
    std::vector<std::string> code = writer_.batch(values);
    for (std::size_t i = 0; i < written.size(); ++i) {
      std::string name = fmt::format("{}_d{}", writer_.own_name_of(t.name), written[i]);
      GiNaC::symbol tangent(name);
      writer_.name(tangent, name);
      writer_.line(fmt::format("const T {} = {};", name, code[i]));
      mine[written[i]] = tangent;
      written_.push_back({tangent, values[i]});
    }
  }
}

}  // namespace eomgen
