#include "spatial/joint_tree_forward_dynamics.hpp"

#include <fmt/format.h>

#include "kinematics/vector3.hpp"
#include "model/recursive_frames.hpp"
#include "spatial/joint_tree_dynamics.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

const char* const articulated_axes[] = {"x", "y", "z"};

// the articulated inertia (N, F) = (A α + B a, Bᵀ α + C a), A and C symmetric
struct ArticulatedInertia {
  GiNaC::matrix A{3, 3}, B{3, 3}, C{3, 3};
};

GiNaC::matrix cross_matrix(const Vector3& h) {
  return {{0, -h[2], h[1]}, {h[2], 0, -h[0]}, {-h[1], h[0], 0}};
}

GiNaC::matrix sum(const GiNaC::matrix& a, const GiNaC::matrix& b) { return a.add(b); }

class ArticulatedBodies {
 public:
  ArticulatedBodies(const std::vector<TreeLink>& links, const Vector3& gravity, const std::vector<ex>& forces,
                    const std::vector<ex>& joint_inertias)
      : links_(links), gravity_(gravity), forces_(forces), joint_inertias_(joint_inertias), inertia_(links.size()),
        bias_(links.size()) {}

  JointTreeAccelerations solve() {
    velocities();
    for (std::size_t i = 0; i < links_.size(); ++i) add_bodies(i);
    for (std::size_t i = links_.size(); i-- > 0;) articulate(i);
    JointTreeAccelerations out;
    out.accelerations.assign(forces_.size(), 0);
    accelerate(out.accelerations);
    out.intermediates = std::move(out_);
    return out;
  }

 private:
  struct Joint {
    Vector3 e{0, 0, 0}, u{0, 0, 0};  // S
    Vector3 U_N, U_F;
    ex inverse_D, w, rate = 0;
    int velocity = -1;
  };

  // ω and the bias acceleration c of every link, root first
  void velocities() {
    Vector3 zero{0, 0, 0};
    for (std::size_t i = 0; i < links_.size(); ++i) {
      const TreeLink& l = links_[i];
      int p = l.parent;
      Vector3 wp = p < 0 ? zero : omega_[std::size_t(p)];
      Vector3 carried = named(i, "fdwp", times(l.turn, wp, true));
      Joint j;
      if (!l.columns.empty()) {
        const TreeLink::Column& c = l.columns.front();
        j = {c.axis, c.origin_velocity, {}, {}, 0, 0, c.rate, c.velocity};
      }
      omega_.push_back(named(i, "fdw", carried + scaled(j.rate, j.e)));
      Vector3 swing = p < 0 ? zero : times(l.turn, cross(wp, cross(wp, l.offset)), true);
      bias_angular_.push_back(named(i, "fdca", scaled(j.rate, cross(carried, j.e))));
      bias_linear_.push_back(named(i, "fdcl", swing + scaled(2 * j.rate, cross(carried, j.u)) +
                                                  scaled(j.rate * j.rate, cross(j.e, j.u))));
      joints_.push_back(j);
    }
  }

  // a rigid body's inertia about the link's origin and its velocity-product force
  void add_bodies(std::size_t i) {
    ArticulatedInertia& I = inertia_[i];
    const Vector3& w = omega_[i];
    bias_[i] = {Vector3{0, 0, 0}, Vector3{0, 0, 0}};
    for (const TreeLink::Body& b : links_[i].bodies) {
      Vector3 h = scaled(b.mass, b.center);
      GiNaC::matrix J = b.inertia;
      ex cc = dot(b.center, b.center);
      for (unsigned a = 0; a < 3; ++a)
        for (unsigned c = 0; c < 3; ++c) J(a, c) += b.mass * ((a == c ? cc : ex(0)) - b.center[a] * b.center[c]);
      I.A = sum(I.A, J);
      I.B = sum(I.B, cross_matrix(h));
      for (unsigned a = 0; a < 3; ++a) I.C(a, a) += b.mass;
      Vector3 spin = named(i, "fdJw", times(J, w));
      bias_[i].first = bias_[i].first + cross(w, spin);
      bias_[i].second = bias_[i].second + cross(w, cross(w, h));
    }
  }

