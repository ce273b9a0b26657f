#include <cmath>

#include <fmt/format.h>

#include "kinematics/rolling_contact.hpp"
#include "model/frames.hpp"
#include "model/model.hpp"
#include "model/recursive_frames.hpp"

namespace eomgen {

using GiNaC::ex;

const std::vector<std::string>& known_methods() {
  static const std::vector<std::string> methods = {"lagrange2", "lagrange1", "appell", "hamilton"};
  return methods;
}

namespace {

/// The value of a constant expression with parameters at their defaults.
std::optional<double> constant_value(const ex& e, const Symbols& symbols) {
  ex v = e.subs(symbols.default_parameter_values()).evalf();
  if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return std::nullopt;
  double x = GiNaC::ex_to<GiNaC::numeric>(v).to_double();
  if (!std::isfinite(x)) return std::nullopt;
  return x;
}

class Builder {
 public:
  Builder(const ModelFile& file, Diagnostics& d) : f_(file), d_(d) {}

  Model build() {
    m_.name = f_.name;
    m_.title = f_.title;
    m_.method = f_.method;
    m_.recursive_kinematics = f_.kinematics == "recursive";
    m_.forward_dynamics = f_.forward_dynamics;
    m_.source = f_.path;
    check_header();
    declare_symbols();
    read_definitions();
    read_initial_state();
    read_frames();
    read_points();
    read_bodies();
    read_energies_and_forces();
    read_constraints();
    read_outputs();
    check_complete();
    check_forward_dynamics(f_, m_, d_);
    build_scenes_and_variants(f_, m_, d_);
    return m_;
  }

 private:
  std::optional<ex> parse(const ExpressionText& text, unsigned allowed, const char* context) {
    return parse_expression(text, m_.symbols, {allowed, context}, d_);
  }

  void check_header() {
    if (f_.name.empty()) return;  // reported by the parser
    if (!is_cpp_identifier(f_.name))
      d_.error(f_.name_where, "model.name", fmt::format("'{}' is not a C++ identifier", f_.name),
               "the name becomes the header's file name and namespace: use letters, digits and _, e.g. double_pendulum");
    else if (f_.name == "std")
      d_.error(f_.name_where, "model.name", "'std' would name the header's namespace eomgen::models::std, which hides the "
               "standard library from the header's own code", "choose another name, e.g. std_model");
    const auto& methods = known_methods();
    if (std::find(methods.begin(), methods.end(), f_.method) == methods.end())
      d_.error(f_.method_where, "model.method", fmt::format("unknown method '{}'", f_.method),
               suggest(f_.method, methods, "methods"));
    if (f_.kinematics != "expanded" && f_.kinematics != "recursive")
      d_.error(f_.kinematics_where, "model.kinematics", fmt::format("unknown kinematics '{}'", f_.kinematics),
               "use \"expanded\" (positions and rotations multiplied out, the default) or \"recursive\" (frames "
               "composed link by link, for long chains)");
  }



  void declare(const std::string& name, SourceLocation where, const std::string& key,
               SymbolKind kind, std::size_t index, const char* what) {
    static const char* kind_names[] = {"a parameter", "a coordinate", "an input", "a definition", "a vector", "a matrix"};
    if (!is_identifier(name)) {
      d_.error(where, key, fmt::format("'{}' is not a valid name", name), "use letters, digits and _, starting with a letter");
      return;
    }
    if (is_reserved_name(name)) {
      d_.error(where, key, fmt::format("'{}' is reserved and cannot name {}", name, what),
               "t is time, der() a velocity, Pi is pi; the others are functions");
      return;
    }
    auto [it, fresh] = m_.symbols.by_name.emplace(name, SymbolInfo{kind, index});
    if (!fresh) {
      SourceLocation first = declared_at_[name];
      d_.error(where, key,
               fmt::format("symbol '{}' is defined twice: as {} (line {}) and as {}", name,
                           kind_names[static_cast<int>(it->second.kind)], first.line, what),
               "give each parameter, coordinate and input its own name");
      return;
    }
    declared_at_[name] = where;
  }

