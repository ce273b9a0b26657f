#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "model/model_builder.hpp"

namespace eomgen {

using GiNaC::ex;

// `may_be_zero`: a rigid body with unphysical_inertia, as a URDF's link of mass 0 with a moment of
// inertia is (Bolt's feet), which URDF readers take as it stands; a rigid body without it is told so
ex ModelBuilder::mass(const ExpressionText& text, bool rigid_body, bool may_be_zero) {
  auto e = parse(text, allow_parameters, "a mass");
  if (!e) return 1;
  auto v = constant_value(*e, m_.symbols);
  if (!v || *v < 0 || (*v == 0 && !may_be_zero))
    d_.error(text.where, text.key,
             v ? fmt::format("the mass is {} with the default parameters; a mass must be positive", *v)
               : std::string("the mass is not a finite real number"),
             rigid_body && v && *v == 0 ? "a rigid body of no mass but a moment of inertia, as a robot file may state it: "
                            "unphysical_inertia = true"
                          : "check the sign of the mass parameter's default in [parameters]");
  return *e;
}

Vector3 ModelBuilder::vector(const std::vector<ExpressionText>& texts, unsigned allowed, const char* context) {
  Vector3 v{0, 0, 0};
  if (std::string name = vector_name(texts); !name.empty()) {
    auto found = m_.symbols.by_name.find(name);
    if (found == m_.symbols.by_name.end() || found->second.kind != SymbolKind::vector) {
      // one error for the name, not one per component
      std::string key = texts[0].key.substr(0, texts[0].key.rfind('['));
      d_.error(texts[0].where, key, fmt::format("'{}' is not a vector or a point", name),
               m_.symbols.vector_names.empty()
                   ? "define it under [definitions] (name = [\"x\", \"y\", \"z\"]) or as a [[points]] entry"
                   : suggest(name, m_.symbols.vector_names, "vectors and points"));
      return v;
    }
  }
  for (std::size_t i = 0; i < texts.size() && i < 3; ++i)
    if (auto e = parse(texts[i], allowed, context)) v[i] = *e;
  return v;
}

std::string ModelBuilder::vector_name(const std::vector<ExpressionText>& texts) {
  if (texts.size() != 3) return {};
  const std::string& x = texts[0].text;
  if (x.size() < 3 || x.compare(x.size() - 2, 2, ".x") != 0) return {};
  std::string name = x.substr(0, x.size() - 2);
  for (std::size_t i = 0; i < 3; ++i)
    if (texts[i].text != component_name(name, i) || texts[i].where.line != texts[0].where.line ||
        texts[i].where.column != texts[0].where.column)
      return {};
  return name;
}

void ModelBuilder::check_body_name(const std::string& name, const SourceLocation& where, const std::string& key) {
  if (name.empty()) return;
  if (!is_identifier(name))
    d_.error(where, key + ".name", fmt::format("'{}' is not a valid body name", name), "use letters, digits and _");
  if (!body_names_.emplace(name, where.line).second)
    d_.error(where, key + ".name", fmt::format("duplicate body name '{}' (first on line {})", name, body_names_[name]),
             "give every particle and rigid body its own name");
}

void ModelBuilder::read_bodies() {
  for (const ParticleEntry& p : f_.particles) {
    check_body_name(p.name, p.where, p.key);
    const PlacedFrame* in = frame(p.frame, p.frame_where, p.key + ".frame");
    Vector3 local = vector(p.position, allow_configuration, "a position");
    Rotation still = rotation(std::nullopt);
    std::string in_frame = in ? body_frame(p.name, p.frame, local, still) : p.frame;
    if (in) in = frame(in_frame, p.frame_where, p.key + ".frame");
    m_.particles.push_back({p.name, mass(p.mass), in ? place_point(*in, local) : local,
                            placement(in_frame, local, still, p.where, p.key + ".position")});
  }
  for (const RigidBodyEntry& b : f_.rigid_bodies) {
    check_body_name(b.name, b.where, b.key);
    const PlacedFrame* in = frame(b.frame, b.frame_where, b.key + ".frame");
    Vector3 local = vector(b.center, allow_configuration, "a position");
    Rotation relative = rotation(b.rotation);
    std::string in_frame = in ? body_frame(b.name, b.frame, local, relative) : b.frame;
    if (in) in = frame(in_frame, b.frame_where, b.key + ".frame");
    RigidBody body{b.name, mass(b.mass, true, b.unphysical_inertia), in ? place_point(*in, local) : local, {}, {3, 3}};
    body.rotation = in ? compose(in->rotation, relative) : relative;
    body.inertia = inertia(b);
    body.placement = placement(in_frame, local, relative, b.where, b.key + ".center");
    m_.rigid_bodies.push_back(body);
  }
}

std::string ModelBuilder::body_frame(const std::string& name, const std::string& frame, Vector3& local, Rotation& relative) {
  if (reading_ != FrameReading::tree || !m_.recursive_kinematics) return frame;
  auto links = frame_as_joints(relative, local, m_.symbols);
  if (!links) return frame;
  std::string link = unused_link_name(name);
  frames_.emplace(link, place_joint_links(link, link_of(frame), *links));
  local = {0, 0, 0};
  relative = rotation(std::nullopt);
  return link;
}

Rotation ModelBuilder::rotation(const std::optional<RotationEntry>& given) {
  Rotation r;
  r.matrix = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3));
  if (!given) return r;
  if (given->product && names_matrix(given->product->text)) {
    std::vector<std::vector<ExpressionText>> entries(3, std::vector<ExpressionText>(3, *given->product));
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j) entries[i][j].text = entry_name(given->product->text, i, j);
    RotationEntry whole = *given;
    whole.product.reset();
    whole.matrix = entries;
    return rotation(whole);
  }
  if (given->product) {
    auto sequence = parse_rotation_product(*given->product, m_.symbols, {allow_configuration, "a rotation"}, d_);
    if (!sequence) return r;
    r.sequence = *sequence;
    r.matrix = rotation_product(r.sequence);
    return r;
  }
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      if (i < given->matrix.size() && j < given->matrix[i].size())
        if (auto e = parse(given->matrix[i][j], allow_configuration, "a rotation")) r.matrix(i, j) = *e;
  check_orthogonal(r.matrix, *given);
  return r;
}

