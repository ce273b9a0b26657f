#include "spatial/joint_tree_derivatives.hpp"

#include <algorithm>
#include <optional>

#include <fmt/format.h>

#include "kinematics/vector3.hpp"
#include "model/recursive_frames.hpp"
#include "spatial/gradient_frame.hpp"
#include "spatial/gradient_form.hpp"
#include "spatial/spatial_algebra.hpp"
#include "symbolic/expression_cost.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

class Gradient {
 public:
  // reference: the link whose axes, about its root's origin, the quantities are written in (none:
  // the world's)
  Gradient(const std::vector<TreeLink>& links, std::vector<Intermediate>& out, std::optional<std::size_t> reference = std::nullopt)
      : links_(links), out_(out), reference_(reference) {
    std::size_t n = links.size();
    R_.resize(n, GiNaC::matrix(3, 3));
    origin_.resize(n);
    S_.resize(n), v_.resize(n), a_.resize(n), still_v_.resize(n), still_a_.resize(n), turning_v_.resize(n);
    a0_.resize(n), driven_a_.resize(n);
    inertia_.resize(n), force_.resize(n), momentum_.resize(n), force0_.resize(n), driven_force_.resize(n);
    D_.resize(n, GiNaC::matrix(6, 6));
    hinge_dS_.resize(n);
  }

  // world poses, twists, accelerations and the links' own inertias, forces and D, parents first
  void forward(const Vector3& gravity, const std::vector<ex>& ddq) {
    find_cyclic_roots(gravity);
    Vector3 g = reference_ ? place_reference(*reference_, gravity) : gravity;
    for (std::size_t i = 0; i < links_.size(); ++i) {
      place(i, g, ddq);
      own_inertia(i);
    }
  }

