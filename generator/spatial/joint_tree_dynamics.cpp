#include "spatial/joint_tree_dynamics.hpp"

#include <array>

#include <fmt/format.h>

#include "kinematics/vector3.hpp"
#include "model/quaternion.hpp"
#include "model/recursive_frames.hpp"
#include "spatial/fixed_links.hpp"
#include "spatial/joint_frames.hpp"
#include "spatial/joint_velocities.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

const char* const axis_names[] = {"x", "y", "z"};

bool moves(const ex& x, const Symbols& s) {
  if (x.has(s.time)) return true;
  for (const GiNaC::realsymbol& q : s.coordinates)
    if (x.has(q)) return true;
  return false;
}

bool moves(const GiNaC::matrix& R, const Symbols& s) {
  for (unsigned a = 0; a < 3; ++a)
    for (unsigned b = 0; b < 3; ++b)
      if (moves(R(a, b), s)) return true;
  return false;
}

GiNaC::matrix identity() { return GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3)); }

// a body in a frame: mass, centre and inertia about the centre, in the frame's coordinates
using Body = TreeLink::Body;

class Tree {
 public:
  Tree(const Model& model, const JointVelocities& velocities, std::vector<Intermediate>& out)
      : model_(model), s_(model.symbols), velocities_(velocities), out_(out) {
    std::size_t links = model.frame_links.size();
    bodies_.resize(links);
    for (const FrameLink& l : model.frame_links) frames_.push_back(joint_frame(*l.joint));
    for (const Particle& p : model.particles) add_body(p.placement.frame, p.mass, p.placement.local, GiNaC::matrix(3, 3));
    for (const RigidBody& r : model.rigid_bodies) {
      const GiNaC::matrix& R = r.placement.relative;
      add_body(r.placement.frame, r.mass, r.placement.local, R.mul(r.inertia).mul(R.transpose()));
    }
    for (std::size_t i = 0; i < links; ++i) place(i);
    fold_fixed_links();
  }

  // ω of every link, its bias accelerations, the backward forces: τ at q̈ = `ddq` (zeros: the bias)
  std::vector<ex> inverse_dynamics(const std::vector<ex>& ddq, const std::string& tag, std::vector<Intermediate>& out) {
    std::size_t links = model_.frame_links.size();
    std::vector<Vector3> alpha(links), acc(links), force(links), moment(links);
    Vector3 zero{0, 0, 0}, minus_g = scaled(-1, model_.gravity);
    for (std::size_t i = 0; i < links; ++i) {
      const Link& l = links_[i];
      int p = parent_[i];
      const Vector3& wp = p < 0 ? zero : omega_[std::size_t(p)];
      const Vector3& alpha_p = p < 0 ? zero : alpha[std::size_t(p)];
      const Vector3& acc_p = p < 0 ? minus_g : acc[std::size_t(p)];
      const Vector3& carried = carried_[i];
      Vector3 turning = zero, sliding = zero, kept = zero, joint_acc = zero, joint_alpha = zero;
      for (const Dof& d : l.dofs) {
        const ex& sdd = ddq[std::size_t(d.velocity)];
        turning = turning + scaled(d.rate, d.e);
        sliding = sliding + scaled(d.rate, d.u);
        if (d.fixed_in_frame) kept = kept + scaled(d.rate, d.u);
        joint_alpha = joint_alpha + scaled(sdd, d.e);
        joint_acc = joint_acc + scaled(sdd, d.u);
      }
      Vector3 al = times(l.E, alpha_p, true) + joint_alpha + cross(carried, turning);
      // the acceleration of the parent's point at the origin, named before it is turned: the
      // products of E with each of its terms multiplied out would cost three times as much
      Vector3 at_origin = p < 0 ? acc_p : named(out, i, "tx" + tag, acc_p + cross(alpha_p, l.r) + cross(wp, cross(wp, l.r)));
      Vector3 a = times(l.E, at_origin, true) + scaled(2, cross(carried, sliding)) + joint_acc + cross(turning, kept);
      alpha[i] = named(out, i, "tal" + tag, al);
      acc[i] = named(out, i, "ta" + tag, a);
    }
    std::vector<ex> tau(velocities_.symbols.size(), 0);
    for (std::size_t i = links; i-- > 0;) {
      Vector3 F = zero, N = zero;
      for (std::size_t k = 0; k < bodies_[i].size(); ++k) {
        const Body& b = bodies_[i][k];
        Vector3 Fb = named(out, i, fmt::format("tB{}F{}", k, tag),
                           scaled(b.mass, acc[i] + cross(alpha[i], b.center) + cross(omega_[i], cross(omega_[i], b.center))));
        F = F + Fb;
        // I ω named first: ω × (I ω) multiplied out costs three times as much
        Vector3 spin = named(out, i, fmt::format("tB{}Iw{}", k, tag), times(b.inertia, omega_[i]));
        N = N + times(b.inertia, alpha[i]) + cross(omega_[i], spin) + cross(b.center, Fb);
      }
      for (std::size_t j = i + 1; j < links; ++j) {
        if (parent_[j] != int(i)) continue;
        Vector3 Fj = named(out, j, "tFp" + tag, times(links_[j].E, force[j]));
        F = F + Fj;
        N = N + times(links_[j].E, moment[j]) + cross(links_[j].r, Fj);
      }
      force[i] = named(out, i, "tF" + tag, F);
      moment[i] = named(out, i, "tN" + tag, N);
      // += : the joints that follow one coordinate each add their share (their e and u carry m)
      for (const Dof& d : links_[i].dofs) tau[std::size_t(d.velocity)] += dot(d.e, moment[i]) + dot(d.u, force[i]);
    }
    return tau;
  }

