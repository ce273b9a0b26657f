#include "model/recursive_frames.hpp"

#include <fmt/format.h>

#include "symbolic/gradient.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// a number, or a symbol or sin or cos of one, or its negative: written where it is used, it costs
// no more than its name (a turn by ±90° about x is a permutation of the entries with signs). (A
// multiple, m·c, costs a product at each use.)
bool is_signed_atom(const ex& x) {
  auto atom = [](const ex& a) {
    return GiNaC::is_a<GiNaC::symbol>(a) || ((GiNaC::is_the_function<GiNaC::sin_SERIAL>(a) || GiNaC::is_the_function<GiNaC::cos_SERIAL>(a)) &&
                                            GiNaC::is_a<GiNaC::symbol>(a.op(0)));
  };
  if (GiNaC::is_a<GiNaC::numeric>(x) || atom(x)) return true;
  return GiNaC::is_a<GiNaC::mul>(x) && x.nops() == 2 &&
         (((x.op(0) + 1).is_zero() && atom(x.op(1))) || ((x.op(1) + 1).is_zero() && atom(x.op(0))));
}

}  // namespace

ex intermediate(std::vector<Intermediate>& intermediates, const std::string& name, const std::string& cpp_name,
                const ex& definition) {
  if (is_signed_atom(definition)) return definition;
  Intermediate i{GiNaC::symbol(name), definition, cpp_name};
  intermediates.push_back(i);
  return i.symbol;
}

ex named_intermediate(std::vector<Intermediate>& intermediates, const std::string& who, const std::string& label,
                      const ex& definition) {
  std::string cpp = "k_" + who + "_" + label;
  for (char& c : cpp)
    if (c == '.') c = '_';
  return intermediate(intermediates, who + "." + label, cpp, definition.expand());
}

PlacedFrame place_recursive_frame(Model& model, const std::string& name, int parent, const Rotation& relative,
                                  const Vector3& origin) {
  static const char* axes = "xyz";
  PlacedFrame above = inertial_frame();
  if (parent >= 0) {
    const FrameLink& p = model.frame_links[std::size_t(parent)];
    above.rotation.matrix = p.rotation;
    above.origin = p.origin;
  }
  // a relative rotation or origin whose entries are sums (a joint about an oblique axis through an
  // anchor: a + b cos q + c sin q) is named first, so that each entry of the world pose is three
  // products of named entries, not the expansion of all of them
  // (at the root, the world pose is the relative one, named below)
  auto name_sum = [&](const ex& x, const std::string& quantity, const std::string& axes_of) {
    if (parent < 0) return x;
    ex expanded = x.expand();
    if (!GiNaC::is_a<GiNaC::add>(expanded)) return x;
    return intermediate(model.intermediates, fmt::format("{}.{}_{}", name, quantity, axes_of),
                        fmt::format("k_{}_{}{}", name, quantity, axes_of), expanded);
  };
  Rotation named = relative;
  Vector3 named_origin = origin;
  for (unsigned a = 0; a < 3; ++a) {
    for (unsigned b = 0; b < 3; ++b)
      named.matrix(a, b) = name_sum(relative.matrix(a, b), "E", fmt::format("{}{}", axes[a], axes[b]));
    named_origin[a] = name_sum(origin[a], "r", std::string(1, axes[a]));
  }
  PlacedFrame placed = place_frame(above, named, named_origin);
  FrameLink link;
  link.name = name;
  link.parent = parent;
  link.sequence = relative.sequence;
  link.relative_rotation = relative.matrix;
  link.relative_origin = origin;
  for (unsigned a = 0; a < 3; ++a) {
    for (unsigned b = 0; b < 3; ++b)
      link.rotation(a, b) = intermediate(model.intermediates, fmt::format("{}.R_{}{}", name, axes[a], axes[b]),
                                         fmt::format("k_{}_R{}{}", name, axes[a], axes[b]),
                                         placed.rotation.matrix(a, b).expand());
    link.origin[a] = intermediate(model.intermediates, fmt::format("{}.o_{}", name, axes[a]),
                                  fmt::format("k_{}_o{}", name, axes[a]), placed.origin[a].expand());
  }
  model.frame_links.push_back(link);
  PlacedFrame symbolic;
  symbolic.rotation.matrix = link.rotation;
  symbolic.origin = link.origin;
  return symbolic;
}

bool moves_with_time(const GiNaC::matrix& rotation, const Vector3& origin, const ex& time) {
  return ex(rotation).has(time) || origin[0].has(time) || origin[1].has(time) || origin[2].has(time);
}

bool uses_frames(const Vector3& v, const std::vector<Intermediate>& intermediates) {
  GiNaC::exset used;
  for (const ex& x : v) collect_symbols(x, used);
  for (const Intermediate& i : intermediates)
    if (used.count(i.symbol)) return true;
  return false;
}

}  // namespace eomgen