  // Every entry is a product of a motion and a force (S·F) or an inertia's quadratic form, the same
  // in any frame that is at rest at this instant (a change of basis, which these pairings do not
  // see; tests/generator/spatial/gradient_frames_test.cpp): the frame that coincides with link
  // `ref` now, moved to the origin of the root above it, serves as well as the world's. There the
  // links near `ref` turn by one or two joints only, whose rotations and twists fold, and the root's
  // origin is 0. The links from `ref` up to the root are placed from it (R_λ = R E^T, o_λ = o −
  // R_λ r); gravity, in these axes, is returned.
  Vector3 place_reference(std::size_t ref, const Vector3& gravity) {
    GiNaC::matrix R = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3));
    Vector3 o{0, 0, 0};
    std::vector<std::pair<std::size_t, Vector3>> path_origins{{ref, o}};
    reference_turn_.assign(links_.size(), std::nullopt);
    reference_turn_[ref] = R;
    for (std::size_t a = ref;;) {
      const TreeLink& l = links_[a];
      bool at_rest = cyclic(a);  // its coordinate's turn about gravity left out, as in place()
      GiNaC::matrix above = R.mul((at_rest ? l.rest_pose->first : l.turn).transpose());
      for (unsigned k = 0; k < 9; ++k) above.let_op(k) = above.op(k).expand();
      o = o - times(above, at_rest ? l.rest_pose->second : l.offset);
      if (l.parent < 0) {
        world_turn_ = above;
        world_origin_ = o;
        break;
      }
      a = std::size_t(l.parent);
      for (unsigned x = 0; x < 3; ++x)
        for (unsigned y = 0; y < 3; ++y) above(x, y) = name(a, fmt::format("gR{}{}", x, y), above(x, y));
      reference_turn_[a] = R = above;
      path_origins.emplace_back(a, o);
    }
    // the root's origin as the frame's
    const Vector3 root = path_origins.back().second;
    reference_origin_.assign(links_.size(), std::nullopt);
    for (const auto& [a, at] : path_origins) reference_origin_[a] = at - root;
    world_origin_ = world_origin_ - root;
    return times(world_turn_, gravity);
  }

  // link i's world pose, its joint's twists S, its v and a, and the joint's w, W and V_b
  void place(std::size_t i, const Vector3& gravity, const std::vector<ex>& ddq) {
    const TreeLink& l = links_[i];
    bool root = l.parent < 0;
    std::size_t p = root ? 0 : std::size_t(l.parent);
    SpatialVector rest, fall{{0, 0, 0}, scaled(-1, gravity)};
    const SpatialVector& vp = root ? rest : v_[p];
    const SpatialVector& ap = root ? fall : a_[p];
    const SpatialVector& a0p = root ? fall : a0_[p];
    const SpatialVector& driven_p = root ? rest : driven_a_[p];
    bool at_rest = cyclic(i);
    GiNaC::matrix turn = at_rest ? l.rest_pose->first : l.turn;
    Vector3 offset = at_rest ? l.rest_pose->second : l.offset;
    GiNaC::matrix R = on_reference_path(i) ? *reference_turn_[i] : !root ? R_[p].mul(l.turn) : reference_ ? world_turn_.mul(turn) : turn;
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned b = 0; b < 3; ++b)
        R_[i](a, b) = name(i, fmt::format("gR{}{}", a, b), R(a, b));
    origin_[i] = named(i, "go", on_reference_path(i) ? *reference_origin_[i]
                                : !root              ? origin_[p] + times(R_[p], l.offset)
                                : reference_         ? world_origin_ + times(world_turn_, offset)
                                                     : offset);
    // v = v_λ + V_p + V_b and a = a_λ + Σ S s' + v × V_b + v_λ × V_p: the columns that turn with
    // the link change as v × S, those that keep the parent's axes as v_λ × S
    SpatialVector kept, turning, driven, kept_driven;
    for (std::size_t c = 0; c < l.columns.size(); ++c) {
      const TreeLink::Column& col = l.columns[c];
      Vector3 s = times(R_[i], col.axis);
      std::string tag = l.columns.size() > 1 ? std::to_string(c) : "";
      S_[i].push_back(named(i, "gS" + tag, SpatialVector{s, cross(origin_[i], s) + times(R_[i], col.origin_velocity)}));
      SpatialVector rate = scaled(col.rate, S_[i][c]), push = scaled(ddq[std::size_t(col.velocity)], S_[i][c]);
      if (col.turns_with_link) turning = turning + rate;
      else kept = kept + rate, kept_driven = kept_driven + push;
      driven = driven + push;
    }
    turning_v_[i] = turning;
    if (l.columns.empty()) {
      v_[i] = vp, a_[i] = ap, a0_[i] = a0p, driven_a_[i] = driven_p;
    } else {
      v_[i] = named(i, "gv", vp + kept + turning);
      // a = a⁰ + α: α = Σ S q'' over the joints up to the root, a⁰ the rest (gravity included), so
      // that M and τ at q'' = 0 come from the same quantities (tree_acceleration_gradient)
      driven_a_[i] = named(i, "gal", driven_p + driven);
      if (is_hinge(i)) {
        // v × S s' = s' (v_λ + S s') × S = s' Ψ': Ψ' = v_λ × S named here, once, for Ψ'' and the pairs
        hinge_dS_[i] = named(i, "gdS", motion_cross(vp, S_[i][0]));
        a0_[i] = named(i, "ga0", a0p + scaled(l.columns[0].rate, *hinge_dS_[i]));
      } else {
        a0_[i] = named(i, "ga0", a0p + motion_cross(v_[i], turning) + motion_cross(vp, kept));
      }
      a_[i] = named(i, "ga", a0_[i] + driven_a_[i]);
      still_v_[i] = named(i, "gw", vp + kept);
      still_a_[i] = named(i, "gW", ap + kept_driven + motion_cross(vp, kept));
    }
  }

  // composite inertias, forces, momenta and D, leaves first
  void backward() {
    for (std::size_t i = links_.size(); i-- > 0;) {
      for (std::size_t c = i + 1; c < links_.size(); ++c) {
        if (links_[c].parent != int(i)) continue;
        inertia_[i].mass += inertia_[c].mass;
        inertia_[i].first = inertia_[i].first + inertia_[c].first;
        inertia_[i].J = inertia_[i].J.add(inertia_[c].J);
        force0_[i] = force0_[i] + force0_[c];
        driven_force_[i] = driven_force_[i] + driven_force_[c];
        momentum_[i] = momentum_[i] + momentum_[c];
        D_[i] = D_[i].add(D_[c]);
      }
      inertia_[i] = named(i, "gC", inertia_[i]);
      force0_[i] = named(i, "gF0", force0_[i]);
      driven_force_[i] = named(i, "gY", driven_force_[i]);
      force_[i] = named(i, "gF", force0_[i] + driven_force_[i]);
      momentum_[i] = named(i, "gP", momentum_[i]);
      for (unsigned r = 0; r < 6; ++r)
        for (unsigned c = r; c < 6; ++c) D_[i](r, c) = D_[i](c, r) = name(i, fmt::format("gD{}{}", r, c), D_[i](r, c));
    }
  }

  // per direction (a coordinate) its twist T, Ψ' and Ψ'' and then G; per column (a row of τ) I^C S
  // and B^Cᵀ S = D S − S ×* P, and as a direction (its velocity) A = (w + u) × S and H
  void joint_quantities() {
    for (std::size_t j = 0; j < links_.size(); ++j) {
      joint_motion(j);
      joint_forces(j);
    }
  }

  // T, Ψ', Ψ'' and A of joint j, which its links' motion gives (place() first)
  void joint_motion(std::size_t j) {
    std::size_t n = links_.size();
    twist_.resize(n), dS_.resize(n), ddS_.resize(n), A_.resize(n);
    const TreeLink& l = links_[j];
    SpatialVector rest, vp = l.parent < 0 ? rest : v_[std::size_t(l.parent)];
    for (std::size_t d = 0; d < l.directions.size(); ++d) {
      SpatialVector T;
      for (const auto& [c, weight] : l.directions[d].weights) T = T + scaled(weight, S_[j][c]);
      std::string tag = l.directions.size() > 1 ? std::to_string(d) : "";
      if (l.directions.size() > 1 || l.directions[d].weights.size() != 1 || !(l.directions[d].weights[0].second - 1).is_zero())
        T = named(j, "gT" + tag, T);
      twist_[j].push_back(T);
      dS_[j].push_back(hinge_dS_[j] ? *hinge_dS_[j] : named(j, "gdS" + tag, motion_cross(still_v_[j], T)));
      ddS_[j].push_back(named(j, "gddS" + tag, motion_cross(still_a_[j], T) + motion_cross(still_v_[j], dS_[j][d])));
    }
    for (std::size_t c = 0; c < l.columns.size(); ++c) {
      const SpatialVector& S = S_[j][c];
      // A = (w + u) × S: for a turning column u = v_j = w + V_b, whose S × S part vanishes, so
      // that a hinge has A = 2 v_λ × S
      SpatialVector A;
      if (!l.columns[c].turns_with_link) A = motion_cross(still_v_[j] + vp, S);
      else if (is_hinge(j)) A = scaled(2, *hinge_dS_[j]);  // T = S: A = 2 Ψ'
      else if (l.columns.size() == 1) A = scaled(2, motion_cross(still_v_[j], S));
      else A = scaled(2, motion_cross(still_v_[j], S)) + motion_cross(turning_v_[j], S);
      A_[j].push_back(named(j, "gA" + (l.columns.size() > 1 ? std::to_string(c) : ""), A));
    }
  }

  // G, I^C S, B^Cᵀ S and H of joint j, from the composite quantities (backward() first)
  void joint_forces(std::size_t j) {
    std::size_t n = links_.size();
    IS_.resize(n), BS_.resize(n), G_.resize(n), H_.resize(n);
    const TreeLink& l = links_[j];
    for (std::size_t d = 0; d < l.directions.size(); ++d)
      G_[j].push_back(named(j, "gG" + (l.directions.size() > 1 ? std::to_string(d) : ""),
                            force_cross(twist_[j][d], force_[j]) + apply(inertia_[j], ddS_[j][d]) +
                                times(D_[j], dS_[j][d]) + force_cross(dS_[j][d], momentum_[j])));
    for (std::size_t c = 0; c < l.columns.size(); ++c) {
      const SpatialVector& S = S_[j][c];
      std::string tag = l.columns.size() > 1 ? std::to_string(c) : "";
      // B^C x = D x + x ×* P
      SpatialVector DS = named(j, "gDS" + tag, times(D_[j], S)), SP = named(j, "gSP" + tag, force_cross(S, momentum_[j]));
      IS_[j].push_back(named(j, "gIS" + tag, apply(inertia_[j], S)));
      BS_[j].push_back(named(j, "gBS" + tag, DS + scaled(-1, SP)));
      H_[j].push_back(named(j, "gH" + tag, apply(inertia_[j], A_[j][c]) + DS + SP));
    }
  }

  // each pair of a link k and a link j at or above it: j's directions in k's rows, and k's in j's;
  // summed where several joints follow one coordinate (their S carry the multiplier, so that by the
  // chain rule each pair of links adds its part)
  InverseDynamicsGradient pairs(std::size_t velocities, std::size_t coordinates) const {
    InverseDynamicsGradient g{GiNaC::matrix(unsigned(velocities), unsigned(coordinates)),
                              GiNaC::matrix(unsigned(velocities), unsigned(velocities)),
                              GiNaC::matrix(unsigned(velocities), unsigned(velocities)), std::vector<ex>(velocities, 0)};
    for (std::size_t k = 0; k < links_.size(); ++k)
      for (int up = int(k); up >= 0; up = links_[std::size_t(up)].parent) {
        std::size_t j = std::size_t(up);
        // M_kj = S_j·I^C_k S_k, once per ordered pair of columns, and τ⁰_k = S_k·F⁰_k
        for (std::size_t r = 0; r < links_[k].columns.size(); ++r) {
          unsigned i = unsigned(links_[k].columns[r].velocity);
          if (j == k) g.bias[i] += power(S_[k][r], force0_[k]).expand();
          for (std::size_t c = 0; c < links_[j].columns.size(); ++c) {
            unsigned m = unsigned(links_[j].columns[c].velocity);
            ex entry = power(S_[j][c], IS_[k][r]).expand();
            g.mass_matrix(i, m) += entry;
            if (j != k) g.mass_matrix(m, i) += entry;
          }
        }
        // the directions of j in the rows of k, which j's joint carries (or k = j)
        for (std::size_t r = 0; r < links_[k].columns.size(); ++r) {
          const TreeLink::Column& row = links_[k].columns[r];
          unsigned i = unsigned(row.velocity);
          for (std::size_t d = 0; d < links_[j].directions.size() && !cyclic(j); ++d) {
            unsigned q = unsigned(links_[j].directions[d].coordinate);
            bool carried = j != k || row.turns_with_link;
            g.coordinates(i, q) += (carried ? power(ddS_[j][d], IS_[k][r]) + power(dS_[j][d], BS_[k][r])
                                           : power(S_[k][r], G_[j][d])).expand();
          }
          for (std::size_t c = 0; c < links_[j].columns.size(); ++c)
            g.velocities(i, unsigned(links_[j].columns[c].velocity)) +=
                (power(A_[j][c], IS_[k][r]) + power(S_[j][c], BS_[k][r])).expand();
        }
        if (j == k) continue;
        // the directions of k in the rows of j, above it: through F_j alone
        for (std::size_t r = 0; r < links_[j].columns.size(); ++r) {
          unsigned i = unsigned(links_[j].columns[r].velocity);
          for (std::size_t d = 0; d < links_[k].directions.size(); ++d)
            g.coordinates(i, unsigned(links_[k].directions[d].coordinate)) += power(S_[j][r], G_[k][d]).expand();
          for (std::size_t c = 0; c < links_[k].columns.size(); ++c)
            g.velocities(i, unsigned(links_[k].columns[c].velocity)) += power(S_[j][r], H_[k][c]).expand();
        }
      }
    return g;
  }

  // the loops' inputs (TreeLinkTables): the links' own data, their bodies summed about their origins;
  // a jointed root's table entries a fixed link's
  TreeLinkTables loop_inputs(const Vector3& gravity, std::vector<JointedRoot> roots) const {
    TreeLinkTables in;
    in.gravity = gravity;
    in.roots = std::move(roots);
    auto jointed = [&](std::size_t i) {
      return std::any_of(in.roots.begin(), in.roots.end(), [&](const JointedRoot& r) { return r.link == i; });
    };
    for (std::size_t i = 0; i < links_.size(); ++i) {
      const TreeLink& l = links_[i];
      in.parent.push_back(l.parent);
      in.turn.push_back({l.turn(0, 0), l.turn(0, 1), l.turn(0, 2), l.turn(1, 0), l.turn(1, 1), l.turn(1, 2), l.turn(2, 0),
                         l.turn(2, 1), l.turn(2, 2)});
      in.offset.push_back(l.offset);
      in.velocity.emplace_back(), in.column.emplace_back(), in.rate.emplace_back();
      in.coordinate.emplace_back(), in.weight.emplace_back();
      if (!jointed(i)) {
        for (const TreeLink::Column& c : l.columns) {
          in.velocity.back().push_back(c.velocity);
          in.rate.back().push_back(c.rate);
          in.column.back().push_back({c.axis[0], c.axis[1], c.axis[2], c.origin_velocity[0], c.origin_velocity[1], c.origin_velocity[2]});
        }
        for (const TreeLink::Direction& d : l.directions) {
          in.coordinate.back().push_back(d.coordinate);
          std::vector<ex> over_columns(l.columns.size(), 0);
          for (const auto& [c, weight] : d.weights) over_columns[c] += weight;
          in.weight.back().push_back(over_columns);
        }
      }
      // about the origin: h = Σ m c and J = Σ J_c + m (|c|² 1 − c cᵀ)
      std::array<ex, 10> I{0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
      for (const TreeLink::Body& b : l.bodies) {
        I[0] += b.mass;
        for (unsigned k = 0; k < 3; ++k) I[1 + k] += b.mass * b.center[k];
        ex cc = dot(b.center, b.center);
        const unsigned rows[6] = {0, 0, 0, 1, 1, 2}, cols[6] = {0, 1, 2, 1, 2, 2};
        for (unsigned k = 0; k < 6; ++k) {
          unsigned r = rows[k], c = cols[k];
          I[4 + k] += b.inertia(r, c) + b.mass * ((r == c ? cc : ex(0)) - b.center[r] * b.center[c]);
        }
      }
      for (ex& entry : I) entry = entry.expand();
      in.inertia.push_back(I);
    }
    return in;
  }

  // every joint but a root link's (which may be of any kind: a floating base, a free object beside
  // it) a hinge or a slide (the loops' one-column formulas: a joint that follows another's
  // coordinate, URDF's mimic, is a hinge whose S carries its multiplier and whose rows and columns
  // the loops add into its leader's, as pairs() does), a joint of several columns that all turn
  // with its link (a ball joint: the loops' general formulas, A = (2 v_λ + V_b) × S), or none (a
  // fixed link)
  bool loops_take_it() const {
    for (std::size_t j = 0; j < links_.size(); ++j) {
      const TreeLink& l = links_[j];
      if (l.parent < 0) continue;
      bool turning = std::all_of(l.columns.begin(), l.columns.end(), [](const TreeLink::Column& c) { return c.turns_with_link; });
      if (!l.columns.empty() && !is_loop_hinge(j) && !(l.columns.size() > 1 && turning)) return false;
    }
    return true;
  }

  // the joints of several velocities of the root links: their motion, straight-line
  std::vector<JointedRoot> jointed_roots(const Vector3& gravity, const std::vector<ex>& ddq) {
    std::vector<JointedRoot> roots;
    for (std::size_t i = 0; i < links_.size(); ++i)
      if (links_[i].parent < 0 && !links_[i].columns.empty() && !is_loop_hinge(i)) roots.push_back(jointed_root(i, gravity, ddq));
    return roots;
  }

 private:
  JointedRoot jointed_root(std::size_t i, const Vector3& gravity, const std::vector<ex>& ddq) {
    place(i, gravity, ddq);
    joint_motion(i);
    auto six = [](const SpatialVector& x) {
      return std::array<ex, 6>{x.top[0], x.top[1], x.top[2], x.bottom[0], x.bottom[1], x.bottom[2]};
    };
    JointedRoot root{i, {}, {}, {}, {}, {}, {}, {}, {}, six(v_[i]), six(a_[i])};
    const TreeLink& l = links_[i];
    for (std::size_t c = 0; c < l.columns.size(); ++c) {
      root.velocity.push_back(l.columns[c].velocity);
      root.turns.push_back(l.columns[c].turns_with_link);
      root.S.push_back(six(S_[i][c]));
      root.A.push_back(six(A_[i][c]));
    }
    for (std::size_t d = 0; d < l.directions.size(); ++d) {
      if (translates_the_tree(i, d)) continue;
      root.coordinate.push_back(l.directions[d].coordinate);
      root.twist.push_back(six(twist_[i][d]));
      root.dS.push_back(six(dS_[i][d]));
      root.ddS.push_back(six(ddS_[i][d]));
    }
    return root;
  }

  // A direction of a root link i's joint that slides its whole tree without turning it, T = (0, t)
  // with Ψ' = Ψ'' = 0 (a free joint's position): every pair term of it vanishes, the rows that turn
  // with a link taking Ψ''·I S + Ψ'·Bᵀ S = 0 and the root's rows that keep its parent's axes, S =
  // (0, s), taking S·G = S·(T ×* F) = (0, s)·(t × f, 0) = 0 (uniform gravity does not see where the
  // tree is), so its column stays zero and the loops leave it out
  bool translates_the_tree(std::size_t i, std::size_t d) const {
    auto zero = [](const Vector3& x) {
      return x[0].expand().is_zero() && x[1].expand().is_zero() && x[2].expand().is_zero();
    };
    const TreeLink& l = links_[i];
    for (std::size_t c = 0; c < l.columns.size(); ++c)
      if (!l.columns[c].turns_with_link && !zero(S_[i][c].top)) return false;
    return zero(twist_[i][d].top) && zero(dS_[i][d].top) && zero(dS_[i][d].bottom) && zero(ddS_[i][d].top) &&
           zero(ddS_[i][d].bottom);
  }

  // A root hinge about gravity's direction (about any axis without gravity) or a root slide moves
  // its subtree as one rigid body, and uniform gravity does not see that motion: the bodies'
  // Lagrangian does not depend on its coordinate, which is cyclic for their forces (∂τ/∂q = 0), and
  // the subtree's quantities may be formed at the coordinate's zero, in world axes turned or slid
  // back by the joint, where the root's turn is constant and the products down the tree fold it
  void find_cyclic_roots(const Vector3& gravity) {
    cyclic_.assign(links_.size(), false);
    for (std::size_t i = 0; i < links_.size(); ++i) {
      const TreeLink& l = links_[i];
      if (l.parent >= 0 || !l.rest_pose || !is_loop_hinge(i)) continue;
      Vector3 across = cross(times(l.rest_pose->first, l.columns[0].axis), gravity);
      cyclic_[i] = std::all_of(across.begin(), across.end(), [](const ex& x) { return x.expand().is_zero(); });
    }
  }
  bool cyclic(std::size_t i) const { return i < cyclic_.size() && cyclic_[i]; }
  bool on_reference_path(std::size_t i) const { return i < reference_turn_.size() && reference_turn_[i].has_value(); }

  // a hinge or slide of one coordinate, which the loops' tables hold
  bool is_loop_hinge(std::size_t j) const { return is_hinge(j) && links_[j].directions.size() == 1; }

  // a joint of one column that turns with its link, whose coordinate's twist is that column's S
  // (a hinge or a slide, a follower's too): its own velocity's Ψ' is v_λ × S
  bool is_hinge(std::size_t j) const {
    const TreeLink& l = links_[j];
    return l.columns.size() == 1 && l.columns[0].turns_with_link && own_direction(j) >= 0;
  }

  // the direction of a one-column joint whose twist is that column's S (weight 1), or −1
  int own_direction(std::size_t j) const {
    const TreeLink& l = links_[j];
    for (std::size_t d = 0; d < l.directions.size(); ++d) {
      const auto& w = l.directions[d].weights;
      if (w.size() == 1 && w[0].first == 0 && (w[0].second - 1).is_zero()) return int(d);
    }
    return -1;
  }

  // the link's bodies about O: J_O = Σ R J_c Rᵀ + m(|c|² 1 − c cᵀ) with c = o + R c_local; then
  // f = I a + v ×* I v, and B x = I (x × v) + x ×* (I v) + v ×* (I x) as D x + x ×* P with the momentum
  // P = I v and the symmetric D = −(K + Kᵀ), K = I (v×), since v ×* = −(v×)ᵀ: 21 entries to carry up
  // the tree instead of 36
  void own_inertia(std::size_t i) {
    const TreeLink& l = links_[i];
    SpatialInertia I;
    for (std::size_t k = 0; k < l.bodies.size(); ++k) {
      const TreeLink::Body& b = l.bodies[k];
      Vector3 c = named(i, fmt::format("gB{}c", k), origin_[i] + times(R_[i], b.center));
      GiNaC::matrix RJ = R_[i].mul(b.inertia);
      for (unsigned r = 0; r < 3; ++r)
        for (unsigned s = 0; s < 3; ++s) RJ(r, s) = name(i, fmt::format("gB{}RJ{}{}", k, r, s), RJ(r, s));
      ex cc = dot(c, c);
      for (unsigned r = 0; r < 3; ++r)
        for (unsigned s = 0; s < 3; ++s) {
          ex turned = 0;
          for (unsigned t = 0; t < 3; ++t) turned += RJ(r, t) * R_[i](s, t);
          I.J(r, s) += turned + b.mass * ((r == s ? cc : ex(0)) - c[r] * c[s]);
        }
      I.mass += b.mass;
      I.first = I.first + scaled(b.mass, c);
    }
    if (l.bodies.empty()) return;
    inertia_[i] = named(i, "gI", I);
    SpatialVector Iv = named(i, "gIv", apply(inertia_[i], v_[i]));
    force0_[i] = apply(inertia_[i], a0_[i]) + force_cross(v_[i], Iv);
    driven_force_[i] = apply(inertia_[i], driven_a_[i]);
    momentum_[i] = Iv;
    GiNaC::symbol x[6];
    SpatialVector X{{x[0], x[1], x[2]}, {x[3], x[4], x[5]}};
    SpatialVector Dx = apply(inertia_[i], motion_cross(X, v_[i])) + force_cross(v_[i], apply(inertia_[i], X));
    for (unsigned r = 0; r < 6; ++r) {
      ex row = Dx[r].expand();
      for (unsigned c = r; c < 6; ++c) D_[i](r, c) = D_[i](c, r) = row.coeff(x[c]);
    }
  }

  // A quantity equal to one already named, or to its negative, is that name: a leaf's D entries
  // are its momentum's, and B S - S x P then cancels where it is formed, not in the header as
  // "- c*x + c*x".
  ex name(std::size_t i, const std::string& label, const ex& value) {
    ex expanded = value.expand();
    if (auto same = named_values_.find(expanded); same != named_values_.end()) return same->second;
    if (auto opposite = named_values_.find((-expanded).expand()); opposite != named_values_.end()) return -opposite->second;
    ex symbol = named_intermediate(out_, links_[i].name, label, expanded);
    if (GiNaC::is_a<GiNaC::symbol>(symbol) && !GiNaC::are_ex_trivially_equal(symbol, expanded)) named_values_[expanded] = symbol;
    return symbol;
  }
  Vector3 named(std::size_t i, const std::string& label, const Vector3& x) {
    return {name(i, label + "_x", x[0]), name(i, label + "_y", x[1]), name(i, label + "_z", x[2])};
  }
  SpatialVector named(std::size_t i, const std::string& label, const SpatialVector& x) {
    return {named(i, label + "w", x.top), named(i, label + "v", x.bottom)};
  }
  SpatialInertia named(std::size_t i, const std::string& label, const SpatialInertia& I) {
    SpatialInertia J;
    J.mass = name(i, label + "m", I.mass);
    J.first = named(i, label + "h", I.first);
    for (unsigned r = 0; r < 3; ++r)
      for (unsigned s = r; s < 3; ++s) J.J(r, s) = J.J(s, r) = name(i, fmt::format("{}J{}{}", label, r, s), I.J(r, s));
    return J;
  }

  const std::vector<TreeLink>& links_;
  std::vector<Intermediate>& out_;
  GiNaC::exmap named_values_;  // name()
  std::vector<bool> cyclic_;  // find_cyclic_roots()
  std::optional<std::size_t> reference_;
  // place_reference(): the turns and origins of the links from the reference up, and the world's
  std::vector<std::optional<GiNaC::matrix>> reference_turn_;
  std::vector<std::optional<Vector3>> reference_origin_;
  GiNaC::matrix world_turn_{3, 3};
  Vector3 world_origin_{0, 0, 0};
  std::vector<GiNaC::matrix> R_;
  std::vector<Vector3> origin_;
  std::vector<std::vector<SpatialVector>> S_;  // per column
  std::vector<SpatialVector> v_, a_;
  std::vector<SpatialVector> a0_, driven_a_;  // a = a⁰ + α, α the part of the joints' q''
  std::vector<SpatialVector> still_v_, still_a_;  // w and W: the joint's motion that its coordinates do not turn
  std::vector<SpatialVector> turning_v_;          // V_b: the turning columns' part of the joint's velocity
  std::vector<SpatialInertia> inertia_;
  std::vector<SpatialVector> force_, momentum_;
  std::vector<SpatialVector> force0_, driven_force_;  // F = F⁰ + Y: of a⁰ and of α
  std::vector<GiNaC::matrix> D_;  // symmetric
  std::vector<std::vector<SpatialVector>> twist_, dS_, ddS_, A_;  // joint_motion()
  std::vector<std::vector<SpatialVector>> IS_, BS_, G_, H_;       // joint_forces()
  std::vector<std::optional<SpatialVector>> hinge_dS_;                     // a hinge's Ψ', from forward()
};