  // T = Σ ½ m |v_o + ω × c|² + ½ ω·I ω over the bodies, with each frame origin's velocity
  // v_i = E_iᵀ (v_p + ω_p × r_i) + u q̇ (frame coordinates): O(n)
  ex kinetic_energy() {
    std::size_t links = model_.frame_links.size();
    std::vector<Vector3> velocity(links);
    Vector3 zero{0, 0, 0};
    ex T = 0;
    for (std::size_t i = 0; i < links; ++i) {
      const Link& l = links_[i];
      int p = parent_[i];
      Vector3 carried = p < 0 ? zero : times(l.E, velocity[std::size_t(p)] + cross(omega_[std::size_t(p)], l.r), true);
      for (const Dof& d : l.dofs) carried = carried + scaled(d.rate, d.u);
      velocity[i] = named(out_, i, "tv", carried);
      for (const Body& b : bodies_[i]) {
        Vector3 v = velocity[i] + cross(omega_[i], b.center);
        T += b.mass * dot(v, v) / 2 + dot(omega_[i], times(b.inertia, omega_[i])) / 2;
      }
    }
    return T;
  }

  // the composite-rigid-body algorithm
  GiNaC::matrix mass_matrix() {
    std::size_t links = model_.frame_links.size(), n = velocities_.symbols.size();
    std::vector<ex> mass(links);
    std::vector<Vector3> first(links);
    std::vector<GiNaC::matrix> inertia(links, GiNaC::matrix(3, 3));
    for (std::size_t i = links; i-- > 0;) {
      ex m = 0;
      Vector3 h{0, 0, 0};
      GiNaC::matrix J(3, 3);
      for (const Body& b : bodies_[i]) {
        m += b.mass;
        h = h + scaled(b.mass, b.center);
        J = J.add(b.inertia).add(shifted(b.mass, b.center, {0, 0, 0}));
      }
      for (std::size_t j = i + 1; j < links; ++j) {
        if (parent_[j] != int(i)) continue;
        const Link& c = links_[j];
        Vector3 hj = named(out_, j, "tEh", times(c.E, first[j]));
        m += mass[j];
        h = h + scaled(mass[j], c.r) + hj;
        GiNaC::matrix EJ = c.E.mul(inertia[j]), turned(3, 3);
        for (unsigned a = 0; a < 3; ++a)
          for (unsigned b = 0; b < 3; ++b)
            EJ(a, b) = intermediate(out_, fmt::format("{}.tEJ_{}{}", name(j), axis_names[a], axis_names[b]),
                                    fmt::format("k_{}_tEJ{}{}", name(j), axis_names[a], axis_names[b]), EJ(a, b).expand());
        for (unsigned a = 0; a < 3; ++a)
          for (unsigned b = 0; b < 3; ++b)
            for (unsigned k = 0; k < 3; ++k) turned(a, b) += EJ(a, k) * c.E(b, k);
        J = J.add(turned).add(shifted(mass[j], c.r, hj));
      }
      mass[i] = named_intermediate(out_, name(i), "tm", m);
      first[i] = named(out_, i, "th", h);
      for (unsigned a = 0; a < 3; ++a)
        for (unsigned b = a; b < 3; ++b) {
          inertia[i](a, b) = intermediate(out_, fmt::format("{}.tJ_{}{}", name(i), axis_names[a], axis_names[b]),
                                          fmt::format("k_{}_tJ{}{}", name(i), axis_names[a], axis_names[b]), J(a, b).expand());
          inertia[i](b, a) = inertia[i](a, b);
        }
    }
    GiNaC::matrix M{unsigned(n), unsigned(n)};
    // the momenta are named after the velocity, and after the link too where one velocity drives
    // several links (joints that follow a coordinate), whose momenta are carried up separately
    std::vector<int> driven(n, 0);
    for (const Link& l : links_)
      for (const Dof& d : l.dofs) ++driven[std::size_t(d.velocity)];
    for (std::size_t i = 0; i < links; ++i)
      for (const Dof& d : links_[i].dofs) {
        unsigned k = unsigned(d.velocity);
        std::string tag = driven[k] > 1 ? fmt::format("{}_{}", k, name(i)) : std::to_string(k);
        Vector3 p = named(out_, i, "tp" + tag, scaled(mass[i], d.u) + cross(d.e, first[i]));
        Vector3 L = named(out_, i, "tL" + tag, times(inertia[i], d.e) + cross(first[i], d.u));
        for (const Dof& other : links_[i].dofs)
          if (other.velocity <= d.velocity) {
            unsigned j = unsigned(other.velocity);
            add_symmetric(M, j, k, (dot(other.e, L) + dot(other.u, p)).expand(), false);
          }
        for (int at = int(i), up = parent_[i]; up >= 0; at = up, up = parent_[std::size_t(up)]) {
          const Link& c = links_[std::size_t(at)];
          p = named(out_, std::size_t(up), "tp" + tag, times(c.E, p));
          L = named(out_, std::size_t(up), "tL" + tag, times(c.E, L) + cross(c.r, p));
          for (const Dof& a : links_[std::size_t(up)].dofs)
            add_symmetric(M, unsigned(a.velocity), k, (dot(a.e, L) + dot(a.u, p)).expand(), true);
        }
      }
    return M;
  }

