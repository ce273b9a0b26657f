#include "spatial/gradient_frame.hpp"

#include <map>
#include <optional>

#include "symbolic/cse.hpp"
#include "symbolic/expression_cost.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// the operations the header writes for the gradient's entries (the quantities they need, with their
// common subexpressions shared as the emitter shares them): what the frame is chosen by, since the
// expressions' own counts, before sharing, rank the frames differently
long shared_operations(const std::vector<Intermediate>& out, std::size_t first, const InverseDynamicsGradient& g) {
  std::map<ex, std::size_t, GiNaC::ex_is_less> defined;
  for (std::size_t i = first; i < out.size(); ++i) defined.emplace(out[i].symbol, i);
  std::vector<ex> entries(g.bias);
  for (const GiNaC::matrix* m : {&g.coordinates, &g.velocities, &g.mass_matrix})
    for (unsigned i = 0; i < m->nops(); ++i) entries.push_back(m->op(i));
  std::vector<bool> needed(out.size(), false);
  std::vector<ex> pending = entries;
  while (!pending.empty()) {
    ex e = pending.back();
    pending.pop_back();
    for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
      auto found = GiNaC::is_a<GiNaC::symbol>(*it) ? defined.find(*it) : defined.end();
      if (found == defined.end() || needed[found->second]) continue;
      needed[found->second] = true;
      pending.push_back(out[found->second].definition);
    }
  }
  std::vector<ex> all;
  for (std::size_t i = first; i < out.size(); ++i)
    if (needed[i]) all.push_back(out[i].definition);
  all.insert(all.end(), entries.begin(), entries.end());
  CommonSubexpressions shared("s");
  CseBatch b = shared.add(all);
  std::vector<ex> counted = b.outputs;
  for (const Temporary& t : b.temporaries) counted.push_back(t.definition);
  return arithmetic_operations(counted);
}

// the links whose frames the gradient may be written in: those up to three joints below a root (the
// seven-joint arm's best is two below), at most `most`, in the links' order
std::vector<std::size_t> reference_candidates(const std::vector<TreeLink>& links, std::size_t most = 8) {
  std::vector<std::size_t> depth(links.size(), 0), candidates;
  for (std::size_t i = 0; i < links.size(); ++i) {
    if (links[i].parent >= 0) depth[i] = depth[std::size_t(links[i].parent)] + 1;
    if (depth[i] <= 3 && candidates.size() < most) candidates.push_back(i);
  }
  return candidates;
}

}  // namespace

// The frame matters: the seven-joint arm's gradient takes 5,338 operations in the world's axes,
// 5,038 in its first link's, 4,752 in its second's and 4,635 in its third's (each about the
// shoulder), and 6,169 in its fourth's, where the links near the base turn by more joints (g++ -O2:
// jacobian_state 3.48–3.54 rhs in the world's axes, 3.17–3.21 in the third link's). The cheapest
// candidate's quantities are kept as they were derived, not derived again.
InverseDynamicsGradient written_out_gradient(const std::vector<TreeLink>& links, const Vector3& gravity, const std::vector<ex>& ddq,
                                             std::size_t velocities, std::size_t coordinates, std::vector<Intermediate>& out) {
  std::size_t first = out.size();
  InverseDynamicsGradient best = gradient_in(links, gravity, ddq, velocities, coordinates, out, std::nullopt);
  long fewest = shared_operations(out, first, best);
  std::vector<Intermediate> best_quantities(out.begin() + long(first), out.end());
  for (std::size_t ref : reference_candidates(links)) {
    out.resize(first);
    InverseDynamicsGradient g = gradient_in(links, gravity, ddq, velocities, coordinates, out, ref);
    long operations = shared_operations(out, first, g);
    if (operations >= fewest) continue;
    fewest = operations, best = std::move(g);
    best_quantities.assign(out.begin() + long(first), out.end());
  }
  out.resize(first);
  out.insert(out.end(), best_quantities.begin(), best_quantities.end());
  return best;
}

}  // namespace eomgen