  void declare_symbols() {
    Symbols& s = m_.symbols;
    for (const ParameterEntry& p : f_.parameters) {
      declare(p.name, p.where, p.key, SymbolKind::parameter, s.parameters.size(), "a parameter");
      s.parameter_names.push_back(p.name);
      s.parameters.emplace_back(p.name);
      s.parameter_defaults.push_back(p.value);
    }
    for (const CoordinateEntry& c : f_.coordinates) {
      declare(c.name, c.where, c.key, SymbolKind::coordinate, s.coordinates.size(), "a coordinate");
      s.coordinate_names.push_back(c.name);
      s.coordinates.emplace_back(c.name);
      s.velocities.emplace_back("der(" + c.name + ")");
    }
    for (const ParameterEntry& u : f_.inputs) {
      declare(u.name, u.where, u.key, SymbolKind::input, s.inputs.size(), "an input");
      s.input_names.push_back(u.name);
      s.inputs.emplace_back(u.name);
      s.input_defaults.push_back(u.value);
    }
    m_.generalized_force.assign(s.coordinates.size(), 0);
  }

  double constant(const ExpressionText& text, const char* context, ex* expression = nullptr) {
    auto e = parse(text, allow_parameters, context);
    if (!e) return 0;
    if (expression) *expression = *e;
    auto v = constant_value(*e, m_.symbols);
    if (!v) d_.error(text.where, text.key, "the value is not a finite real number");
    return v.value_or(0);
  }

  // in file order: each may use the symbols and the definitions before it
  void read_definitions() {
    std::vector<std::string> later;
    for (const DefinitionEntry& e : f_.definitions) later.push_back(e.name);
    for (const DefinitionEntry& e : f_.definitions) {
      later.erase(later.begin());
      std::string key = "definitions." + e.name;
      if (e.components.size() == 1) {
        auto value = parse_expression(e.components[0], m_.symbols, {allow_everything, "a definition", &later}, d_);
        define(e.name, e.where, key, value.value_or(0));
        continue;
      }
      std::vector<ex> values(e.components.size(), 0);
      for (std::size_t i = 0; i < values.size(); ++i)
        if (auto c = parse_expression(e.components[i], m_.symbols, {allow_everything, "a definition", &later}, d_))
          values[i] = *c;
      define_whole(e.name, e.where, key, values);
    }
  }

  void define(const std::string& name, SourceLocation where, const std::string& key, const ex& value) {
    Symbols& s = m_.symbols;
    declare(name, where, key, SymbolKind::definition, s.definitions.size(), "a definition");
    s.definition_names.push_back(name);
    s.definitions.push_back(value);
  }

  // NAME names a vector or a matrix as a whole (to refuse it as a scalar); its components,
  // named as component_name or entry_name give them, are definitions
  void define_whole(const std::string& name, SourceLocation where, const std::string& key, const std::vector<ex>& values) {
    Symbols& s = m_.symbols;
    if (!is_identifier(name)) {
      d_.error(where, key, fmt::format("'{}' is not a valid name", name), "use letters, digits and _, starting with a letter");
      return;
    }
    bool matrix = values.size() == 9;
    std::vector<std::string>& wholes = matrix ? s.matrix_names : s.vector_names;
    declare(name, where, key, matrix ? SymbolKind::matrix : SymbolKind::vector, wholes.size(), matrix ? "a matrix" : "a vector");
    wholes.push_back(name);
    for (std::size_t k = 0; k < values.size(); ++k) {
      std::string component = matrix ? entry_name(name, k / 3, k % 3) : component_name(name, k);
      s.by_name[component] = {SymbolKind::definition, s.definitions.size()};
      s.definition_names.push_back(component);
      s.definitions.push_back(values[k]);
    }
  }

  // [[frames]] in file order: a parent comes before its children
  void read_frames() {
    for (const FrameEntry& f : f_.frames) {
      if (f.name.empty()) continue;  // reported by the parser
      if (!is_identifier(f.name) || f.name == "inertial") {
        d_.error(f.where, f.key + ".name", fmt::format("'{}' cannot name a frame", f.name),
                 "use letters, digits and _; \"inertial\" is the inertial frame");
        continue;
      }
      const PlacedFrame* parent = frame(f.parent, f.parent_where, f.key + ".parent");
      if (!parent) continue;
      Rotation relative = rotation(f.rotation);
      Vector3 origin = f.origin.empty() ? Vector3{0, 0, 0} : vector(f.origin, allow_configuration, "a position");
      if (frames_.count(f.name)) {
        d_.error(f.where, f.key + ".name", fmt::format("two frames are named '{}'", f.name), "give each frame its own name");
        continue;
      }
      if (!m_.recursive_kinematics) {
        frames_.emplace(f.name, place_frame(*parent, relative, origin));
        continue;
      }
      if (moves_with_time(relative.matrix, origin, m_.symbols.time))
        d_.error(f.where, f.key, fmt::format("frame '{}' moves with time t itself", f.name),
                 "recursive kinematics takes frames placed by the coordinates alone: make the prescribed motion a "
                 "coordinate, or use kinematics = \"expanded\"");
      frame_index_[f.name] = int(m_.frame_links.size());
      frames_.emplace(f.name, place_recursive_frame(m_, f.name, link_of(f.parent), relative, origin));
    }
  }