  // U, D, w of link i's joint, and its articulated inertia and bias force carried to its parent
  void articulate(std::size_t i) {
    const TreeLink& l = links_[i];
    ArticulatedInertia I = named(i, "fdI", inertia_[i]);
    Vector3 pN = named(i, "fdpN", bias_[i].first), pF = named(i, "fdpF", bias_[i].second);
    if (l.parent < 0 && l.columns.empty()) return;  // fixed to the world
    const Vector3 &ca = bias_angular_[i], &cl = bias_linear_[i];
    Vector3 aN = pN + times(I.A, ca) + times(I.B, cl), aF = pF + times(I.B, ca, true) + times(I.C, cl);
    Joint& j = joints_[i];
    if (!l.columns.empty()) {
      j.U_N = named(i, "fdUN", times(I.A, j.e) + times(I.B, j.u));
      j.U_F = named(i, "fdUF", times(I.B, j.e, true) + times(I.C, j.u));
      ex D = dot(j.e, j.U_N) + dot(j.u, j.U_F) + joint_inertias_[std::size_t(j.velocity)];
      j.inverse_D = named_intermediate(out_, l.name, "fdDi", 1 / D.expand());
      ex Q = forces_[std::size_t(j.velocity)];
      j.w = named_intermediate(out_, l.name, "fdu", Q - dot(j.e, pN) - dot(j.u, pF));
      ex k = named_intermediate(out_, l.name, "fdk", (j.w - dot(j.U_N, ca) - dot(j.U_F, cl)) * j.inverse_D);
      aN = aN + scaled(k, j.U_N);
      aF = aF + scaled(k, j.U_F);
      for (unsigned a = 0; a < 3; ++a)
        for (unsigned b = 0; b < 3; ++b) {
          I.A(a, b) -= j.U_N[a] * j.U_N[b] * j.inverse_D;
          I.B(a, b) -= j.U_N[a] * j.U_F[b] * j.inverse_D;
          I.C(a, b) -= j.U_F[a] * j.U_F[b] * j.inverse_D;
        }
      if (joint_inertias_[std::size_t(j.velocity)].is_zero()) without_joint_direction(j, I);
      I = named(i, "fdIa", I);
    }
    if (l.parent < 0) return;
    carry(i, I, named(i, "fdaN", aN), named(i, "fdaF", aF));
  }

  // Iᵃ S = 0 (U − U D/D; with a joint inertia a, U a/(D + a)). Along a joint frame's axis (S = (±e_k, 0) or (0, ±e_k)) the entries it makes zero are
  // set so, where the formula leaves D − D²/D with D a named quantity, which no rule cancels.
  static void without_joint_direction(const Joint& j, ArticulatedInertia& I) {
    auto axis = [](const Vector3& v) {
      int k = -1;
      for (unsigned a = 0; a < 3; ++a) {
        if (v[a].is_zero()) continue;
        if (k >= 0 || !(GiNaC::abs(v[a]) - 1).is_zero()) return -2;
        k = int(a);
      }
      return k;
    };
    int turning = axis(j.e), sliding = axis(j.u);
    if (turning >= 0 && sliding == -1)
      for (unsigned b = 0; b < 3; ++b) {
        I.A(unsigned(turning), b) = I.A(b, unsigned(turning)) = 0;
        I.B(unsigned(turning), b) = 0;
      }
    if (sliding >= 0 && turning == -1)
      for (unsigned b = 0; b < 3; ++b) {
        I.C(unsigned(sliding), b) = I.C(b, unsigned(sliding)) = 0;
        I.B(b, unsigned(sliding)) = 0;
      }
  }

  // Xᵀ I X and Xᵀ p into the parent's coordinates (the header's formulas)
  void carry(std::size_t i, const ArticulatedInertia& I, const Vector3& N, const Vector3& F) {
    const TreeLink& l = links_[i];
    std::size_t p = std::size_t(l.parent);
    const GiNaC::matrix& E = l.turn;
    auto turned = [&](const GiNaC::matrix& X, const std::string& label, bool symmetric) {
      GiNaC::matrix EX = named(i, label + "E", E.mul(X), false);
      return named(i, label + "T", EX.mul(E.transpose()), symmetric);
    };
    GiNaC::matrix A = turned(I.A, "fdA", true), B = turned(I.B, "fdB", false), C = turned(I.C, "fdC", true);
    GiNaC::matrix R = cross_matrix(l.offset), RC = R.mul(C);
    GiNaC::matrix BR = B.mul(R);
    ArticulatedInertia& P = inertia_[p];
    P.A = sum(P.A, A.sub(BR).sub(BR.transpose()).sub(RC.mul(R)));
    P.B = sum(P.B, B.add(RC));
    P.C = sum(P.C, C);
    Vector3 EF = named(i, "fdEF", times(E, F));
    bias_[p].first = bias_[p].first + times(E, N) + cross(l.offset, EF);
    bias_[p].second = bias_[p].second + EF;
  }

  // q̈ and (α, a) of every link, root first
  void accelerate(std::vector<ex>& ddq) {
    Vector3 zero{0, 0, 0}, minus_g = scaled(-1, gravity_);
    std::vector<Vector3> alpha(links_.size()), acc(links_.size());
    for (std::size_t i = 0; i < links_.size(); ++i) {
      const TreeLink& l = links_[i];
      int p = l.parent;
      const Vector3& alpha_p = p < 0 ? zero : alpha[std::size_t(p)];
      Vector3 at_origin = p < 0 ? minus_g : named(i, "fdtx", acc[std::size_t(p)] + cross(alpha_p, l.offset));
      Vector3 al = times(l.turn, alpha_p, true) + bias_angular_[i];
      Vector3 a = times(l.turn, at_origin, true) + bias_linear_[i];
      const Joint& j = joints_[i];
      if (j.velocity >= 0) {
        // named before q̈ is: q̈ and (α, a) each take them
        al = named(i, "fdal0", al);
        a = named(i, "fdac0", a);
        ex qdd = named_intermediate(out_, l.name, "fdqdd", (j.w - dot(j.U_N, al) - dot(j.U_F, a)) * j.inverse_D);
        ddq[std::size_t(j.velocity)] = qdd;
        al = al + scaled(qdd, j.e);
        a = a + scaled(qdd, j.u);
      }
      alpha[i] = named(i, "fdal", al);
      acc[i] = named(i, "fdac", a);
    }
  }