// the longest row, at least 1 (the tables' extent)
std::size_t longest(const std::vector<std::vector<int>>& rows) {
  std::size_t most = 1;
  for (const std::vector<int>& row : rows) most = std::max(most, row.size());
  return most;
}

}  // namespace

std::size_t TreeLinkTables::most_columns() const { return longest(velocity); }
std::size_t TreeLinkTables::most_directions() const { return longest(coordinate); }

std::vector<ex> written_expressions(const BodiesGradient& g) {
  std::vector<ex> out = g.applied_inverse_dynamics;
  if (const InverseDynamicsGradient* closed = g.expressions()) {
    for (const GiNaC::matrix* m : {&closed->coordinates, &closed->velocities, &closed->mass_matrix})
      for (unsigned i = 0; i < m->nops(); ++i) out.push_back(m->op(i));
    out.insert(out.end(), closed->bias.begin(), closed->bias.end());
    return out;
  }
  const TreeLinkTables& l = *g.loops();
  auto add = [&](const auto& rows) {
    for (const auto& row : rows) out.insert(out.end(), row.begin(), row.end());
  };
  add(l.turn), add(l.offset), add(l.inertia), add(l.rate);
  for (std::size_t i = 0; i < l.parent.size(); ++i) add(l.column[i]), add(l.weight[i]);
  out.insert(out.end(), l.gravity.begin(), l.gravity.end());
  for (const JointedRoot& r : l.roots) {
    add(r.S), add(r.A), add(r.twist), add(r.dS), add(r.ddS);
    out.insert(out.end(), r.v.begin(), r.v.end());
    out.insert(out.end(), r.a.begin(), r.a.end());
  }
  return out;
}