  // the frame link of a frame name for recursive kinematics; -1: the inertial frame (or none)
  int link_of(const std::string& name) const {
    auto found = frame_index_.find(name);
    return found == frame_index_.end() ? -1 : found->second;
  }

  // where a body is, for recursive kinematics; a body outside the frames must not be placed
  // through them (by a point): only the recursion knows how such a position moves
  FramePlacement placement(const std::string& frame_name, const Vector3& local, const Rotation& relative,
                           const SourceLocation& where, const std::string& key) {
    FramePlacement p;
    if (!m_.recursive_kinematics) return p;
    if (frame_name.empty() && uses_frames(local, m_.intermediates))
      d_.error(where, key, "with recursive kinematics a body is placed in a frame, not through a point of one",
               "give the body frame = \"...\" and its centre in that frame's coordinates");
    else if (!frame_name.empty() && moves_with_time(relative.matrix, local, m_.symbols.time))
      d_.error(where, key, "with recursive kinematics a body in a frame moves with the coordinates alone, not with t",
               "make the prescribed motion a coordinate, or use kinematics = \"expanded\"");
    p.frame = link_of(frame_name);
    p.local = local;
    p.sequence = relative.sequence;
    p.relative = relative.matrix;
    return p;
  }

  // the frame named `name` (the inertial frame when empty), or nothing after an error
  const PlacedFrame* frame(const std::string& name, const SourceLocation& where, const std::string& key) {
    static const PlacedFrame inertial = inertial_frame();
    if (name.empty()) return &inertial;
    auto found = frames_.find(name);
    if (found != frames_.end()) return &found->second;
    std::vector<std::string> names{"inertial"};
    for (const FrameEntry& f : f_.frames) names.push_back(f.name);
    bool later = std::find(names.begin(), names.end(), name) != names.end();
    d_.error(where, key, fmt::format("'{}' is not a frame{}", name, later ? " yet: [[frames]] are read from the top" : ""),
             later ? "move the parent frame above the frames and bodies that use it" : suggest(name, names, "frames"));
    return nullptr;
  }

  void read_points() {
    for (const PointEntry& p : f_.points) {
      const PlacedFrame* in = frame(p.frame, p.frame_where, p.key + ".frame");
      if (!in || p.name.empty()) continue;
      Vector3 at = place_point(*in, vector(p.position, allow_configuration, "a position"));
      define_whole(p.name, p.where, p.key + ".name", {at[0], at[1], at[2]});
    }
  }

  void read_initial_state() {
    Symbols& s = m_.symbols;
    for (const CoordinateEntry& c : f_.coordinates) {
      ex q0 = 0, rate0 = 0;
      s.initial_coordinates.push_back(constant(c.initial, "an initial value", &q0));
      s.initial_velocities.push_back(constant(c.rate, "an initial rate", &rate0));
      s.initial_coordinate_expressions.push_back(q0);
      s.initial_rate_expressions.push_back(rate0);
    }
  }

  ex mass(const ExpressionText& text) {
    auto e = parse(text, allow_parameters, "a mass");
    if (!e) return 1;
    auto v = constant_value(*e, m_.symbols);
    if (!v || *v <= 0)
      d_.error(text.where, text.key,
               v ? fmt::format("the mass is {} with the default parameters; a mass must be positive", *v)
                 : std::string("the mass is not a finite real number"),
               "check the sign of the mass parameter's default in [parameters]");
    return *e;
  }

