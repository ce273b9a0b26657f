#include "spatial/fixed_links.hpp"

#include "kinematics/vector3.hpp"

namespace eomgen {

namespace {

GiNaC::matrix expanded_entries(const GiNaC::matrix& m) {
  GiNaC::matrix out(m.rows(), m.cols());
  for (unsigned r = 0; r < m.rows(); ++r)
    for (unsigned c = 0; c < m.cols(); ++c) out(r, c) = m(r, c).expand();
  return out;
}

Vector3 expanded_entries(const Vector3& x) { return {x[0].expand(), x[1].expand(), x[2].expand()}; }

GiNaC::matrix unturned() {
  GiNaC::matrix one(3, 3);
  for (unsigned k = 0; k < 3; ++k) one(k, k) = 1;
  return one;
}

}  // namespace

std::vector<TreeLink> with_fixed_links_fused(const std::vector<TreeLink>& links) {
  // per link: the kept link it belongs to (its host), and its own coordinates' turn and origin
  // in the host's
  std::vector<int> host(links.size(), -1);
  std::vector<GiNaC::matrix> turn_in_host(links.size(), unturned());
  std::vector<Vector3> origin_in_host(links.size(), Vector3{0, 0, 0});
  std::vector<TreeLink> out;
  for (std::size_t i = 0; i < links.size(); ++i) {
    const TreeLink& l = links[i];
    bool keep = l.parent < 0 || !l.columns.empty();
    std::size_t p = l.parent < 0 ? 0 : std::size_t(l.parent);
    // the link's constant placement in its parent's host, before its own joint moves it
    GiNaC::matrix turn = l.parent < 0 ? l.turn : expanded_entries(turn_in_host[p].mul(l.turn));
    Vector3 offset = l.parent < 0 ? l.offset : expanded_entries(origin_in_host[p] + times(turn_in_host[p], l.offset));
    if (keep) {
      host[i] = int(out.size());
      TreeLink k = l;
      k.parent = l.parent < 0 ? -1 : host[p];
      k.turn = turn;
      k.offset = offset;
      out.push_back(k);
      continue;
    }
    host[i] = host[p];
    turn_in_host[i] = turn;
    origin_in_host[i] = offset;
    for (const TreeLink::Body& b : l.bodies) {
      TreeLink::Body moved{b.mass, expanded_entries(offset + times(turn, b.center)),
                           expanded_entries(turn.mul(b.inertia).mul(turn.transpose()))};
      out[std::size_t(host[i])].bodies.push_back(moved);
    }
  }
  return out;
}

}  // namespace eomgen