  // M_jk and M_kj of a pair of joints: their sum over every pair of links whose joints the two
  // velocities drive (more than one when a joint follows another's coordinate); a pair of two
  // links that one velocity drives gives M_kk twice, once for each order
  static void add_symmetric(GiNaC::matrix& M, unsigned j, unsigned k, const ex& x, bool two_links) {
    if (j == k) {
      M(k, k) += two_links ? 2 * x : x;
      return;
    }
    M(j, k) += x;
    M(k, j) += x;
  }

  // the links as the closed-form derivatives take them: each joint's velocities, and the twist of
  // each of its coordinates (a quaternion component's through Y = ∂s/∂q' of the joint's ω); a
  // folded link that nothing hangs from any more is left out (fold_fixed_links)
  std::vector<TreeLink> layout() const {
    std::vector<bool> carries(links_.size(), false);
    for (int p : parent_)
      if (p >= 0) carries[std::size_t(p)] = true;
    std::vector<int> index(links_.size(), -1);
    std::vector<TreeLink> out;
    for (std::size_t i = 0; i < links_.size(); ++i) {
      if (folded(i) && !carries[i]) continue;
      const FrameLink::Joint& j = *model_.frame_links[i].joint;
      index[i] = int(out.size());
      TreeLink t;
      t.name = name(i);
      t.parent = parent_[i] < 0 ? -1 : index[std::size_t(parent_[i])];
      t.turn = links_[i].E;
      t.offset = links_[i].r;
      for (const Dof& d : links_[i].dofs) t.columns.push_back({d.velocity, d.rate, d.e, d.u, d.fixed_in_frame});
      if (j.coordinate >= 0) t.directions.push_back({j.coordinate, {{0, 1}}});
      if (j.type == FrameLink::Joint::Type::free)
        for (std::size_t k = 0; k < 3; ++k) t.directions.push_back({j.position[k], {{k, 1}}});
      if (j.spherical()) {
        std::size_t first_turning = j.type == FrameLink::Joint::Type::free ? 3 : 0;
        for (int c : j.quaternion) {
          TreeLink::Direction q{c, {}};
          for (std::size_t k = 0; k < 3; ++k) {
            const TreeLink::Column& turning = t.columns[first_turning + k];
            ex y = velocities_.definitions[std::size_t(turning.velocity)].expression.diff(s_.velocities[std::size_t(c)]);
            if (!y.is_zero()) q.weights.push_back({first_turning + k, y});
          }
          t.directions.push_back(q);
        }
      }
      t.bodies = bodies_[i];
      t.rest_pose = links_[i].rest_pose;
      out.push_back(t);
    }
    return out;
  }

