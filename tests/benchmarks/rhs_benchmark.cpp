// Right-hand-side speed of one generated model against its peers, in one
// process with interleaved repetitions and medians: the generated rhs,
// MuJoCo's mj_forward on the equivalent MJCF, a hand-written Eigen version
// (planar chains: M_jk = (Σ_{i≥max(j,k)} m_i) l_j l_k cos(φ_j − φ_k), LDLT solve),
// and jacobian_state against central differences of rhs. With -DOTHER=NAME2 (the same model
// generated with the other form, `generate --forward-dynamics`), that header's rhs too, and the largest
// difference between the two forms' results.
// -DJACOBIAN=0 leaves the Jacobian out (long chains, whose dense jacobian_state takes minutes to compile).
// -DTREE_PEERS=1 (tree_benchmark.py) also times Featherstone's articulated-body algorithm written by
// hand over Eigen (articulated_body.hpp) on the MJCF, and MuJoCo's finite-difference derivatives
// mjd_transitionFD (forward differences, its default) against jacobian_state.
// Built by peer_benchmark.py: c++ -O2 -DMODEL=NAME [-DOTHER=NAME2] -DPLANAR=0|1 -I DIR rhs_benchmark.cpp -lmujoco
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <Eigen/Dense>
#include <mujoco/mujoco.h>

#include "batch_timing.hpp"

#ifndef TREE_PEERS
#define TREE_PEERS 0
#endif
#if TREE_PEERS
#include "articulated_body.hpp"
#endif

#ifndef JACOBIAN
#define JACOBIAN 1
#endif
#define EOMGEN_STRING2(x) #x
#define EOMGEN_STRING(x) EOMGEN_STRING2(x)
#include EOMGEN_STRING(MODEL.hpp)

namespace model = eomgen::models::MODEL;
#ifdef OTHER
#include EOMGEN_STRING(OTHER.hpp)
namespace other = eomgen::models::OTHER;
#endif
constexpr int N = static_cast<int>(model::num_states), n = static_cast<int>(model::num_coordinates);

// planar chain by hand: parameters m1, l1, m2, l2, ..., g
struct HandWritten {
  Eigen::MatrixXd M = Eigen::MatrixXd(n, n);
  Eigen::VectorXd f = Eigen::VectorXd(n), tail = Eigen::VectorXd(n + 1);
  Eigen::LDLT<Eigen::MatrixXd> ldlt = Eigen::LDLT<Eigen::MatrixXd>(n);
  void rhs(const double* x, const double* p, double* xdot) {
    const double g = p[2 * n];
    tail[n] = 0;
    for (int i = n - 1; i >= 0; --i) tail[i] = tail[i + 1] + p[2 * i];  // Σ_{k≥i} m_k
    for (int j = 0; j < n; ++j) {
      const double lj = p[2 * j + 1];
      double fj = -tail[j] * g * lj * std::sin(x[j]);
      for (int k = 0; k < n; ++k) {
        const double lk = p[2 * k + 1], mass = tail[std::max(j, k)], d = x[j] - x[k];
        M(j, k) = mass * lj * lk * std::cos(d);
        fj -= mass * lj * lk * std::sin(d) * x[n + k] * x[n + k];
      }
      f[j] = fj;
    }
    ldlt.compute(M);
    Eigen::Map<Eigen::VectorXd> a(xdot + n, n);
    a = ldlt.solve(f);
    for (int i = 0; i < n; ++i) xdot[i] = x[n + i];
  }
};

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  char error[1000] = "";
  // MuJoCo's XML reader stops at about 100 nested elements: the 100-link chain is timed without it
  mjModel* mj = mj_loadXML(argv[1], nullptr, error, sizeof error);
  if (!mj) std::fprintf(stderr, "MuJoCo (left out): %s\n", error);
  mjData* data = mj ? mj_makeData(mj) : nullptr;
  std::mt19937 random(1);
  std::uniform_real_distribution<double> uniform(-0.5, 0.5);
  std::vector<double> x(N), xdot(N), xdot_hand(N), J(N * N), fd(N * N), plus(N), minus(N), u(model::num_inputs + 1, 0.0);
  for (double& v : x) v = uniform(random);
  for (int i = 0; mj && i < mj->nq; ++i) data->qpos[i] = uniform(random);
  for (int i = 0; mj && i < mj->nv; ++i) data->qvel[i] = uniform(random);
  if (mj) mj_normalizeQuat(mj, data->qpos);  // a ball or free joint's quaternion of unit length
  auto p = model::Parameters<double>().values();
  HandWritten hand;
  volatile double sink = 0;
  int calls = std::max(20, 200000 / (n * n + 10));
  // jacobian_state costs a few rhs: its batches about as long in time as the rhs's. (Batches of
  // calls / N were 10 calls on the 21-joint tree, timed right after mjd_transitionFD had taken the
  // caches: they measured the first call's cache misses, 3.7 rhs where longer batches give 3.0.)
  int jacobian_calls = std::max(5, calls / 4);
  std::vector<double> ours, theirs, mujoco, jacobian, differences, other_form, articulated, transition;
#if TREE_PEERS
  // the articulated-body peer at MuJoCo's state (no controls), and its qacc against MuJoCo's there
  if (!mj) return 2;
  featherstone::ArticulatedBody<double> aba(mj);
  std::vector<double> no_forces(std::size_t(mj->nv), 0.0), aba_qacc(std::size_t(mj->nv));
  std::vector<double> A(std::size_t(2 * mj->nv + mj->na) * std::size_t(2 * mj->nv + mj->na));
  mj_forward(mj, data);
  aba.accelerations(data->qpos, data->qvel, no_forces.data(), aba_qacc.data());
  double aba_differs = 0, qacc_size = 0;
  for (int i = 0; i < mj->nv; ++i) {
    qacc_size = std::max(qacc_size, std::abs(data->qacc[i]));
    aba_differs = std::max(aba_differs, std::abs(aba_qacc[std::size_t(i)] - data->qacc[i]));
  }
  aba_differs /= std::max(qacc_size, 1e-300);
