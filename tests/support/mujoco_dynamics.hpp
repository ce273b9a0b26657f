// An imported robot's equations against MuJoCo reading the same file: M and the bias forces
// (f = −qfrc_bias) at random states of a fixed-base robot of hinges and slides, whose qpos and qvel
// are the coordinates `joints` (in MuJoCo's order) and their rates.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "derive/equations.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {

/// |M − MuJoCo's| ≤ `mass_tolerance` entry by entry and |f + qfrc_bias| ≤ `force_tolerance` ·
/// max(1, |qfrc_bias|), at five states drawn with `seed` (angles in ±2, rates in ±3).
inline void expect_mujoco_dynamics(const Equations& e, const mjModel* m, const std::vector<std::string>& joints, unsigned seed,
                                   double mass_tolerance, double force_tolerance) {
  std::size_t n = joints.size();
  ASSERT_EQ(e.num_velocities(), n);
  ASSERT_EQ(std::size_t(m->nv), n);
  std::unique_ptr<mjData, void (*)(mjData*)> d(mj_makeData(m), mj_deleteData);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> angle(-2, 2), rate(-3, 3);
  std::vector<double> full(n * n);
  for (int point = 0; point < 5; ++point) {
    std::map<std::string, double> at;
    for (std::size_t j = 0; j < n; ++j) {
      d->qpos[j] = angle(random), d->qvel[j] = rate(random);
      at[joints[j]] = d->qpos[j], at["der(" + joints[j] + ")"] = d->qvel[j];
    }
    mj_forward(m, d.get());
    mj_fullM(m, full.data(), d->qM);
    GiNaC::exmap x = point_by_name(e, at);
    for (unsigned i = 0; i < n; ++i) {
      EXPECT_NEAR(value_at(e.forcing[i], x), -d->qfrc_bias[i], force_tolerance * std::max(1.0, std::abs(d->qfrc_bias[i]))) << i;
      for (unsigned j = 0; j < n; ++j) EXPECT_NEAR(value_at(e.mass_matrix(i, j), x), full[i * n + j], mass_tolerance) << i << ", " << j;
    }
  }
}

}  // namespace eomgen::test
