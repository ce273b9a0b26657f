#include "kinematics/recursive_kinematics.hpp"

#include <fmt/format.h>

#include "kinematics/vector3.hpp"
#include "model/recursive_frames.hpp"
#include "symbolic/gradient.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

const char* axis_names = "xyz";

bool is_identity(const GiNaC::matrix& R) { return ex(R).is_equal(GiNaC::unit_matrix(3)); }

// entry (a, b) of Ṙ = R[ω]× and of R̈ = R([α]× + [ω]×[ω]×) at q̈ = 0: row a of R times [·]× e_b
RecursiveKinematics::PoseRates rotation_rates(const FrameMotion& m, unsigned a, unsigned b) {
  Vector3 e{0, 0, 0};
  e[b] = 1;
  Vector3 turning = cross(m.angular_velocity, e);
  Vector3 accelerating = cross(m.angular_bias, e) + cross(m.angular_velocity, turning);
  Vector3 row{m.rotation(a, 0), m.rotation(a, 1), m.rotation(a, 2)};
  return {dot(row, turning), dot(row, accelerating)};
}

}  // namespace

ex RecursiveKinematics::rate_along_motion(const ex& x, bool twice) const {
  const Symbols& s = symbols_;
  GiNaC::exset used;
  collect_symbols(x, used);
  // ṡ of each pose symbol as a symbol σ of its own, so that the second derivative sees it
  std::vector<std::pair<ex, GiNaC::symbol>> rates;
  for (const ex& u : used)
    if (pose_rates_.count(u)) rates.emplace_back(u, GiNaC::symbol());
  auto once = [&](const ex& y, bool second) {
    ex d = y.diff(s.time);
    for (std::size_t j = 0; j < s.coordinates.size(); ++j) d += y.diff(s.coordinates[j]) * s.velocities[j];
    for (const auto& [pose, sigma] : rates) {
      d += y.diff(GiNaC::ex_to<GiNaC::symbol>(pose)) * sigma;
      if (second) d += y.diff(sigma) * pose_rates_.at(pose).bias_acceleration;
    }
    return d;
  };
  ex d = once(x, false);
  if (twice) d = once(d, true);
  GiNaC::exmap rate_of;
  for (const auto& [pose, sigma] : rates) rate_of[sigma] = pose_rates_.at(pose).rate;
  return d.subs(rate_of);
}

ex RecursiveKinematics::named(const std::string& name, const std::string& label, const ex& definition) {
  return named_intermediate(intermediates_, name, label, definition);
}

RecursiveKinematics::RecursiveKinematics(const Model& model, std::vector<Intermediate>& intermediates)
    : model_(model), symbols_(model.symbols), motion_(motion_symbols(model.symbols)), intermediates_(intermediates) {
  std::size_t n = symbols_.coordinates.size();
  inertial_.rotation = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3));
  inertial_.partial_angular_velocity = GiNaC::matrix(3, n);
  inertial_.partial_velocity = GiNaC::matrix(3, n);
  // a frame turned or moved by nothing shares its parent's symbols, which have their partials already
  GiNaC::exset placed;
  for (const Intermediate& i : model.intermediates) placed.insert(i.symbol);
  auto fresh = [&](const ex& x) { return placed.count(x) && !partials_.count(x); };
  for (const FrameLink& link : model.frame_links) {
    const FrameMotion& parent = link.parent < 0 ? inertial_ : frames_[std::size_t(link.parent)];
    FrameMotion m = child(parent, link.relative_rotation, link.sequence, link.relative_origin, link.name);
    m.rotation = link.rotation;
    m.origin = link.origin;
    // ∂R/∂q_j = R [W_j]×, ∂o/∂q_j = V_j
    for (unsigned a = 0; a < 3; ++a) {
      for (unsigned b = 0; b < 3; ++b)
        if (fresh(m.rotation(a, b))) {
          std::vector<ex>& d = partials_[m.rotation(a, b)];
          for (unsigned j = 0; j < n; ++j) {
            Vector3 w = column(m.partial_angular_velocity, j);
            // row a of R times column b of [w]×: [w]× e_b = w × e_b
            Vector3 e{0, 0, 0};
            e[b] = 1;
            Vector3 wb = cross(w, e);
            d.push_back(m.rotation(a, 0) * wb[0] + m.rotation(a, 1) * wb[1] + m.rotation(a, 2) * wb[2]);
          }
          pose_rates_[m.rotation(a, b)] = rotation_rates(m, a, b);
        }
      if (fresh(m.origin[a])) {
        std::vector<ex>& d = partials_[m.origin[a]];
        ex rate = 0;
        for (unsigned j = 0; j < n; ++j) {
          d.push_back(m.partial_velocity(a, j));
          rate += m.partial_velocity(a, j) * symbols_.velocities[j];
        }
        pose_rates_[m.origin[a]] = {rate, m.acceleration_bias[a]};
      }
    }
    frames_.push_back(m);
  }
}