bool ModelBuilder::names_matrix(const std::string& text) const {
  auto found = m_.symbols.by_name.find(text);
  return found != m_.symbols.by_name.end() && found->second.kind == SymbolKind::matrix;
}

void ModelBuilder::check_orthogonal(const GiNaC::matrix& R, const RotationEntry& where) {
  GiNaC::exmap at = m_.symbols.default_parameter_values();
  for (std::size_t i = 0; i < m_.symbols.coordinates.size() && i < m_.symbols.initial_coordinates.size(); ++i)
    at[m_.symbols.coordinates[i]] = m_.symbols.initial_coordinates[i];
  at[m_.symbols.time] = 0;
  GiNaC::matrix RtR = R.transpose().mul(R);
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) {
      auto v = constant_value(RtR(i, j).subs(at), m_.symbols);
      if (!v || std::abs(*v - (i == j ? 1.0 : 0.0)) > 1e-9) {
        d_.error(where.where, where.key, "the rotation matrix is not orthogonal at the initial state (R^T R != I)",
                 "check the entries, or write it as a product such as rot_z(a)*rot_x(b)");
        return;
      }
    }
}

GiNaC::matrix ModelBuilder::inertia(const RigidBodyEntry& b) {
  GiNaC::matrix I(3, 3);
  if (b.inertia_name && !names_matrix(b.inertia_name->text)) {
    d_.error(b.inertia_name->where, b.inertia_name->key,
             fmt::format("'{}' is not a 3x3 matrix under [definitions]", b.inertia_name->text),
             m_.symbols.matrix_names.empty()
                 ? "define it, e.g. I_B = [[\"A\", \"0\", \"0\"], [\"0\", \"B\", \"0\"], [\"0\", \"0\", \"C\"]]"
                 : suggest(b.inertia_name->text, m_.symbols.matrix_names, "matrices"));
    return I;
  }
  if (!b.principal_inertia.empty()) {
    Vector3 moments = vector(b.principal_inertia, allow_parameters, "an inertia");
    for (std::size_t i = 0; i < 3; ++i) {
      I(i, i) = moments[i];
      auto v = constant_value(moments[i], m_.symbols);
      if (v && *v < 0 && !b.unphysical_inertia)
        d_.error(b.principal_inertia[i].where, b.principal_inertia[i].key,
                 fmt::format("the principal moment is {} with the default parameters; it must not be negative", *v),
                 "a robot file's values that are meant as they stand: unphysical_inertia = true");
    }
  } else if (b.inertia.size() == 3) {
    for (std::size_t i = 0; i < 3; ++i) {
      Vector3 row = vector(b.inertia[i], allow_parameters, "an inertia");
      for (std::size_t j = 0; j < 3; ++j) I(i, j) = row[j];
    }
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = i + 1; j < 3; ++j)
        if (!(I(i, j) - I(j, i)).expand().is_zero())
          d_.error(b.inertia[i][j].where, b.inertia[i][j].key,
                   fmt::format("the inertia tensor is not symmetric: entry ({},{}) differs from ({},{})", i, j, j, i),
                   "an inertia tensor equals its transpose");
  }
  if (!b.principal_inertia.empty() || b.inertia.size() == 3) check_realizable(I, b);
  return I;
}