 private:
  // one velocity of a joint: the link's ω and its origin's velocity per unit of it; `fixed_in_frame`
  // when u turns with the link (a revolute, prismatic or ball joint's), not when it keeps the
  // parent's axes (a free joint's position)
  struct Dof {
    int velocity = -1;
    ex rate;
    Vector3 e{0, 0, 0}, u{0, 0, 0};
    bool fixed_in_frame = true;
  };
  struct Link {
    std::vector<Dof> dofs;
    GiNaC::matrix E{3, 3};           // the link's components to its parent's
    Vector3 r{0, 0, 0};              // its origin in its parent's coordinates
    std::optional<std::pair<GiNaC::matrix, Vector3>> rest_pose;  // a root hinge's or slide's E and r at q = 0
  };

  // A link without a joint moves rigidly with its parent: its bodies go to the parent, in the
  // parent's coordinates (c' = E c + r, J' = E J Eᵀ), and place() has hung the links below it from
  // the parent by the composed turn and offset, so that the recursions do the parent's work once
  // for them, and the link's own quantities, unused, are never written (a URDF's sensor and tool
  // frames: 826 of the 4,572 operations of TIAGo's M and f; ANYmal C's fixed links between its
  // joints). A link fixed to the world stays: it does not move, and costs nothing.
  void fold_fixed_links() {
    for (std::size_t i = links_.size(); i-- > 0;) {
      if (!folded(i)) continue;
      for (const Body& b : bodies_[i]) bodies_[std::size_t(parent_[i])].push_back(body_in(b, links_[i].E, links_[i].r));
      bodies_[i].clear();
    }
    for (std::vector<Body>& on_link : bodies_) on_link = as_one_body(on_link);
  }

  // a link without a joint below a link that moves: place() hangs its links from that one
  bool folded(std::size_t i) const { return links_[i].dofs.empty() && parent_[i] >= 0; }

  // a body in frame i, moved to the joint frame's coordinates: c' = Cᵀ(c − o), J' = Cᵀ J C
  void add_body(int frame, const ex& mass, const Vector3& center, const GiNaC::matrix& inertia) {
    const JointFrame& f = frames_[std::size_t(frame)];
    Body b{mass, times(f.axes, center - f.origin, true), f.axes.transpose().mul(inertia).mul(f.axes)};
    if (f.floating) {
      ex size = GiNaC::abs(center[0]) + GiNaC::abs(center[1]) + GiNaC::abs(center[2]) + GiNaC::abs(f.origin[0]) +
                GiNaC::abs(f.origin[1]) + GiNaC::abs(f.origin[2]);
      ex spread = 0;
      for (unsigned a = 0; a < 3; ++a) spread += GiNaC::abs(inertia(a, a));
      for (unsigned a = 0; a < 3; ++a) {
        b.center[a] = rounded_to(without_rounding_residue(b.center[a].expand(), size), size);
        for (unsigned c = 0; c < 3; ++c)
          b.inertia(a, c) = rounded_to(without_rounding_residue(b.inertia(a, c).expand(), spread), spread);
      }
    }
    bodies_[std::size_t(frame)].push_back(b);
  }