  Vector3 vector(const std::vector<ExpressionText>& texts, unsigned allowed, const char* context) {
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

  // NAME when the components were read from one string "NAME" (NAME.x, NAME.y, NAME.z)
  static std::string vector_name(const std::vector<ExpressionText>& texts) {
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

  void check_body_name(const std::string& name, const SourceLocation& where, const std::string& key) {
    if (name.empty()) return;
    if (!is_identifier(name))
      d_.error(where, key + ".name", fmt::format("'{}' is not a valid body name", name), "use letters, digits and _");
    if (!body_names_.emplace(name, where.line).second)
      d_.error(where, key + ".name", fmt::format("duplicate body name '{}' (first on line {})", name, body_names_[name]),
               "give every particle and rigid body its own name");
  }

  void read_bodies() {
    for (const ParticleEntry& p : f_.particles) {
      check_body_name(p.name, p.where, p.key);
      const PlacedFrame* in = frame(p.frame, p.frame_where, p.key + ".frame");
      Vector3 local = vector(p.position, allow_configuration, "a position");
      m_.particles.push_back({p.name, mass(p.mass), in ? place_point(*in, local) : local,
                              placement(p.frame, local, rotation(std::nullopt), p.where, p.key + ".position")});
    }
    for (const RigidBodyEntry& b : f_.rigid_bodies) {
      check_body_name(b.name, b.where, b.key);
      const PlacedFrame* in = frame(b.frame, b.frame_where, b.key + ".frame");
      Vector3 local = vector(b.center, allow_configuration, "a position");
      RigidBody body{b.name, mass(b.mass), in ? place_point(*in, local) : local, {}, {3, 3}};
      Rotation relative = rotation(b.rotation);
      body.rotation = in ? compose(in->rotation, relative) : relative;
      body.inertia = inertia(b);
      body.placement = placement(b.frame, local, relative, b.where, b.key + ".center");
      m_.rigid_bodies.push_back(body);
    }
  }

  Rotation rotation(const std::optional<RotationEntry>& given) {
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
      for (const ElementaryRotation& e : r.sequence) r.matrix = r.matrix.mul(elementary_rotation(e.axis, e.angle));
      return r;
    }
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 3; ++j)
        if (i < given->matrix.size() && j < given->matrix[i].size())
          if (auto e = parse(given->matrix[i][j], allow_configuration, "a rotation")) r.matrix(i, j) = *e;
    check_orthogonal(r.matrix, *given);
    return r;
  }

  bool names_matrix(const std::string& text) const {
    auto found = m_.symbols.by_name.find(text);
    return found != m_.symbols.by_name.end() && found->second.kind == SymbolKind::matrix;
  }

