#include "symbolic/gradient.hpp"

#include <map>

namespace eomgen {

namespace {
void symbols_of(const GiNaC::ex& e, const std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less>& index,
                std::vector<bool>& found) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    auto i = index.find(e);
    if (i != index.end()) found[i->second] = true;
    return;
  }
  for (std::size_t k = 0; k < e.nops(); ++k) symbols_of(e.op(k), index, found);
}
}  // namespace

void collect_symbols(const GiNaC::ex& e, GiNaC::exset& out) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) out.insert(e);
  for (std::size_t i = 0; i < e.nops(); ++i) collect_symbols(e.op(i), out);
}

std::vector<GiNaC::ex> gradient(const GiNaC::ex& e, const std::vector<GiNaC::ex>& variables) {
  std::map<GiNaC::ex, std::size_t, GiNaC::ex_is_less> index;
  for (std::size_t k = 0; k < variables.size(); ++k) index.emplace(variables[k], k);
  std::vector<GiNaC::exvector> parts(variables.size());
  auto add_term = [&](const GiNaC::ex& term) {
    std::vector<bool> found(variables.size(), false);
    symbols_of(term, index, found);
    for (std::size_t k = 0; k < variables.size(); ++k)
      if (found[k]) parts[k].push_back(term.diff(GiNaC::ex_to<GiNaC::symbol>(variables[k])));
  };
  if (GiNaC::is_a<GiNaC::add>(e))
    for (std::size_t i = 0; i < e.nops(); ++i) add_term(e.op(i));
  else
    add_term(e);
  std::vector<GiNaC::ex> out;
  for (auto& p : parts) out.push_back(GiNaC::add(p));
  return out;
}

}  // namespace eomgen