FrameMotion RecursiveKinematics::child(const FrameMotion& p, const GiNaC::matrix& relative,
                                       const std::vector<ElementaryRotation>& sequence, const Vector3& o,
                                       const std::string& name) {
  const Symbols& s = symbols_;
  std::size_t n = s.coordinates.size();
  FrameMotion c;
  c.partial_angular_velocity = GiNaC::matrix(3, n);
  c.partial_velocity = GiNaC::matrix(3, n);
  Vector3 w_rel = relative_angular_velocity(relative, sequence);
  std::vector<ex> coordinates(s.coordinates.begin(), s.coordinates.end());
  std::vector<std::vector<ex>> do_dq;
  for (unsigned a = 0; a < 3; ++a) do_dq.push_back(eomgen::gradient(o[a], coordinates));
  for (unsigned j = 0; j < n; ++j) {
    const std::string& q = s.coordinate_names[j];
    Vector3 wp = column(p.partial_angular_velocity, j);
    Vector3 w = times(relative, wp, true);
    Vector3 v = cross(wp, o) + Vector3{do_dq[0][j], do_dq[1][j], do_dq[2][j]};
    v = times(p.rotation, v);
    for (unsigned a = 0; a < 3; ++a) {
      c.partial_angular_velocity(a, j) =
          named(name, fmt::format("W_{}_{}", q, axis_names[a]), w[a] + w_rel[a].diff(s.velocities[j]));
      c.partial_velocity(a, j) = named(name, fmt::format("V_{}_{}", q, axis_names[a]), p.partial_velocity(a, j) + v[a]);
    }
  }
  Vector3 carried = times(relative, p.angular_velocity, true);
  // the bias accelerations: those of q'' = 0
  Acceleration bias = child_acceleration(p, {p.angular_bias, p.acceleration_bias}, relative, sequence, o, {});
  for (unsigned a = 0; a < 3; ++a) {
    c.angular_velocity[a] = named(name, fmt::format("omega_{}", axis_names[a]), carried[a] + w_rel[a]);
    c.angular_bias[a] = named(name, fmt::format("alpha_{}", axis_names[a]), bias.angular[a]);
    c.acceleration_bias[a] = named(name, fmt::format("acc_{}", axis_names[a]), bias.linear[a]);
  }
  return c;
}

Vector3 RecursiveKinematics::named_vector(std::vector<Intermediate>& out, const std::string& who,
                                          const std::string& label, const Vector3& x) {
  Vector3 v;
  for (unsigned a = 0; a < 3; ++a) v[a] = named_intermediate(out, who, fmt::format("{}_{}", label, axis_names[a]), x[a]);
  return v;
}

Vector3 RecursiveKinematics::relative_angular_velocity(const GiNaC::matrix& relative,
                                                       const std::vector<ElementaryRotation>& sequence) const {
  if (is_identity(relative)) return {0, 0, 0};
  return sequence.empty() ? angular_velocity_of_matrix(relative, symbols_, motion_)
                          : angular_velocity_of_sequence(sequence, symbols_);
}

BodyKinematics RecursiveKinematics::body(const std::string& name, const ex& mass, const Vector3& position,
                                         const FramePlacement& placement, bool rigid) {
  const FrameMotion& frame = placement.frame < 0 ? inertial_ : frames_[std::size_t(placement.frame)];
  FrameMotion m = child(frame, rigid ? placement.relative : GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3)),
                        placement.sequence, placement.local, name + ".cm");
  BodyKinematics b;
  b.name = name;
  b.mass = mass;
  b.position = position;
  b.velocity_jacobian = m.partial_velocity;
  b.bias_acceleration = m.acceleration_bias;
  // v = V q' as intermediates of their own: T = Σ ½ m v·v + ½ ω·I ω is then O(n), not the O(n³) of ½ q'ᵀ M q'
  std::size_t n = symbols_.coordinates.size();
  for (unsigned a = 0; a < 3; ++a) {
    ex v = 0;
    for (unsigned j = 0; j < n; ++j) v += m.partial_velocity(a, j) * symbols_.velocities[j];
    b.velocity[a] = named(name + ".cm", fmt::format("v_{}", axis_names[a]), v);
  }
  if (rigid) {
    b.rotates = true;
    b.angular_velocity_jacobian = m.partial_angular_velocity;
    b.angular_velocity = m.angular_velocity;
    b.bias_angular_acceleration = m.angular_bias;
  }
  return b;
}

std::vector<ex> RecursiveKinematics::gradient(const ex& x) const {
  std::vector<ex> coordinates(symbols_.coordinates.begin(), symbols_.coordinates.end());
  std::vector<ex> d = eomgen::gradient(x, coordinates);
  GiNaC::exset used;
  collect_symbols(x, used);
  for (const ex& s : used) {
    auto found = partials_.find(s);
    if (found == partials_.end()) continue;
    ex partial = x.diff(GiNaC::ex_to<GiNaC::symbol>(s));
    for (std::size_t j = 0; j < d.size(); ++j) d[j] += partial * found->second[j];
  }
  return d;
}

}  // namespace eomgen