  // E, r and ω of link i in the joint frames' coordinates (spatial/joint_frames.hpp): with C_p, o_p
  // the parent's joint frame and C, o the link's, E' = C_pᵀ E C and r' = C_pᵀ(r + E o − o_p), where
  // E = R_p R(q) turns the link's frame and r places its origin; as intermediates
  void place(std::size_t i) {
    const FrameLink::Joint& j = *model_.frame_links[i].joint;
    using Type = FrameLink::Joint::Type;
    const JointFrame& own = frames_[i];
    int p = model_.frame_links[i].parent;
    JointFrame world;
    world.axes = identity();
    const JointFrame& above = p < 0 ? world : frames_[std::size_t(p)];
    bool floating = own.floating || above.floating;
    Link l;
    GiNaC::matrix R = identity();
    Vector3 r = j.placement_origin, zero{0, 0, 0};
    auto velocity_of = [&](int coordinate) { return velocities_.of_coordinate[std::size_t(coordinate)]; };
    // a joint that follows its coordinate by m·q + c moves m times as fast: its e and u carry m
    ex q = joint_angle(j);
    if (j.type == Type::prismatic) {
      l.dofs.push_back({velocity_of(j.coordinate), s_.velocities[std::size_t(j.coordinate)], zero,
                        scaled(j.multiplier, joint_direction(j, own))});
      r = r + times(j.placement, scaled(q, j.axis));
    } else if (j.type == Type::revolute) {
      Vector3 e = joint_direction(j, own);
      l.dofs.push_back({velocity_of(j.coordinate), s_.velocities[std::size_t(j.coordinate)], scaled(j.multiplier, e),
                        scaled(j.multiplier, cross(times(own.axes, j.anchor - own.origin, true), e))});
      ElementaryRotation about_axis{ElementaryRotation::about_direction, q};
      about_axis.direction = j.axis;
      R = rotation_matrix(about_axis);
      r = r + times(j.placement, j.anchor - times(R, j.anchor));
    } else if (j.spherical()) {
      R = joint_rotation(i, j);
      if (j.type == Type::free) {
        Vector3 x;
        for (unsigned k = 0; k < 3; ++k) x[k] = s_.coordinates[std::size_t(j.position[k])];
        r = r + times(j.placement, x);
      } else {
        r = r + times(j.placement, j.anchor - times(R, j.anchor));
      }
    }
    GiNaC::matrix E = turn(j, R, above, own);
    Vector3 origin = r + times(j.placement.mul(R), own.origin) - above.origin;
    for (ex& x : origin) x = x.expand();
    Vector3 offset = times(above.axes, origin, true);
    if (floating) {
      ex size = GiNaC::abs(origin[0]) + GiNaC::abs(origin[1]) + GiNaC::abs(origin[2]);
      for (ex& x : offset) x = rounded_to(without_rounding_residue(without_small_terms(x.expand()), size), size);
    }
    // below a folded link, hung from its parent: E_p E and r_p + E_p r (a ball or free joint keeps
    // its link, whose axes its position and its turn are written in)
    parent_.push_back(p);
    if (p >= 0 && folded(std::size_t(p)) && !j.spherical()) {
      const Link& fixed = links_[std::size_t(p)];
      E = fixed.E.mul(E);
      offset = fixed.r + times(fixed.E, offset);
      parent_[i] = parent_[std::size_t(p)];
    }
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned b = 0; b < 3; ++b)
        l.E(a, b) = intermediate(out_, fmt::format("{}.tE_{}{}", name(i), axis_names[a], axis_names[b]),
                                 fmt::format("k_{}_tE{}{}", name(i), axis_names[a], axis_names[b]), E(a, b).expand());
    if (j.spherical()) add_spherical_dofs(j, above, own, l);
    for (ex& x : offset) x = x.expand();
    l.r = named(out_, i, "tr", offset);
    if (p < 0 && !j.spherical() && j.coordinate >= 0) {
      ex at_zero = s_.coordinates[std::size_t(j.coordinate)] == 0;
      GiNaC::matrix E0(3, 3);
      for (unsigned a = 0; a < 3; ++a)
        for (unsigned b = 0; b < 3; ++b) E0(a, b) = E(a, b).subs(at_zero).expand();
      Vector3 r0;
      for (unsigned k = 0; k < 3; ++k) r0[k] = offset[k].subs(at_zero).expand();
      l.rest_pose = {E0, r0};
    }
    Vector3 wp = parent_[i] < 0 ? zero : omega_[std::size_t(parent_[i])];
    carried_.push_back(named(out_, i, "twp", times(l.E, wp, true)));
    Vector3 w = carried_.back();
    for (const Dof& d : l.dofs) w = w + scaled(d.rate, d.e);
    omega_.push_back(named(out_, i, "tw", w));
    links_.push_back(l);
  }

  // a revolute or prismatic joint's axis in its joint frame: z, when the frame was built on it
  static Vector3 joint_direction(const FrameLink::Joint& j, const JointFrame& own) {
    if (own.floating) return {0, 0, 1};
    Vector3 e = times(own.axes, j.axis, true);
    for (ex& x : e) x = x.expand();
    return e;
  }

  // E' = C_pᵀ R_p R(q) C; for a joint about z of its joint frame, K·rot_z(q) with the constant
  // K = C_pᵀ R_p C formed once, so that no rounding residue multiplies cos q or sin q
  GiNaC::matrix turn(const FrameLink::Joint& j, const GiNaC::matrix& R, const JointFrame& above,
                     const JointFrame& own) const {
    Vector3 e = joint_direction(j, own);
    bool about_z = j.type == FrameLink::Joint::Type::revolute && e[0].is_zero() && e[1].is_zero() && (e[2] - 1).is_zero();
    GiNaC::matrix K = above.axes.transpose().mul(j.placement).mul(about_z ? own.axes : R.mul(own.axes));
    bool approximate = above.floating || own.floating;
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned b = 0; b < 3; ++b) {
        K(a, b) = K(a, b).expand();
        K(a, b) = rotation_entry(approximate ? without_small_terms(K(a, b)) : K(a, b), approximate);
      }
    if (!about_z) return K;
    ex q = joint_angle(j);
    GiNaC::matrix rot_z = {{GiNaC::cos(q), -GiNaC::sin(q), 0}, {GiNaC::sin(q), GiNaC::cos(q), 0}, {0, 0, 1}};
    return K.mul(rot_z);
  }

  // the angle or travel of a revolute or prismatic joint: its coordinate, or m·q + c for a follower
  ex joint_angle(const FrameLink::Joint& j) const {
    return j.coordinate < 0 ? ex(0) : j.multiplier * s_.coordinates[std::size_t(j.coordinate)] + j.offset;
  }

  // R(q) of a ball or free joint's quaternion (model/quaternion.hpp), with 1/|q|² named
  GiNaC::matrix joint_rotation(std::size_t i, const FrameLink::Joint& j) {
    std::array<ex, 4> q;
    for (std::size_t k = 0; k < 4; ++k) q[k] = s_.coordinates[std::size_t(j.quaternion[k])];
    ex n = intermediate(out_, fmt::format("{}.tqn", name(i)), fmt::format("k_{}_tqn", name(i)),
                        1 / (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]));
    return quaternion_rotation(q, n);
  }

  // a free joint's position: u_k = E'ᵀ C_pᵀ R_p e_k, the placement's axis k in the link's coordinates;
  // then ω about the link's axes, through the anchor (a ball's) or the origin (a free joint's)
  void add_spherical_dofs(const FrameLink::Joint& j, const JointFrame& above, const JointFrame& own, Link& l) const {
    Vector3 zero{0, 0, 0};
    GiNaC::matrix axes = above.axes.transpose().mul(j.placement);
    if (j.type == FrameLink::Joint::Type::free)
      for (unsigned k = 0; k < 3; ++k) {
        Vector3 u;
        for (unsigned a = 0; a < 3; ++a) {
          u[a] = 0;
          for (unsigned b = 0; b < 3; ++b) u[a] += l.E(b, a) * axes(b, k);
        }
        l.dofs.push_back({velocities_.of_coordinate[std::size_t(j.position[k])], s_.velocities[std::size_t(j.position[k])], zero, u, false});
      }
    int first = -1;
    for (std::size_t v = 0; v < velocities_.symbols.size() && first < 0; ++v)
      if (velocities_.symbols[v] == j.angular_velocity[0]) first = int(v);
    for (unsigned k = 0; k < 3; ++k) {
      Vector3 e{0, 0, 0};
      e[k] = 1;
      l.dofs.push_back({first + int(k), j.angular_velocity[k], e, cross(j.anchor - own.origin, e)});
    }
  }

  // the inertia about a point at −d from the centre (J_O = J_c + m(|d|²I − d dᵀ)), and with s, the
  // cross terms of a subtree whose first moment about its own origin is s: 2(d·s)I − s dᵀ − d sᵀ
  static GiNaC::matrix shifted(const ex& m, const Vector3& d, const Vector3& s) {
    GiNaC::matrix J(3, 3);
    ex dd = dot(d, d), ds = dot(d, s);
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned b = 0; b < 3; ++b)
        J(a, b) = m * ((a == b ? dd : ex(0)) - d[a] * d[b]) + (a == b ? 2 * ds : ex(0)) - s[a] * d[b] - d[a] * s[b];
    return J;
  }

  // frame names are identifiers: the same in the printed names and in C++
  std::string name(std::size_t i) const { return model_.frame_links[i].name; }

  Vector3 named(std::vector<Intermediate>& out, std::size_t i, const std::string& label, const Vector3& x) const {
    Vector3 v;
    for (unsigned a = 0; a < 3; ++a) v[a] = named_intermediate(out, name(i), fmt::format("{}_{}", label, axis_names[a]), x[a]);
    return v;
  }

  const Model& model_;
  const Symbols& s_;
  const JointVelocities& velocities_;
  std::vector<Intermediate>& out_;
  std::vector<std::vector<Body>> bodies_;
  std::vector<JointFrame> frames_;
  std::vector<Link> links_;
  std::vector<Vector3> omega_;
  std::vector<Vector3> carried_;  // the parent's ω in the link's coordinates
  std::vector<int> parent_;       // the link each hangs from, past folded ones (fold_fixed_links)
};