  Vector3 named(std::size_t i, const std::string& label, const Vector3& x) {
    Vector3 v;
    for (unsigned a = 0; a < 3; ++a)
      v[a] = named_intermediate(out_, links_[i].name, fmt::format("{}_{}", label, articulated_axes[a]), x[a]);
    return v;
  }

  GiNaC::matrix named(std::size_t i, const std::string& label, const GiNaC::matrix& X, bool symmetric) {
    GiNaC::matrix out(3, 3);
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned b = symmetric ? a : 0; b < 3; ++b) {
        out(a, b) = named_intermediate(out_, links_[i].name,
                                       fmt::format("{}_{}{}", label, articulated_axes[a], articulated_axes[b]), X(a, b));
        if (symmetric) out(b, a) = out(a, b);
      }
    return out;
  }

  ArticulatedInertia named(std::size_t i, const std::string& label, const ArticulatedInertia& I) {
    return {named(i, label + "A", I.A, true), named(i, label + "B", I.B, false), named(i, label + "C", I.C, true)};
  }

  const std::vector<TreeLink>& links_;
  Vector3 gravity_;
  const std::vector<ex>& forces_;
  const std::vector<ex>& joint_inertias_;
  std::vector<ArticulatedInertia> inertia_;
  std::vector<std::pair<Vector3, Vector3>> bias_;  // p = (N, F) of each link's subtree at α = a = 0
  std::vector<Vector3> omega_, bias_angular_, bias_linear_;
  std::vector<Joint> joints_;
  std::vector<Intermediate> out_;
};

}  // namespace

std::optional<std::string> why_not_articulated_joint_tree(const Model& model) {
  if (model.method != "lagrange2") return fmt::format("its method is '{}', not lagrange2", model.method);
  if (auto why = why_not_a_joint_tree(model)) return "it is not a tree of joints: " + *why;
  const Symbols& s = model.symbols;
  for (std::size_t j = 0; j < s.velocities.size(); ++j)
    for (std::size_t k = j + 1; k < s.velocities.size(); ++k)
      if (!model.kinetic.diff(s.velocities[j]).diff(s.velocities[k]).expand().is_zero())
        return fmt::format("its [energy] kinetic couples the rates of '{}' and '{}'", s.coordinate_names[j], s.coordinate_names[k]);
  std::vector<int> joints(model.symbols.coordinates.size(), 0);
  for (const FrameLink& l : model.frame_links) {
    using Type = FrameLink::Joint::Type;
    if (l.joint->type != Type::revolute && l.joint->type != Type::prismatic && l.joint->type != Type::fixed)
      return fmt::format("frame '{}' has a ball or free joint (the algorithm here takes joints of one velocity)", l.name);
    if (l.joint->coordinate >= 0 && ++joints[std::size_t(l.joint->coordinate)] > 1)
      return fmt::format("coordinate '{}' moves more than one joint",
                         model.symbols.coordinate_names[std::size_t(l.joint->coordinate)]);
  }
  return std::nullopt;
}

// M = L D Lᵀ from the composite-rigid-body algorithm costs per velocity about its depth (the joints
// it carries up to the root, for M's row) and the square of it (the factorization), the
// articulated-body algorithm a fixed amount, larger where oblique axes make every turn of an
// articulated inertia a dense product: so the mean depth admits a tree, and the operations decide.
// tests/benchmarks/forward_dynamics_forms.py on 2026-11-29 (AMD EPYC, g++ -O2, both forms' rhs in one
// process), M = L D Lᵀ against the algorithm: chains of rods on universal joints of 8 hinges (mean
// depth 4.5) 430 ns against 399, of 16 1,916 against 1,264, of 30 7,321 against 3,056; the 7-joint
// arm (4) 436 against 550, the 21-joint branched tree (4.3) 3,176 against 3,836, 12 oblique hinges
// in a row (6.5) 2,090 against 2,160.
bool articulated_body_may_pay(const std::vector<TreeLink>& links) {
  std::vector<int> depth(links.size(), 0);
  long velocities = 0, depths = 0;
  for (std::size_t i = 0; i < links.size(); ++i) {
    if (links[i].columns.size() > 1) return false;
    int above = links[i].parent < 0 ? 0 : depth[std::size_t(links[i].parent)];
    depth[i] = above + int(links[i].columns.size());
    if (links[i].columns.empty()) continue;
    ++velocities;
    depths += depth[i];
  }
  return velocities > 0 && double(depths) >= articulated_mean_depth * double(velocities);
}

JointTreeAccelerations joint_tree_accelerations(const std::vector<TreeLink>& links, const Vector3& gravity,
                                                const std::vector<ex>& generalized_forces,
                                                const std::vector<ex>& joint_inertias) {
  return ArticulatedBodies(links, gravity, generalized_forces, joint_inertias).solve();
}

}  // namespace eomgen