// the operations of the quantities from `first` on and of the gradient's entries
long written_out_operations(const std::vector<Intermediate>& out, std::size_t first, const InverseDynamicsGradient& g) {
  std::vector<ex> all(g.bias);
  for (std::size_t i = first; i < out.size(); ++i) all.push_back(out[i].definition);
  for (const GiNaC::matrix* m : {&g.coordinates, &g.velocities, &g.mass_matrix})
    for (unsigned i = 0; i < m->nops(); ++i) all.push_back(m->op(i));
  return arithmetic_operations(all);
}

InverseDynamicsGradient gradient_in(const std::vector<TreeLink>& links, const Vector3& gravity, const std::vector<ex>& ddq,
                                    std::size_t velocities, std::size_t coordinates, std::vector<Intermediate>& out,
                                    std::optional<std::size_t> reference) {
  Gradient g(links, out, reference);
  g.forward(gravity, ddq);
  g.backward();
  g.joint_quantities();
  return g.pairs(velocities, coordinates);
}

JointTreeGradient joint_tree_gradient(const std::vector<TreeLink>& links, const Vector3& gravity, const std::vector<ex>& ddq,
                                      std::size_t velocities, std::size_t coordinates, std::vector<Intermediate>& out) {
  Gradient g(links, out);
  if (!beyond_straight_line_cut(links, velocities) || !g.loops_take_it())
    return written_out_gradient(links, gravity, ddq, velocities, coordinates, out);
  // pairs that straight-line code folds (axes along the links' own, slides) keep it where it stays short
  // (counted in the world's axes, which the limit was set in)
  if (worth_counting_straight_line(links)) {
    std::size_t first = out.size();
    long operations = written_out_operations(out, first, gradient_in(links, gravity, ddq, velocities, coordinates, out, std::nullopt));
    out.resize(first);
    if (short_enough_for_straight_line(operations)) return written_out_gradient(links, gravity, ddq, velocities, coordinates, out);
  }
  return g.loop_inputs(gravity, g.jointed_roots(gravity, ddq));
}

}  // namespace eomgen
