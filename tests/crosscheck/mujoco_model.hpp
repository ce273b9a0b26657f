// What the MuJoCo oracle tests share: a model loaded from MJCF with its data, the path of a
// file of tests/crosscheck/, and random states in MuJoCo's qpos and qvel.
#pragma once

#include <random>
#include <string>

#include <mujoco/mujoco.h>

namespace {

struct MujocoModel {
  explicit MujocoModel(const std::string& file) {
    char error[1000] = "";
    model = mj_loadXML(file.c_str(), nullptr, error, sizeof error);
    message = error;
    if (model) data = mj_makeData(model);
  }
  ~MujocoModel() {
    if (data) mj_deleteData(data);
    if (model) mj_deleteModel(model);
  }
  MujocoModel(const MujocoModel&) = delete;
  MujocoModel& operator=(const MujocoModel&) = delete;
  mjModel* model = nullptr;
  mjData* data = nullptr;
  std::string message;
};

// a file of tests/crosscheck/mjcf/, or a path below tests/crosscheck/
inline std::string mjcf(const std::string& name) {
  return std::string(EOMGEN_SOURCE_DIR) + "/tests/crosscheck/" + (name.find('/') == std::string::npos ? "mjcf/" : "") + name;
}

// a random state in MuJoCo's qpos, qvel: angles and positions, unit quaternions for ball and free joints
inline void random_state(const mjModel* m, std::mt19937& random, double* qpos, double* qvel) {
  std::uniform_real_distribution<double> angle(-3.0, 3.0), rate(-4.0, 4.0);
  for (int i = 0; i < m->nq; ++i) qpos[i] = angle(random);
  for (int i = 0; i < m->nv; ++i) qvel[i] = rate(random);
  for (int j = 0; j < m->njnt; ++j) {
    int type = m->jnt_type[j], at = m->jnt_qposadr[j] + (type == mjJNT_FREE ? 3 : 0);
    if (type == mjJNT_BALL || type == mjJNT_FREE) mju_normalize4(qpos + at);
  }
}

}  // namespace