  // R^T R = I at the initial state, a cheap guard against a mistyped entry
  void check_orthogonal(const GiNaC::matrix& R, const RotationEntry& where) {
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

  GiNaC::matrix inertia(const RigidBodyEntry& b) {
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
        if (v && *v < 0)
          d_.error(b.principal_inertia[i].where, b.principal_inertia[i].key,
                   fmt::format("the principal moment is {} with the default parameters; it must not be negative", *v));
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

  // A body's second moments J = Σ m r rᵀ = tr(I)/2·E − I are positive semidefinite: in
  // principal axes, every moment is at most the sum of the other two (the triangle
  // inequality, equal for a flat body). Checked with the default parameters.
  void check_realizable(const GiNaC::matrix& I, const RigidBodyEntry& b) {
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
    if (realizable || (!b.principal_inertia.empty() && zero_moments == 2)) return;
    const ExpressionText& at = b.principal_inertia.empty() ? b.inertia[0][0] : b.principal_inertia[0];
    std::string what = b.principal_inertia.empty()
                           ? "its principal moments"
                           : fmt::format("{:g}, {:g}, {:g}", v[0][0], v[1][1], v[2][2]);
    d_.error(at.where, b.key + ".inertia",
             fmt::format("no rigid body has this inertia: {} break the triangle inequality (each principal moment is at "
                         "most the sum of the other two) with the default parameters", what),
             "check the axes and the values; a planar model that only needs Izz can give a thin plate's moments, "
             "[Izz/2, Izz/2, Izz]");
  }

  std::optional<std::size_t> coordinate_index(const NamedExpression& g, const std::string& key) {
    auto found = m_.symbols.by_name.find(g.name);
    if (found != m_.symbols.by_name.end() && found->second.kind == SymbolKind::coordinate) return found->second.index;
    d_.error(g.where, key + "." + g.name, fmt::format("'{}' is not a coordinate", g.name),
             suggest(g.name, m_.symbols.coordinate_names, "coordinates"));
    return std::nullopt;
  }

  void read_energies_and_forces() {
    if (!f_.gravity.empty()) m_.gravity = vector(f_.gravity, allow_parameters | allow_time, "gravity");
    if (f_.kinetic) m_.kinetic = parse(*f_.kinetic, allow_configuration | allow_velocities, "the kinetic energy").value_or(0);
    if (f_.potential) m_.potential = parse(*f_.potential, allow_configuration, "the potential energy").value_or(0);
    if (f_.dissipation) m_.dissipation = parse(*f_.dissipation, allow_configuration | allow_velocities, "the dissipation function").value_or(0);
    for (const ForceEntry& f : f_.forces) {
      switch (f.kind) {
        case ForceEntry::Kind::generalized:
          for (const NamedExpression& g : f.generalized) {
            auto index = coordinate_index(g, f.key + ".generalized");
            auto e = parse(g.expression, allow_everything, "a force");
            if (index && e) m_.generalized_force[*index] += *e;
          }
          break;
        case ForceEntry::Kind::point:
          m_.point_forces.push_back({vector(f.at, allow_configuration, "a position"), vector(f.force, allow_everything, "a force")});
          break;
        case ForceEntry::Kind::torque: read_torque(f); break;
      }
    }
  }

  void read_torque(const ForceEntry& f) {
    Vector3 torque = vector(f.torque, allow_everything, "a torque");
    for (std::size_t i = 0; i < f_.rigid_bodies.size(); ++i)
      if (f_.rigid_bodies[i].name == f.body) {
        m_.torques.push_back({i, torque, f.inertial_frame});
        return;
      }
    std::vector<std::string> names;
    for (const RigidBodyEntry& b : f_.rigid_bodies) names.push_back(b.name);
    d_.error(f.body_where, f.key + ".body", fmt::format("'{}' is not a rigid body", f.body),
             suggest(f.body, names, "rigid bodies"));
  }

  void read_constraints() {
    for (const ConstraintEntry& c : f_.constraints) {
      if (c.kind == ConstraintEntry::Kind::rolls) {
        read_rolling(c);
        continue;
      }
      bool holonomic = c.kind == ConstraintEntry::Kind::holonomic;
      auto e = holonomic ? parse(c.expression, allow_configuration, "a holonomic constraint")
                         : parse(c.expression, allow_configuration | allow_velocities, "a nonholonomic constraint");
      if (!e) continue;
      if (!holonomic) check_linear_in_velocities(*e, c.expression, "a nonholonomic constraint");
      add_constraint(c, holonomic, *e, c.name.empty() ? fmt::format("c{}", m_.constraints.size() + 1) : c.name);
    }
    for (const NamedExpression& p : f_.pseudo_velocities) {
      std::string key = "pseudo_velocities." + p.name;
      if (!is_identifier(p.name) || is_reserved_name(p.name) || m_.symbols.by_name.count(p.name))
        d_.error(p.where, key, fmt::format("'{}' cannot name a pseudo-velocity", p.name),
                 "use a new name that is not a parameter, coordinate, input or function");
      auto e = parse(p.expression, allow_configuration | allow_velocities, "a pseudo-velocity");
      if (!e) continue;
      check_linear_in_velocities(*e, p.expression, "a pseudo-velocity");
      m_.pseudo_velocities.push_back({p.name, *e});
    }
  }

  void add_constraint(const ConstraintEntry& c, bool holonomic, const ex& e, const std::string& name) {
    if (!is_cpp_identifier(name))
      d_.error(c.name_where, c.key + ".name", fmt::format("'{}' is not a C++ identifier", name),
               "a constraint's name becomes part of its multiplier's name, lambda_NAME");
    for (const Constraint& other : m_.constraints)
      if (other.name == name)
        d_.error(c.name_where.line ? c.name_where : c.where, c.key + ".name",
                 fmt::format("two constraints are named '{}'", name), "give each constraint its own name");
    m_.constraints.push_back({holonomic, e, c.key, name});
  }

  // rolls: the contact condition (unless the coordinates keep it already) and two no-slip conditions
  void read_rolling(const ConstraintEntry& c) {
    auto body = std::find_if(m_.rigid_bodies.begin(), m_.rigid_bodies.end(),
                             [&](const RigidBody& b) { return b.name == c.body; });
    if (body == m_.rigid_bodies.end()) {
      std::vector<std::string> names;
      for (const RigidBody& b : m_.rigid_bodies) names.push_back(b.name);
      d_.error(c.body_where, c.key + ".rolls.body", fmt::format("'{}' is not a rigid body", c.body),
               suggest(c.body, names, "rigid bodies"));
      return;
    }
    auto radius = parse(c.radius, allow_parameters, "a radius");
    Vector3 axis = vector(c.axis, allow_parameters, "an axis");
    if (!radius) return;
    if ((axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).is_zero()) {
      d_.error(c.axis[0].where, c.key + ".rolls.axis", "the disk's axis is zero", "give its direction in the body frame, e.g. [0, 1, 0]");
      return;
    }
    // an oblique axis puts √(axis·axis) and √(1 − n_z²) of no known angle into every constraint: the
    // derivation then takes seconds and fails in GiNaC's polynomial arithmetic (found by fuzzing)
    if (std::count_if(axis.begin(), axis.end(), [](const ex& a) { return !a.is_zero(); }) != 1) {
      d_.error(c.axis[0].where, c.key + ".rolls.axis",
               fmt::format("the disk's axis must lie along x, y or z of the body's frame; [{}, {}, {}] does not", c.axis[0].text,
                           c.axis[1].text, c.axis[2].text),
               "turn the body instead: give it (or its frame) the rotation that brings the disk's axis onto one of the "
               "frame's axes, and write that axis, [0, 0, 1] say");
      return;
    }
    std::optional<RollingContact> found = rolling_contact(body->center, body->rotation, axis, *radius, m_.symbols);
    if (!found) {
      d_.error(c.axis[0].where, c.key + ".rolls.axis",
               "the disk lies flat at the initial state (its axis is vertical), so no point of its rim is the lowest",
               "check the axis in the body frame and the rotations of the body and its frames, and start it tilted "
               "away from flat");
      return;
    }
    const RollingContact& contact = *found;
    std::string base = c.name.empty() ? c.body : c.name;
    if (!contact.height.is_zero()) add_constraint(c, true, contact.height, base + "_contact");
    add_constraint(c, false, contact.slip_x, base + "_slip_x");
    add_constraint(c, false, contact.slip_y, base + "_slip_y");
  }

  // a(q,t)·der(q) + b(q,t): every second derivative in the velocities vanishes
  void check_linear_in_velocities(const ex& e, const ExpressionText& text, const char* what) {
    const auto& v = m_.symbols.velocities;
    bool has_velocity = false;
    for (std::size_t i = 0; i < v.size(); ++i) {
      ex di = e.diff(v[i]);
      has_velocity = has_velocity || !di.is_zero();
      for (std::size_t j = i; j < v.size(); ++j)
        if (!di.diff(v[j]).expand().is_zero()) {
          d_.error(text.where, text.key,
                   fmt::format("{} must be linear in the velocities; it is not, in der({}){}", what,
                               m_.symbols.coordinate_names[i],
                               i == j ? "" : " and der(" + m_.symbols.coordinate_names[j] + ")"),
                   "write it as a(q,t)*der(q) + b(q,t)");
          return;
        }
    }
    if (!has_velocity)
      d_.error(text.where, text.key, fmt::format("{} without any velocity", what),
               "a relation between coordinates alone is holonomic: write holonomic = \"...\"");
  }

  void read_outputs() {
    for (const NamedExpression& o : f_.outputs) {
      std::string key = "outputs." + o.name;
      if (!is_cpp_identifier(o.name))
        d_.error(o.where, key, fmt::format("'{}' is not a C++ identifier", o.name), "output names become C++ names");
      auto e = parse(o.expression, allow_everything, "an output");
      if (e) m_.outputs.push_back({o.name, *e});
    }
  }

  void check_complete() {
    SourceLocation top{f_.path, 1, 1};
    if (f_.coordinates.empty() && f_.coordinates_where)
      d_.error(*f_.coordinates_where, "coordinates", "[coordinates] is empty: the model has no coordinates",
               "add one per degree of freedom under it, e.g. phi = { initial = 0.1, rate = 0 }");
    else if (f_.coordinates.empty())
      d_.error(top, "coordinates", "the model has no coordinates",
               "add a [coordinates] section, e.g. phi = { initial = 0.1, rate = 0 }");
    bool has_mass = !f_.particles.empty() || !f_.rigid_bodies.empty() || f_.kinetic;
    if (!f_.coordinates.empty() && !has_mass)
      d_.error(top, "", "nothing in the model has mass or kinetic energy",
               "add [[particles]], [[rigid_bodies]] or [energy] kinetic = \"...\"");
  }

  const ModelFile& f_;
  Diagnostics& d_;
  Model m_;
  std::map<std::string, SourceLocation> declared_at_;
  std::map<std::string, int> body_names_;
  std::map<std::string, PlacedFrame> frames_;
  std::map<std::string, int> frame_index_;  // recursive kinematics: a frame's index in m_.frame_links
};

}  // namespace

Model build_model(const ModelFile& file, Diagnostics& diagnostics) {
  return Builder(file, diagnostics).build();
}

}  // namespace eomgen