// the velocities that drive each link's joint: a hinge's or slide's coordinate's (that of a
// joint that follows it too), a free joint's position's and a ball's or free joint's angular ones
std::vector<std::vector<int>> driving_velocities(const Model& model, const JointVelocities& v) {
  std::vector<std::vector<int>> driving(model.frame_links.size());
  for (std::size_t i = 0; i < model.frame_links.size(); ++i) {
    const FrameLink& l = model.frame_links[i];
    if (l.joint->coordinate >= 0) driving[i].push_back(v.of_coordinate[std::size_t(l.joint->coordinate)]);
    if (l.joint->type == FrameLink::Joint::Type::free)
      for (int k : l.joint->position) driving[i].push_back(v.of_coordinate[std::size_t(k)]);
    for (std::size_t k = 0; k < l.joint->angular_velocity.size(); ++k)
      for (std::size_t s = 0; s < v.symbols.size(); ++s)
        if (v.symbols[s] == l.joint->angular_velocity[k]) driving[i].push_back(int(s));
  }
  return driving;
}

// For each velocity k, the one the factorization of M from the leaves (emit/cpp_ldlt.hpp) treats
// as above it: M_jk can be nonzero only when a joint that j drives carries one that k drives (or
// is it); eliminating k, from the last, couples the others of row k among themselves. So the
// nearest of them, p, is k's parent, and the rest join row p; then every nonzero left of k's
// diagonal, filled in or not, is on k's chain of parents. For a tree numbered parents first whose
// every velocity drives one joint this is the nearest velocity above, with no fill-in; joints that
// follow another's coordinate (URDF's mimic) and numberings that are not parents first fill in
// only what they couple.
std::vector<int> velocity_parents(const Model& model, const JointVelocities& v) {
  std::size_t n = v.symbols.size();
  std::vector<std::vector<int>> driving = driving_velocities(model, v);
  std::vector<std::vector<bool>> coupled(n, std::vector<bool>(n, false));
  for (std::size_t b = 0; b < driving.size(); ++b)
    for (int a = int(b); a >= 0; a = model.frame_links[std::size_t(a)].parent)
      for (int j : driving[std::size_t(a)])
        for (int k : driving[b]) coupled[std::size_t(j)][std::size_t(k)] = coupled[std::size_t(k)][std::size_t(j)] = true;
  std::vector<int> parents(n, -1);
  for (std::size_t k = n; k-- > 0;) {
    int p = -1;
    for (std::size_t j = 0; j < k; ++j)
      if (coupled[k][j]) p = int(j);
    parents[k] = p;
    for (std::size_t j = 0; p >= 0 && j < std::size_t(p); ++j)
      if (coupled[k][j]) coupled[std::size_t(p)][j] = coupled[j][std::size_t(p)] = true;
  }
  return parents;
}

}  // namespace