void ModelBuilder::check_realizable(const GiNaC::matrix& I, const RigidBodyEntry& b) {
  double v[3][3], scale = 0;
  for (unsigned i = 0; i < 3; ++i)
    for (unsigned j = 0; j < 3; ++j) {
      auto x = constant_value(I(i, j), m_.symbols);
      if (!x) return;
      v[i][j] = *x, scale = std::max(scale, std::abs(*x));
    }
  double trace = v[0][0] + v[1][1] + v[2][2], J[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) J[i][j] = (i == j ? trace / 2 : 0) - v[i][j];
  auto minor2 = [&](int i, int j) { return J[i][i] * J[j][j] - J[i][j] * J[j][i]; };
  double det = J[0][0] * minor2(1, 2) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
               J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
  double tol = 1e-12 * scale;
  bool realizable = J[0][0] >= -tol && J[1][1] >= -tol && J[2][2] >= -tol && minor2(0, 1) >= -tol * scale &&
                    minor2(0, 2) >= -tol * scale && minor2(1, 2) >= -tol * scale && det >= -tol * scale * scale;
  // [0, 0, Izz]: the shorthand of planar models, where only one moment ever acts
  int zero_moments = (v[0][0] == 0) + (v[1][1] == 0) + (v[2][2] == 0);
  if (realizable || b.unphysical_inertia || (!b.principal_inertia.empty() && zero_moments == 2)) return;
  const ExpressionText& at = b.principal_inertia.empty() ? b.inertia[0][0] : b.principal_inertia[0];
  std::string what = b.principal_inertia.empty()
                         ? "its principal moments"
                         : fmt::format("{:g}, {:g}, {:g}", v[0][0], v[1][1], v[2][2]);
  d_.error(at.where, b.key + ".inertia",
           fmt::format("no rigid body has this inertia: {} break the triangle inequality (each principal moment is at "
                       "most the sum of the other two) with the default parameters", what),
           "check the axes and the values; a planar model that only needs Izz can give a thin plate's moments, "
           "[Izz/2, Izz/2, Izz]; a robot file's values that are meant as they stand: unphysical_inertia = true");
}

}  // namespace eomgen
