#include "spatial/joint_tree_forward_dynamics.hpp"

#include <sstream>

#include <fmt/format.h>

#include "kinematics/vector3.hpp"
#include "model/recursive_frames.hpp"
#include "spatial/joint_tree_dynamics.hpp"
#include "spatial/spatial_algebra.hpp"

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

// a joint's column S = (e, u) as a motion
SpatialVector motion_of(const TreeLink::Column& c) { return {c.axis, c.origin_velocity}; }

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
  // for a link's joint columns S = (e, u): U = I S (forces (N, F)), D = Sᵀ U (+ joint inertias) as
  // L Δ Lᵀ, and w = Q − Sᵀ p
  struct Joint {
    std::vector<SpatialVector> U;
    std::vector<std::vector<ex>> L;
    std::vector<ex> inverse_pivots, w;
  };

  // ω and the bias acceleration c of every link, root first (as joint_tree_dynamics.cpp's recursion:
  // a column that keeps the parent's axes, a free joint's position, has no turning × u term)
  void velocities() {
    Vector3 zero{0, 0, 0};
    for (std::size_t i = 0; i < links_.size(); ++i) {
      const TreeLink& l = links_[i];
      int p = l.parent;
      Vector3 wp = p < 0 ? zero : omega_[std::size_t(p)];
      Vector3 carried = named(i, "fdwp", times(l.turn, wp, true));
      Vector3 turning = zero, sliding = zero, kept = zero;
      for (const TreeLink::Column& c : l.columns) {
        turning = turning + scaled(c.rate, c.axis);
        sliding = sliding + scaled(c.rate, c.origin_velocity);
        if (c.turns_with_link) kept = kept + scaled(c.rate, c.origin_velocity);
      }
      omega_.push_back(named(i, "fdw", carried + turning));
      Vector3 swing = p < 0 ? zero : times(l.turn, cross(wp, cross(wp, l.offset)), true);
      bias_angular_.push_back(named(i, "fdca", cross(carried, turning)));
      bias_linear_.push_back(named(i, "fdcl", swing + scaled(2, cross(carried, sliding)) + cross(turning, kept)));
      joints_.emplace_back();
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
      I.A = I.A.add(J);
      I.B = I.B.add(cross_matrix(h));
      for (unsigned a = 0; a < 3; ++a) I.C(a, a) += b.mass;
      Vector3 spin = named(i, "fdJw", times(J, w));
      bias_[i].first = bias_[i].first + cross(w, spin);
      bias_[i].second = bias_[i].second + cross(w, cross(w, h));
    }
  }

  // U, D, w of link i's joint, and its articulated inertia and bias force carried to its parent:
  // pᵃ = p + I c + U D⁻¹ (w − Uᵀ c)
  void articulate(std::size_t i) {
    const TreeLink& l = links_[i];
    ArticulatedInertia I = named(i, "fdI", inertia_[i]);
    Vector3 pN = named(i, "fdpN", bias_[i].first), pF = named(i, "fdpF", bias_[i].second);
    if (l.parent < 0 && l.columns.empty()) return;  // fixed to the world
    const Vector3 &ca = bias_angular_[i], &cl = bias_linear_[i];
    Vector3 aN = pN + times(I.A, ca) + times(I.B, cl), aF = pF + times(I.B, ca, true) + times(I.C, cl);
    const Joint& j = joints_[i];
    if (!l.columns.empty()) {
      project(i, I, pN, pF);
      std::vector<ex> h;
      for (std::size_t c = 0; c < l.columns.size(); ++c) h.push_back(j.w[c] - power({ca, cl}, j.U[c]));
      std::vector<ex> y = solved(i, h, "fdk");
      for (std::size_t c = 0; c < l.columns.size(); ++c) {
        aN = aN + scaled(y[c], j.U[c].top);
        aF = aF + scaled(y[c], j.U[c].bottom);
      }
      if (l.parent < 0) return;  // a root's Iᵃ and pᵃ go nowhere
      I = named(i, "fdIa", without_joint(i, I));
    }
    if (l.parent < 0) return;
    carry(i, I, named(i, "fdaN", aN), named(i, "fdaF", aF));
  }

  // U = I S and w = Q − Sᵀ p for each column of link i's joint, and D's factors
  void project(std::size_t i, const ArticulatedInertia& I, const Vector3& pN, const Vector3& pF) {
    Joint& j = joints_[i];
    const std::vector<TreeLink::Column>& columns = links_[i].columns;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const TreeLink::Column& s = columns[c];
      Vector3 N = times(I.A, s.axis) + times(I.B, s.origin_velocity), F = times(I.B, s.axis, true) + times(I.C, s.origin_velocity);
      j.U.push_back({named(i, fmt::format("fdU{}N", c), N), named(i, fmt::format("fdU{}F", c), F)});
      j.w.push_back(named_intermediate(out_, links_[i].name, fmt::format("fdu{}", c),
                                       forces_[std::size_t(s.velocity)] - power(motion_of(s), {pN, pF})));
    }
    factor(i);
  }

  // Iᵃ = I − U D⁻¹ Uᵀ, with the rows of G = U D⁻¹ solved for
  ArticulatedInertia without_joint(std::size_t i, ArticulatedInertia I) {
    const Joint& j = joints_[i];
    const std::vector<TreeLink::Column>& columns = links_[i].columns;
    std::size_t k = columns.size();
    std::vector<std::vector<ex>> G(6);
    for (unsigned r = 0; r < 6; ++r) {
      std::vector<ex> row(k);
      for (std::size_t c = 0; c < k; ++c) row[c] = j.U[c][r];
      G[r] = solved(i, row, fmt::format("fdG{}", r));
    }
    auto UDU = [&](unsigned r, unsigned s) {
      ex x = 0;
      for (std::size_t c = 0; c < k; ++c) x += G[r][c] * j.U[c][s];
      return x;
    };
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned b = 0; b < 3; ++b) {
        I.A(a, b) -= UDU(a, b);
        I.B(a, b) -= UDU(a, 3 + b);
        I.C(a, b) -= UDU(3 + a, 3 + b);
      }
    if (k == 1 && joint_inertias_[std::size_t(columns[0].velocity)].is_zero()) without_joint_direction(columns[0], I);
    return I;
  }

  // D = L Δ Lᵀ with L unit lower triangular, each entry and 1/Δ named (k ≤ 6: a ball's 3, a free joint's 6)
  void factor(std::size_t i) {
    Joint& j = joints_[i];
    const std::vector<TreeLink::Column>& columns = links_[i].columns;
    std::size_t k = columns.size();
    auto D = [&](std::size_t a, std::size_t b) {
      ex x = power(motion_of(columns[a]), j.U[b]);
      if (a == b) x += joint_inertias_[std::size_t(columns[a].velocity)];
      return x;
    };
    j.L.assign(k, std::vector<ex>(k, 0));
    std::vector<ex> pivot(k);
    for (std::size_t c = 0; c < k; ++c) {
      ex d = D(c, c);
      for (std::size_t m = 0; m < c; ++m) d -= j.L[c][m] * j.L[c][m] * pivot[m];
      if (d.is_zero()) throw SingularJointDirection(singular_direction(i, c));
      pivot[c] = named_intermediate(out_, links_[i].name, fmt::format("fdD{}", c), d);
      j.inverse_pivots.push_back(named_intermediate(out_, links_[i].name, fmt::format("fdDi{}", c), 1 / pivot[c]));
      for (std::size_t r = c + 1; r < k; ++r) {
        ex x = D(r, c);
        for (std::size_t m = 0; m < c; ++m) x -= j.L[r][m] * j.L[c][m] * pivot[m];
        j.L[r][c] = named_intermediate(out_, links_[i].name, fmt::format("fdL{}{}", r, c), x * j.inverse_pivots[c]);
      }
    }
  }

  // which direction of link i's joint moves no inertia, for the error
  std::string singular_direction(std::size_t i, std::size_t c) const {
    const TreeLink::Column& s = links_[i].columns[c];
    auto text = [](const Vector3& v) {
      std::ostringstream out;
      out << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
      return out.str();
    };
    bool turns = !(s.axis[0].is_zero() && s.axis[1].is_zero() && s.axis[2].is_zero());
    return fmt::format("the joint of frame '{}' moves no inertia {} {} (in the frame's axes): what it carries "
                       "meets that motion with no mass or moment of inertia, so that M is singular",
                       links_[i].name, turns ? "turning about" : "sliding along", text(turns ? s.axis : s.origin_velocity));
  }

  // D⁻¹ b by the factors, named `label`0, `label`1, …
  std::vector<ex> solved(std::size_t i, const std::vector<ex>& b, const std::string& label) {
    const Joint& j = joints_[i];
    std::size_t k = b.size();
    std::vector<ex> x(k);
    for (std::size_t r = 0; r < k; ++r) {
      ex z = b[r];
      for (std::size_t m = 0; m < r; ++m) z -= j.L[r][m] * x[m];
      x[r] = k == 1 ? z : named_intermediate(out_, links_[i].name, fmt::format("{}f{}", label, r), z);
    }
    for (std::size_t r = k; r-- > 0;) {
      ex z = x[r] * j.inverse_pivots[r];
      for (std::size_t m = r + 1; m < k; ++m) z -= j.L[m][r] * x[m];
      x[r] = named_intermediate(out_, links_[i].name, fmt::format("{}{}", label, r), z);
    }
    return x;
  }

  // Iᵃ S = 0 (U − U D/D; with a joint inertia a, U a/(D + a)). Along a joint frame's axis (S = (±e_k, 0)
  // or (0, ±e_k)) the entries it makes zero are set so, where the formula leaves D − D²/D with D a
  // named quantity, which no rule cancels.
  static void without_joint_direction(const TreeLink::Column& column, ArticulatedInertia& I) {
    auto axis = [](const Vector3& v) {
      int k = -1;
      for (unsigned a = 0; a < 3; ++a) {
        if (v[a].is_zero()) continue;
        if (k >= 0 || !(GiNaC::abs(v[a]) - 1).is_zero()) return -2;
        k = int(a);
      }
      return k;
    };
    int turning = axis(column.axis), sliding = axis(column.origin_velocity);
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
    P.A = P.A.add(A.sub(BR).sub(BR.transpose()).sub(RC.mul(R)));
    P.B = P.B.add(B.add(RC));
    P.C = P.C.add(C);
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
      if (!l.columns.empty()) {
        // named before q̈ is: q̈ and (α, a) each take them
        al = named(i, "fdal0", al);
        a = named(i, "fdac0", a);
        std::vector<ex> h(l.columns.size());
        for (std::size_t c = 0; c < h.size(); ++c) h[c] = j.w[c] - power({al, a}, j.U[c]);
        std::vector<ex> qdd = solved(i, h, "fdqdd");
        for (std::size_t c = 0; c < h.size(); ++c) {
          ddq[std::size_t(l.columns[c].velocity)] = qdd[c];
          al = al + scaled(qdd[c], l.columns[c].axis);
          a = a + scaled(qdd[c], l.columns[c].origin_velocity);
        }
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

bool articulated_method(const Model& model) {
  bool spherical = false;
  for (const FrameLink& l : model.frame_links) spherical = spherical || (l.joint && l.joint->spherical());
  return model.method == "lagrange2" || (spherical && model.method == "appell");
}

std::optional<std::string> why_not_articulated_joint_tree(const Model& model) {
  if (!articulated_method(model)) return fmt::format("its method is '{}', not lagrange2", model.method);
  if (auto why = why_not_a_joint_tree(model)) return "it is not a tree of joints: " + *why;
  const Symbols& s = model.symbols;
  for (std::size_t j = 0; j < s.velocities.size(); ++j)
    for (std::size_t k = j + 1; k < s.velocities.size(); ++k)
      if (!model.kinetic.diff(s.velocities[j]).diff(s.velocities[k]).expand().is_zero())
        return fmt::format("its [energy] kinetic couples the rates of '{}' and '{}'", s.coordinate_names[j], s.coordinate_names[k]);
  std::vector<int> joints(s.coordinates.size(), 0);
  for (const FrameLink& l : model.frame_links)
    if (l.joint->coordinate >= 0 && ++joints[std::size_t(l.joint->coordinate)] > 1)
      return fmt::format("coordinate '{}' moves more than one joint", s.coordinate_names[std::size_t(l.joint->coordinate)]);
  return std::nullopt;
}

// M = L D Lᵀ from the composite-rigid-body algorithm costs per velocity about its depth (the joints
// it carries up to the root, for M's row) and the square of it (the factorization), the
// articulated-body algorithm a fixed amount, larger where oblique axes make every turn of an
// articulated inertia a dense product: so the mean depth admits a tree, and the operations decide.
// tests/benchmarks/forward_dynamics_forms.py on 2026-11-29 (AMD EPYC, g++ -O2, both forms' rhs in one
// process), M = L D Lᵀ against the algorithm: chains of rods on universal joints of 8 hinges (mean
// depth 4.5) 397 ns against 420, of 16 1,883 against 1,228, of 30 7,448 against 3,006; the 7-joint
// arm (4) 448 against 561, the 21-joint branched tree (4.3) 3,285 against 3,907, the quadruped
// (6.5) 1,624 against 1,843, a free head with 16 hinges (11.5) 3,618 against 2,654, 12 oblique
// hinges in a row (6.5) 2,078 against 2,124.
bool articulated_body_may_pay(const std::vector<TreeLink>& links) {
  // a joint's columns are a dense block of M, each below the one before
  std::vector<long> depth(links.size(), 0);
  long velocities = 0, depths = 0;
  for (std::size_t i = 0; i < links.size(); ++i) {
    long above = links[i].parent < 0 ? 0 : depth[std::size_t(links[i].parent)];
    for (std::size_t c = 0; c < links[i].columns.size(); ++c) depths += above + long(c) + 1;
    velocities += long(links[i].columns.size());
    depth[i] = above + long(links[i].columns.size());
  }
  return velocities > 0 && double(depths) >= articulated_mean_depth * double(velocities);
}

JointTreeAccelerations joint_tree_accelerations(const std::vector<TreeLink>& links, const Vector3& gravity,
                                                const std::vector<ex>& generalized_forces,
                                                const std::vector<ex>& joint_inertias) {
  return ArticulatedBodies(links, gravity, generalized_forces, joint_inertias).solve();
}

}  // namespace eomgen