std::optional<std::string> why_not_a_joint_tree(const Model& model) {
  const Symbols& s = model.symbols;
  if (!model.recursive_kinematics || model.frame_links.empty()) return "it has no frames with recursive kinematics";
  std::vector<int> joints(s.coordinates.size(), 0);
  for (const FrameLink& l : model.frame_links) {
    if (!l.joint) return fmt::format("frame '{}' is not placed by constants and moved by one joint", l.name);
    if (l.joint->coordinate >= 0) ++joints[std::size_t(l.joint->coordinate)];
    for (int k : l.joint->quaternion)
      if (k >= 0) ++joints[std::size_t(k)];
    for (int k : l.joint->position)
      if (k >= 0) ++joints[std::size_t(k)];
  }
  // a coordinate may move several revolute or prismatic joints (those that follow it, URDF's mimic)
  for (std::size_t k = 0; k < joints.size(); ++k)
    if (joints[k] == 0) return fmt::format("coordinate '{}' moves no joint", s.coordinate_names[k]);
  for (const FrameLink& l : model.frame_links)
    for (int k : l.joint->quaternion)
      if (k >= 0 && joints[std::size_t(k)] != 1)
        return fmt::format("coordinate '{}' of a quaternion moves {} joints, not one", s.coordinate_names[std::size_t(k)],
                           joints[std::size_t(k)]);
  for (const FrameLink& l : model.frame_links)
    for (int k : l.joint->position)
      if (k >= 0 && joints[std::size_t(k)] != 1)
        return fmt::format("coordinate '{}' of a free joint's position moves {} joints, not one",
                           s.coordinate_names[std::size_t(k)], joints[std::size_t(k)]);
  for (const Particle& p : model.particles)
    if (p.placement.frame < 0 || moves(p.placement.local[0] + p.placement.local[1] + p.placement.local[2], s))
      return fmt::format("particle '{}' does not sit still in a frame", p.name);
  for (const RigidBody& r : model.rigid_bodies)
    if (r.placement.frame < 0 || moves(r.placement.local[0] + r.placement.local[1] + r.placement.local[2], s) ||
        moves(r.placement.relative, s))
      return fmt::format("rigid body '{}' does not sit still in a frame", r.name);
  if (moves(model.gravity[0] + model.gravity[1] + model.gravity[2], s)) return "gravity changes with q or t";
  return std::nullopt;
}

JointTreeDynamics joint_tree_dynamics(const Model& model, const JointVelocities& velocities,
                                      const std::vector<GiNaC::symbol>& accelerations,
                                      std::vector<Intermediate>& intermediates,
                                      std::vector<Intermediate>& acceleration_intermediates) {
  Tree tree(model, velocities, intermediates);
  JointTreeDynamics d;
  std::vector<ex> none(velocities.symbols.size(), 0), ddq(accelerations.begin(), accelerations.end());
  d.bias_forces = tree.inverse_dynamics(none, "0", intermediates);
  for (ex& f : d.bias_forces) f = -f;
  d.inverse_dynamics = tree.inverse_dynamics(ddq, "", acceleration_intermediates);
  d.links = tree.layout();
  d.gradient = joint_tree_gradient(d.links, model.gravity, ddq, velocities.symbols.size(),
                                   model.symbols.coordinates.size(), acceleration_intermediates);
  d.mass_matrix = tree.mass_matrix();
  d.kinetic_energy = tree.kinetic_energy();
  d.velocity_parents = velocity_parents(model, velocities);
  return d;
}

}  // namespace eomgen
