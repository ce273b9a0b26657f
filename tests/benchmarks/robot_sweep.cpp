// One robot of robot_sweep.py: the generated header's qacc against MuJoCo's reading the same robot
// file at random states (contacts and joint limits off: neither is in the model), and the rhs
// against mj_forward and jacobian_state against the rhs, timed in this one process (medians of
// interleaved batches); and jacobian_state against central differences of the rhs at the last of
// those states (or, timed only, at MuJoCo's initial pose with every velocity 0.1). Compiled per robot with -DMODEL=name -DHEADER="path". Arguments: the file
// as MuJoCo is to read it, and "urdf" when it is a URDF, whose bodies then take the inertia tensors
// the file states (tests/support/urdf_inertias.hpp: MuJoCo's principal axes of a full tensor are
// an iteration's, eomgen's the file's six numbers), and "bounded" after it when it was read with
// MuJoCo's mass bounds. Prints one JSON line; exit 3, and no qacc, when
// the two models' states differ in size (a URDF mimic, which MuJoCo's reader ignores) or the robot
// has equality constraints (a closed loop: MuJoCo's are soft, and a random state breaks them).
#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "batch_timing.hpp"
#include "support/urdf_inertias.hpp"
#include HEADER

namespace model = eomgen::models::MODEL;

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  char error[1000] = "";
  mjModel* mj = mj_loadXML(argv[1], nullptr, error, sizeof error);
  if (!mj) {
    std::fprintf(stderr, "MuJoCo cannot read %s: %s\n", argv[1], error);
    return 2;
  }
  if (argc > 2 && std::strcmp(argv[2], "urdf") == 0) with_stated_urdf_inertias(mj, argv[1]);
  // read with MuJoCo's mass bounds (a massless link that a joint moves): what was raised to the
  // bound back to 0, as the import takes it (generator/import/massless_bodies.hpp)
  if (argc > 3 && std::strcmp(argv[3], "bounded") == 0)
    for (int k = 0; k < mj->nbody; ++k) {
      if (mj->body_mass[k] <= 2e-15) mj->body_mass[k] = 0;
      for (int a = 0; a < 3; ++a)
        if (mj->body_inertia[3 * k + a] <= 2e-15) mj->body_inertia[3 * k + a] = 0;
    }
  // contacts, limits and dry friction (the constraints) and a medium's drag are what the import
  // warns it does not carry
  mj->opt.disableflags |= mjDSBL_CONSTRAINT;
  mj->opt.density = mj->opt.viscosity = 0;
  mjData* d = mj_makeData(mj);
  const int nq = int(model::num_coordinates), nv = int(model::num_velocities), N = int(model::num_states);
  bool same_layout = nq == mj->nq && nv == mj->nv && mj->neq == 0;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  const std::size_t states = model::num_states;
  std::vector<double> x(states), xdot(states), J(states * states), u(model::num_inputs + 1, 0.0);
  auto p = model::Parameters<double>().values();
  // largest |qacc − MuJoCo's| relative to max(1, MuJoCo's largest |qacc|) over 20 states (rotors
  // spinning about their axes have no acceleration but rounding's, which is then compared with 1)
  double worst = 0;
  for (int state = 0; state < 20 && same_layout; ++state) {
    for (int i = 0; i < mj->nq; ++i) d->qpos[i] = uniform(random);
    for (int i = 0; i < mj->nv; ++i) d->qvel[i] = uniform(random);
    mj_normalizeQuat(mj, d->qpos);
    mj_forward(mj, d);
    for (int i = 0; i < nq; ++i) x[std::size_t(i)] = d->qpos[i];
    for (int i = 0; i < nv; ++i) x[std::size_t(nq + i)] = d->qvel[i];
    model::rhs(0.0, x.data(), u.data(), p.data(), xdot.data());
    double size = 0, difference = 0;
    for (int i = 0; i < nv; ++i) size = std::max(size, std::abs(d->qacc[i]));
    for (int i = 0; i < nv; ++i) difference = std::max(difference, std::abs(xdot[std::size_t(nq + i)] - d->qacc[i]));
    worst = std::max(worst, difference / std::max(size, 1.0));
  }
  if (!same_layout) {
    for (int i = 0; i < nq; ++i) x[std::size_t(i)] = i < mj->nq ? d->qpos[i] : 0.0;
    for (int i = 0; i < nv; ++i) x[std::size_t(nq + i)] = 0.1;
  }
  // each column of jacobian_state against (rhs(x + h e_k) − rhs(x − h e_k)) / 2h, h = ε^(1/3) max(1, |x_k|)
  // (about 6e-6), where the differences' truncation (h²) and the rhs's rounding (ε/h) balance: its
  // largest difference relative to the larger of 1 and J's largest entry
  model::jacobian_state(0.0, x.data(), u.data(), p.data(), J.data());
  double jacobian_size = 1, jacobian_worst = 0;
  for (double entry : J) jacobian_size = std::max(jacobian_size, std::abs(entry));
  std::vector<double> up(states), down(states);
  for (std::size_t k = 0; k < states; ++k) {
    std::vector<double> plus = x, minus = x;
    double h = std::cbrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, std::abs(x[k]));
    plus[k] += h, minus[k] -= h;
    model::rhs(0.0, plus.data(), u.data(), p.data(), up.data());
    model::rhs(0.0, minus.data(), u.data(), p.data(), down.data());
    for (std::size_t i = 0; i < states; ++i)
      jacobian_worst = std::max(jacobian_worst, std::abs(J[i * states + k] - (up[i] - down[i]) / (2 * h)) / jacobian_size);
  }
  volatile double sink = 0;
  std::vector<double> ours, mujoco, jacobian;
  int calls = std::max(20, 100000 / (N * N + 10));
  for (int rep = 0; rep < 15; ++rep) {
    ours.push_back(time_batch([&] { model::rhs(0.0, x.data(), u.data(), p.data(), xdot.data()); sink = sink + xdot[std::size_t(N - 1)]; }, calls));
    mujoco.push_back(time_batch([&] { mj_forward(mj, d); sink = sink + d->qacc[0]; }, calls));
    jacobian.push_back(time_batch([&] { model::jacobian_state(0.0, x.data(), u.data(), p.data(), J.data()); sink = sink + J[0]; },
                                  std::max(5, calls / 4)));
  }
  char difference[32] = "null";
  if (same_layout) std::snprintf(difference, sizeof difference, "%.3g", worst);
  const char* why = mj->neq > 0 ? "equality constraints" : "a mimic";
  std::printf("{\"velocities\": %d, \"why_not_compared\": \"%s\", \"qacc_difference\": %s, \"jacobian_difference\": %.3g, "
              "\"rhs_ns\": %.1f, \"mujoco_ns\": %.1f, \"jacobian_ns\": %.1f}\n",
              nv, why, difference, jacobian_worst, median(ours), median(mujoco), median(jacobian));
  mj_deleteData(d), mj_deleteModel(mj);
  return sink == 12345.678 ? 4 : same_layout ? 0 : 3;
}
