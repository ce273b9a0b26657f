// spatial/joint_tree_derivatives: the closed form of M, τ⁰, ∂τ/∂q and ∂τ/∂q' written in the world's
// axes and in each link's (about its root's origin), which written_out_gradient chooses among by
// their operations. Every entry is a product of a motion and a force, so each frame must give the
// world's entries: checked at random states on two trees built by hand: an oblique hinge with an
// offset, a slide on it and a hinge on that; beside them a second root, a hinge about gravity's
// direction whose coordinate is cyclic (its column zero in every frame).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <fmt/format.h>

#include "kinematics/vector3.hpp"
#include "spatial/joint_tree_derivatives.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

using GiNaC::ex;

GiNaC::matrix turn_about(int axis, const ex& angle) {
  ex c = GiNaC::cos(angle), s = GiNaC::sin(angle);
  int a = (axis + 1) % 3, b = (axis + 2) % 3;
  GiNaC::matrix R = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3));
  R(unsigned(a), unsigned(a)) = c, R(unsigned(a), unsigned(b)) = -s, R(unsigned(b), unsigned(a)) = s, R(unsigned(b), unsigned(b)) = c;
  return R;
}

struct HandBuiltTree {
  std::vector<GiNaC::symbol> q, dq, ddq;
  std::vector<TreeLink> links;
};

TreeLink::Body body(double mass, Vector3 center, double xx, double yy, double zz, double xy) {
  TreeLink::Body b{mass, center, GiNaC::matrix(3, 3)};
  b.inertia(0, 0) = xx, b.inertia(1, 1) = yy, b.inertia(2, 2) = zz, b.inertia(0, 1) = b.inertia(1, 0) = xy;
  b.inertia(1, 2) = b.inertia(2, 1) = ex(xy) / 3;
  return b;
}

// link k moved by coordinate k: a hinge about its own z (after the constant turn `fixed`), or a
// slide along `along` (link coordinates)
TreeLink joint_link(HandBuiltTree& t, int parent, const GiNaC::matrix& fixed, const Vector3& offset, bool slide,
                    const Vector3& along = {0, 0, 1}) {
  std::size_t k = t.links.size();
  TreeLink l;
  l.name = fmt::format("link{}", k);
  l.parent = parent;
  l.turn = slide ? fixed : fixed.mul(turn_about(2, t.q[k]));
  l.offset = slide ? offset + scaled(t.q[k], times(fixed, along)) : offset;
  TreeLink::Column column;
  column.velocity = int(k);
  column.rate = t.dq[k];
  column.axis = slide ? Vector3{0, 0, 0} : Vector3{0, 0, 1};
  column.origin_velocity = slide ? along : Vector3{0, 0, 0};
  l.columns = {column};
  l.directions = {TreeLink::Direction{int(k), {{0, ex(1)}}}};
  return l;
}

HandBuiltTree two_roots() {
  HandBuiltTree t;
  for (int k = 0; k < 4; ++k) {
    t.q.emplace_back(fmt::format("q{}", k));
    t.dq.emplace_back(fmt::format("dq{}", k));
    t.ddq.emplace_back(fmt::format("ddq{}", k));
  }
  t.links.push_back(joint_link(t, -1, turn_about(0, ex(3) / 10), {ex(1) / 10, ex(1) / 5, ex(3) / 10}, false));
  t.links.back().bodies = {body(1.3, {ex(1) / 20, -ex(1) / 10, ex(1) / 5}, 0.04, 0.05, 0.03, 0.004)};
  t.links.push_back(joint_link(t, 0, turn_about(1, ex(2) / 5), {ex(1) / 5, 0, -ex(1) / 2}, true, {ex(1) / 3, 0, ex(2) / 3}));
  t.links.back().bodies = {body(0.7, {0, ex(1) / 10, -ex(1) / 10}, 0.02, 0.01, 0.015, -0.002)};
  t.links.push_back(joint_link(t, 1, turn_about(0, -ex(7) / 10), {ex(1) / 10, -ex(1) / 5, -ex(2) / 5}, false));
  t.links.back().bodies = {body(0.9, {ex(3) / 20, 0, -ex(1) / 4}, 0.03, 0.035, 0.01, 0.003)};
  // the second root: a hinge about the vertical, which gravity does not see
  GiNaC::matrix upright = GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3));
  t.links.push_back(joint_link(t, -1, upright, {1, ex(1) / 2, 0}, false));
  t.links.back().rest_pose = std::make_pair(upright, Vector3{1, ex(1) / 2, 0});
  t.links.back().bodies = {body(2.1, {ex(2) / 5, 0, -ex(1) / 5}, 0.06, 0.05, 0.07, 0.01)};
  return t;
}

// the entries at a point, each intermediate evaluated once, in order
std::vector<double> entries_at(const InverseDynamicsGradient& g, const std::vector<Intermediate>& out, GiNaC::exmap point) {
  for (const Intermediate& i : out) point[i.symbol] = i.definition.subs(point).evalf();
  std::vector<double> values;
  for (const GiNaC::matrix* m : {&g.mass_matrix, &g.coordinates, &g.velocities})
    for (unsigned k = 0; k < m->nops(); ++k) values.push_back(value_at(m->op(k), point));
  for (const ex& b : g.bias) values.push_back(value_at(b, point));
  return values;
}

TEST(GradientFrames, EveryLinksFrameGivesTheWorldsEntries) {
  HandBuiltTree t = two_roots();
  std::vector<ex> ddq(t.ddq.begin(), t.ddq.end());
  Vector3 gravity{0, 0, -ex(981) / 100};
  std::mt19937 random(29);
  std::uniform_real_distribution<double> spread(-1.5, 1.5);
  for (int trial = 0; trial < 3; ++trial) {
    GiNaC::exmap point;
    for (std::size_t k = 0; k < 4; ++k)
      point[t.q[k]] = spread(random), point[t.dq[k]] = spread(random), point[t.ddq[k]] = 3 * spread(random);
    std::vector<Intermediate> out;
    InverseDynamicsGradient world = gradient_in(t.links, gravity, ddq, 4, 4, out, std::nullopt);
    std::vector<double> expected = entries_at(world, out, point);
    double largest = 0;
    for (double v : expected) largest = std::max(largest, std::abs(v));
    for (unsigned k = 0; k < 4; ++k) EXPECT_EQ(world.coordinates(k, 3), 0) << "the cyclic root's column";
    for (std::size_t reference = 0; reference < t.links.size(); ++reference) {
      std::vector<Intermediate> in_link;
      InverseDynamicsGradient g = gradient_in(t.links, gravity, ddq, 4, 4, in_link, reference);
      std::vector<double> got = entries_at(g, in_link, point);
      ASSERT_EQ(got.size(), expected.size());
      for (std::size_t e = 0; e < got.size(); ++e)
        EXPECT_NEAR(got[e], expected[e], 1e-14 * largest) << "entry " << e << " in link " << reference << "'s frame, trial " << trial;
    }
  }
}

}  // namespace
}  // namespace eomgen::test
