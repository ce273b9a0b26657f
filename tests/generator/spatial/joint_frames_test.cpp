// The joint frames the spatial recursions run in (generator/spatial/joint_frames.hpp): z along
// the joint's axis and the origin on a revolute or ball joint's anchor; exact signed permutations
// for axes along ±x, ±y, ±z; for an oblique axis, exact rational axes that are orthonormal and
// along the axis to 36 digits (checked in 60-digit arithmetic against the exact unit axis), the
// same on every call; residues cut to 0 and ±1, other constants of a rotation made exact.
#include <gtest/gtest.h>

#include <ginac/ginac.h>

#include "spatial/joint_frames.hpp"

namespace eomgen::test {
namespace {

using GiNaC::ex;
using GiNaC::numeric;
using Type = FrameLink::Joint::Type;

FrameLink::Joint joint(Type type, const Vector3& direction, const Vector3& anchor = {0, 0, 0}) {
  FrameLink::Joint j;
  j.type = type;
  ex length = GiNaC::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  for (unsigned k = 0; k < 3; ++k) j.axis[k] = direction[k] / length;
  j.anchor = anchor;
  return j;
}

// |x| in 60 digits
double magnitude(const ex& x) {
  long saved = GiNaC::Digits;
  GiNaC::Digits = 60;
  double value = std::abs(GiNaC::ex_to<numeric>(x.evalf()).to_double());
  GiNaC::Digits = saved;
  return value;
}

// CᵀC − I and C z − e, largest entry
double orthonormality_error(const JointFrame& f, const Vector3& e) {
  double worst = 0;
  for (unsigned a = 0; a < 3; ++a) {
    for (unsigned b = 0; b < 3; ++b) {
      ex product = 0;
      for (unsigned k = 0; k < 3; ++k) product += f.axes(k, a) * f.axes(k, b);
      worst = std::max(worst, magnitude(product - (a == b ? 1 : 0)));
    }
    worst = std::max(worst, magnitude(f.axes(a, 2) - e[a]));
  }
  return worst;
}

TEST(JointFrames, AnAxisAlongACoordinateAxisGetsAnExactSignedPermutation) {
  for (unsigned k = 0; k < 3; ++k)
    for (int sign : {1, -1}) {
      Vector3 direction{0, 0, 0};
      direction[k] = sign * 3;
      JointFrame f = joint_frame(joint(Type::revolute, direction, {1, 2, 3}));
      EXPECT_FALSE(f.floating);
      for (unsigned a = 0; a < 3; ++a)
        for (unsigned b = 0; b < 3; ++b)
          EXPECT_TRUE(GiNaC::is_a<numeric>(f.axes(a, b)) && GiNaC::ex_to<numeric>(f.axes(a, b)).is_integer());
      EXPECT_EQ(orthonormality_error(f, {k == 0 ? sign : 0, k == 1 ? sign : 0, k == 2 ? sign : 0}), 0.0);
      // right-handed: det C = +1
      EXPECT_EQ(ex(f.axes.determinant()), ex(1));
      EXPECT_EQ(f.origin, (Vector3{1, 2, 3}));
    }
}

TEST(JointFrames, AnObliqueAxisGetsExactAxesOrthonormalTo36Digits) {
  for (const Vector3& direction : {Vector3{numeric(-12, 100), numeric(-629, 1000), numeric(-194, 1000)}, Vector3{1, 2, 2},
                                   Vector3{numeric(1, 1000000000), 1, 1000000000},
                                   Vector3{numeric(3, 7), numeric(-5, 11), 1}}) {
    FrameLink::Joint j = joint(Type::revolute, direction, {numeric(1, 10), 0, numeric(-1, 20)});
    JointFrame f = joint_frame(j);
    EXPECT_TRUE(f.floating);
    EXPECT_LT(orthonormality_error(f, j.axis), 2e-36) << direction[0] << ", " << direction[1] << ", " << direction[2];
    for (unsigned a = 0; a < 3; ++a)
      for (unsigned b = 0; b < 3; ++b) ASSERT_TRUE(GiNaC::ex_to<numeric>(f.axes(a, b)).is_rational());
    EXPECT_LT(magnitude(f.axes.determinant() - 1), 1e-35);
    JointFrame again = joint_frame(j);
    EXPECT_TRUE(ex(again.axes).is_equal(ex(f.axes)));
    EXPECT_EQ(f.origin, j.anchor);
  }
}

TEST(JointFrames, PrismaticFreeAndFixedJointsKeepTheFramesOrigin) {
  EXPECT_EQ(joint_frame(joint(Type::prismatic, {3, 0, 4}, {1, 1, 1})).origin, (Vector3{0, 0, 0}));
  EXPECT_EQ(joint_frame(joint(Type::ball, {0, 0, 1}, {1, 2, 3})).origin, (Vector3{1, 2, 3}));
  JointFrame free = joint_frame(joint(Type::free, {0, 0, 1}, {0, 0, 0}));
  EXPECT_TRUE(ex(free.axes).is_equal(GiNaC::unit_matrix(3)));
  JointFrame fixed = joint_frame(joint(Type::fixed, {0, 0, 1}, {1, 0, 0}));
  EXPECT_EQ(fixed.origin, (Vector3{0, 0, 0}));
}

TEST(JointFrames, RotationEntriesLoseTheirResidueAndBecomeExact) {
  numeric tiny = numeric(10).power(-33);
  EXPECT_EQ(rotation_entry(tiny, true), ex(0));
  EXPECT_EQ(rotation_entry(1 - tiny, true), ex(1));
  EXPECT_EQ(rotation_entry(-1 + tiny, true), ex(-1));
  // a rational of an exact rotation stays as it is; with approximate axes it is rounded
  EXPECT_EQ(rotation_entry(numeric(3, 7), false), ex(numeric(3, 7)));
  ex rounded = rotation_entry(numeric(3, 7), true);
  EXPECT_LT(magnitude(rounded - numeric(3, 7)), 1e-36);
  // cos(7/10) is a number but no rational: made exact to 36 digits
  const ex cosine = GiNaC::cos(ex(numeric(7, 10)));
  ex c = rotation_entry(cosine, false);
  ASSERT_TRUE(GiNaC::is_a<numeric>(c) && GiNaC::ex_to<numeric>(c).is_rational());
  EXPECT_LT(magnitude(c - cosine), 1e-36);
  GiNaC::symbol q("q");
  EXPECT_TRUE(rotation_entry(GiNaC::cos(q), true).is_equal(GiNaC::cos(q)));
}

TEST(JointFrames, ResiduesAreCutRelativeToTheirScale) {
  GiNaC::symbol q("q");
  numeric scale = numeric(10).power(12);
  EXPECT_EQ(without_rounding_residue(numeric(10).power(-19), scale), ex(0));
  EXPECT_EQ(without_rounding_residue(numeric(10).power(-17), scale), ex(numeric(10).power(-17)));
  ex sum = numeric(3, 2) * q + numeric(10).power(-40) * q * q + 2;
  EXPECT_TRUE(without_small_terms(sum).is_equal(numeric(3, 2) * q + 2));
  EXPECT_LT(magnitude(rounded_to(numeric(1, 3) * scale, scale) - numeric(1, 3) * scale), 1e-23);
}

}  // namespace
}  // namespace eomgen::test