#else
  double aba_differs = 0;
#endif
  for (int rep = 0; rep < 15; ++rep) {
    ours.push_back(time_batch([&] { model::rhs(0.0, x.data(), u.data(), p.data(), xdot.data()); sink = sink + xdot[N - 1]; }, calls));
#ifdef OTHER
    other_form.push_back(time_batch([&] { other::rhs(0.0, x.data(), u.data(), p.data(), xdot_hand.data()); sink = sink + xdot_hand[N - 1]; }, calls));
#endif
    if (mj) mujoco.push_back(time_batch([&] { mj_forward(mj, data); sink = sink + data->qacc[0]; }, calls));
#if TREE_PEERS
    articulated.push_back(time_batch([&] { aba.accelerations(data->qpos, data->qvel, no_forces.data(), aba_qacc.data()); sink = sink + aba_qacc[0]; }, calls));
    transition.push_back(time_batch([&] { mjd_transitionFD(mj, data, 1e-6, 0, A.data(), nullptr, nullptr, nullptr); sink = sink + A[0]; }, std::max(5, calls / N)));
#endif
    if (PLANAR) theirs.push_back(time_batch([&] { hand.rhs(x.data(), p.data(), xdot_hand.data()); sink = sink + xdot_hand[N - 1]; }, calls));
#if JACOBIAN
    jacobian.push_back(time_batch([&] { model::jacobian_state(0.0, x.data(), u.data(), p.data(), J.data()); sink = sink + J[0]; }, jacobian_calls));
    differences.push_back(time_batch([&] {
      for (int j = 0; j < N; ++j) {
        double h = 1e-7 * std::max(1.0, std::abs(x[j])), keep = x[j];
        x[j] = keep + h;
        model::rhs(0.0, x.data(), u.data(), p.data(), plus.data());
        x[j] = keep - h;
        model::rhs(0.0, x.data(), u.data(), p.data(), minus.data());
        x[j] = keep;
        for (int i = 0; i < N; ++i) fd[i * N + j] = (plus[i] - minus[i]) / (2 * h);
      }
      sink = sink + fd[0];
    }, std::max(5, calls / N)));
#endif
  }
  // the two forms at random states, against each other and against the same model's rhs in long
  // double: largest difference relative to max(1, max_i |x'_i|)
  double forms_differ = 0, own_error = 0, other_error = 0;
#ifdef OTHER
  std::vector<double> state(N), other_xdot(N);
  std::vector<long double> state_l(N), xdot_l(N), u_l(u.begin(), u.end());
  auto p_l = model::Parameters<long double>().values();
  auto worst = [&](const auto& a, const auto& b, double& out) {
    long double scale = 1, largest = 0;
    for (int i = 0; i < N; ++i) scale = std::max(scale, std::abs(static_cast<long double>(b[i])));
    for (int i = 0; i < N; ++i) largest = std::max(largest, std::abs(static_cast<long double>(a[i]) - static_cast<long double>(b[i])));
    out = std::max(out, static_cast<double>(largest / scale));
  };
  for (int trial = 0; trial < 100; ++trial) {
    for (int i = 0; i < N; ++i) state_l[i] = state[i] = 6 * uniform(random) * (i < n ? 1 : 2);
    model::rhs(0.0, state.data(), u.data(), p.data(), xdot.data());
    other::rhs(0.0, state.data(), u.data(), p.data(), other_xdot.data());
    model::rhs(0.0L, state_l.data(), u_l.data(), p_l.data(), xdot_l.data());
    worst(xdot, other_xdot, forms_differ);
    worst(xdot, xdot_l, own_error);
    worst(other_xdot, xdot_l, other_error);
  }
#endif
  double agreement = 0;
  if (PLANAR) {
    model::rhs(0.0, x.data(), u.data(), p.data(), xdot.data());
    hand.rhs(x.data(), p.data(), xdot_hand.data());
    for (int i = 0; i < N; ++i) agreement = std::max(agreement, std::abs(xdot[i] - xdot_hand[i]) / std::max(1.0, std::abs(xdot[i])));
  }
  auto or_null = [](const std::vector<double>& v) { return v.empty() ? std::string("null") : std::to_string(median(v)); };
  std::printf("{\"eomgen_ns\": %.1f, \"mujoco_ns\": %s, \"eigen_ns\": %s, \"jacobian_ns\": %s, "
              "\"finite_difference_ns\": %s, \"hand_written_difference\": %.2g, \"other_form_ns\": %s, "
              "\"forms_differ\": %.2g, \"error\": %.2g, \"other_form_error\": %.2g, \"featherstone_ns\": %s, "
              "\"featherstone_differs\": %.2g, \"transition_fd_ns\": %s, \"eomgen_fastest_ns\": %.1f, \"jacobian_fastest_ns\": %s}\n",
              median(ours), or_null(mujoco).c_str(), or_null(theirs).c_str(), or_null(jacobian).c_str(),
              or_null(differences).c_str(), agreement, or_null(other_form).c_str(),
              forms_differ, own_error, other_error, or_null(articulated).c_str(), aba_differs, or_null(transition).c_str(),
              fastest(ours), jacobian.empty() ? "null" : std::to_string(fastest(jacobian)).c_str());
  if (mj) mj_deleteData(data), mj_deleteModel(mj);
  return sink == 12345.678 ? 3 : 0;
}
