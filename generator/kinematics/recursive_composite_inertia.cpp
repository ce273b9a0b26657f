/// @file The composite-body recursion of recursive kinematics (recursive_kinematics.hpp): the
/// mass matrix in O(n²) code.
///
/// Each frame C's subtree (its bodies and those of the frames below it) has a mass m_C, a first
/// moment h_C = Σ m ρ and an inertia J_C = Σ (I + m(|ρ|² 1 − ρ ρᵀ)) about C's origin, ρ from the
/// origin, all in C's body components. Its own bodies' part is constant; a child K adds
/// m_K, R_rel h_K + m_K d and R_rel J_K R_relᵀ + m_K(|d|² 1 − d dᵀ) + 2(d·h)1 − d hᵀ − h dᵀ
/// (h = R_rel h_K, d = o_rel of K) — Steiner's theorem with the first moment.
/// A coordinate q_j that only frame C's placement contains moves C's subtree rigidly by the twist
/// s_j = (R_relᵀ ∂o_rel/∂q_j, ∂ω_rel/∂q̇_j) at C's origin; a q_k of C or of a frame above it moves
/// it by (R_Cᵀ V_C,k, W_C,k), whose momentum is p = m v + ω × h and angular momentum about the origin
/// L = h × v + J ω. Then M_jk = s_j·(p, L) (the virtual power of the subtree's momentum rates).
#include "kinematics/recursive_kinematics.hpp"
#include "kinematics/vector3.hpp"
#include "model/recursive_frames.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

struct Composite {
  ex mass = 0;
  Vector3 first{0, 0, 0};
  GiNaC::matrix inertia{3, 3};
};

GiNaC::matrix outer(const Vector3& a, const Vector3& b) {
  GiNaC::matrix m(3, 3);
  for (unsigned r = 0; r < 3; ++r)
    for (unsigned c = 0; c < 3; ++c) m(r, c) = a[r] * b[c];
  return m;
}

// m(|d|² 1 − d dᵀ)
GiNaC::matrix steiner(const ex& m, const Vector3& d) {
  GiNaC::matrix s(3, 3);
  ex square = dot(d, d);
  for (unsigned r = 0; r < 3; ++r)
    for (unsigned c = 0; c < 3; ++c) s(r, c) = m * ((r == c ? square : ex(0)) - d[r] * d[c]);
  return s;
}

// whether a placement (its rotation and origin or centre) contains one of `symbols`
bool placed_by(const GiNaC::matrix& R, const Vector3& origin, const std::vector<GiNaC::realsymbol>& symbols) {
  for (const auto& s : symbols)
    if (ex(R).has(s) || origin[0].has(s) || origin[1].has(s) || origin[2].has(s)) return true;
  return false;
}

}  // namespace

std::optional<GiNaC::matrix> RecursiveKinematics::composite_mass_matrix(std::vector<Intermediate>& out) const {
  const Symbols& s = symbols_;
  std::size_t n = s.coordinates.size(), frames = frames_.size();
  std::vector<int> owner(n, -1);
  for (std::size_t i = 0; i < frames; ++i) {
    const FrameLink& link = model_.frame_links[i];
    for (std::size_t j = 0; j < n; ++j)
      if (placed_by(link.relative_rotation, link.relative_origin, {s.coordinates[j]})) {
        if (owner[j] >= 0) return std::nullopt;
        owner[j] = int(i);
      }
  }
  for (int o : owner)
    if (o < 0) return std::nullopt;
  std::vector<Composite> composite(frames);
  auto add_body = [&](const ex& mass, const GiNaC::matrix* inertia, const FramePlacement& at) {
    if (at.frame < 0 || placed_by(at.relative, at.local, s.coordinates)) return false;
    Composite& c = composite[std::size_t(at.frame)];
    c.mass += mass;
    c.first = c.first + scaled(mass, at.local);
    c.inertia = c.inertia.add(steiner(mass, at.local));
    if (inertia) c.inertia = c.inertia.add(at.relative.mul(*inertia).mul(at.relative.transpose()));
    return true;
  };
  for (const Particle& p : model_.particles)
    if (!add_body(p.mass, nullptr, p.placement)) return std::nullopt;
  for (const RigidBody& b : model_.rigid_bodies)
    if (!add_body(b.mass, &b.inertia, b.placement)) return std::nullopt;
  // backward: each subtree's first moment and inertia as intermediates, handed to the parent
  for (std::size_t i = frames; i-- > 0;) {
    const FrameLink& link = model_.frame_links[i];
    Composite& c = composite[i];
    c.first = named_vector(out, link.name, "h", c.first);
    Vector3 diagonal = named_vector(out, link.name, "Jd", {c.inertia(0, 0), c.inertia(1, 1), c.inertia(2, 2)});
    Vector3 off = named_vector(out, link.name, "Jo", {c.inertia(1, 2), c.inertia(0, 2), c.inertia(0, 1)});
    c.inertia = GiNaC::matrix(3, 3, GiNaC::lst{diagonal[0], off[2], off[1], off[2], diagonal[1], off[0], off[1], off[0],
                                               diagonal[2]});
    if (link.parent < 0) continue;
    Composite& p = composite[std::size_t(link.parent)];
    const GiNaC::matrix& R = link.relative_rotation;
    const Vector3& d = link.relative_origin;
    Vector3 h = times(R, c.first);
    GiNaC::matrix moved = R.mul(c.inertia).mul(R.transpose()).add(steiner(c.mass, d));
    ex dh = dot(d, h);
    for (unsigned r = 0; r < 3; ++r) moved(r, r) += 2 * dh;
    moved = moved.sub(outer(d, h)).sub(outer(h, d));
    p.mass += c.mass;
    p.first = p.first + h + scaled(c.mass, d);
    p.inertia = p.inertia.add(moved);
  }
  // the twists of each frame's own coordinates, in its body components
  std::vector<Vector3> shift(n), turn(n);
  for (std::size_t j = 0; j < n; ++j) {
    const FrameLink& link = model_.frame_links[std::size_t(owner[j])];
    Vector3 w = relative_angular_velocity(link.relative_rotation, link.sequence), o = link.relative_origin;
    for (unsigned a = 0; a < 3; ++a) turn[j][a] = w[a].diff(s.velocities[j]), o[a] = o[a].diff(s.coordinates[j]);
    shift[j] = times(link.relative_rotation, o, true);
  }
  auto above_or_same = [&](int ancestor, int frame) {
    for (int f = frame; f >= 0; f = model_.frame_links[std::size_t(f)].parent)
      if (f == ancestor) return true;
    return false;
  };
  GiNaC::matrix M{unsigned(n), unsigned(n)};
  for (std::size_t j = 0; j < n; ++j) {
    std::size_t C = std::size_t(owner[j]);
    const FrameMotion& frame = frames_[C];
    const Composite& c = composite[C];
    for (std::size_t k = 0; k < n; ++k) {
      bool same = owner[k] == owner[j];
      if (!above_or_same(owner[k], owner[j]) || (same && k > j)) continue;
      Vector3 v = times(frame.rotation, column(frame.partial_velocity, unsigned(k)), true);
      Vector3 w = column(frame.partial_angular_velocity, unsigned(k));
      Vector3 momentum = scaled(c.mass, v) + cross(w, c.first), angular = cross(c.first, v) + times(c.inertia, w);
      ex entry = (dot(shift[j], momentum) + dot(turn[j], angular)).expand();
      M(unsigned(j), unsigned(k)) = M(unsigned(k), unsigned(j)) = entry;
    }
  }
  return M;
}

}  // namespace eomgen
