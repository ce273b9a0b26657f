#include "import/mjcf_reader.hpp"

#include "import/joint_followers.hpp"
#include "import/massless_bodies.hpp"
#include "import/rounding_noise.hpp"
#include "import/unbalanced_inertias.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <cmath>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include "common/independent_rows.hpp"
#include "import/automatic_limits.hpp"
#include "import/free_base.hpp"
#include "import/joint_force_limits.hpp"
#include "import/joint_torques.hpp"
#include "import/mjcf_actuators.hpp"
#include "import/mujoco_model_parts.hpp"
#include "import/newer_mjcf.hpp"
#include "import/option_forces.hpp"
#include "import/right_angles.hpp"
#include "import/urdf_text.hpp"

namespace eomgen {

namespace {

Triple triple(const mjtNum* x) { return {x[0], x[1], x[2]}; }
Quaternion quaternion(const mjtNum* x) { return {x[0], x[1], x[2], x[3]}; }

const char* joint_type(int type) {
  switch (type) {
    case mjJNT_FREE: return "free";
    case mjJNT_BALL: return "ball";
    case mjJNT_SLIDE: return "slide";
    default: return "hinge";
  }
}

RobotJoint joint_of(const mjModel* m, int j, const mjtNum* qpos, const mjtNum* qvel) {
  RobotJoint joint;
  joint.name = name_of(m, m->name_jntadr, j);
  joint.type = joint_type(m->jnt_type[j]);
  joint.axis = triple(m->jnt_axis + 3 * j);
  joint.anchor = triple(m->jnt_pos + 3 * j);
  int q = m->jnt_qposadr[j], v = m->jnt_dofadr[j];
  int nq = m->jnt_type[j] == mjJNT_FREE ? 7 : m->jnt_type[j] == mjJNT_BALL ? 4 : 1, nv = nq == 7 ? 6 : nq == 4 ? 3 : 1;
  joint.initial_position.assign(qpos + q, qpos + q + nq);
  joint.initial_velocity.assign(qvel + v, qvel + v + nv);
  joint.spring_reference.assign(m->qpos_spring + q, m->qpos_spring + q + nq);
  if (nq == 1) joint.reference = m->qpos0[q];
  joint.armature = m->dof_armature[v];
  joint.damping = m->dof_damping[v];
  joint.stiffness = m->jnt_stiffness[j];
  joint.limited = m->jnt_limited[j];
  joint.range = {m->jnt_range[2 * j], m->jnt_range[2 * j + 1]};
  return joint;
}

bool has_spherical_joints(const mjModel* m) {
  for (int j = 0; j < m->njnt; ++j)
    if (m->jnt_type[j] == mjJNT_FREE || m->jnt_type[j] == mjJNT_BALL) return true;
  return false;
}

// the world components of a loop's distance whose rows (Jacobian `first` − `second`, 3 × nv) are
// independent of the rows kept before them
void keep_independent_rows(const std::vector<mjtNum>& first, const std::vector<mjtNum>& second, int nv,
                           IndependentRows& kept, RobotLoop& loop) {
  for (int a = 0; a < 3; ++a) {
    std::vector<double> row(static_cast<std::size_t>(nv));
    for (int v = 0; v < nv; ++v) row[std::size_t(v)] = first[std::size_t(a * nv + v)] - second[std::size_t(a * nv + v)];
    loop.kept[std::size_t(a)] = kept.add(row);
  }
}

// the loops an equality closes: a connect's two anchors; a weld (MuJoCo 2.2.2: body1's point p
// coincides with body2's anchor a, and body1's axes turned by the quaternion D are body2's; eq_data
// = a, p, D, torquescale) as three such pairs, at p and at the tips of unit vectors along D's x and
// y axes, so that both the position and the orientation are held by points coinciding
std::vector<RobotLoop> loops_of(const mjModel* m, int e, std::size_t before) {
  RobotLoop loop;
  loop.name = name_of(m, m->name_eqadr, e);
  if (loop.name.empty()) loop.name = fmt::format("loop{}", before + 1);
  loop.body1 = m->eq_obj1id[e] - 1;
  loop.body2 = m->eq_obj2id[e] - 1;
  const mjtNum* data = m->eq_data + mjNEQDATA * e;
  if (m->eq_type[e] == mjEQ_CONNECT) {
    loop.anchor1 = triple(data);
    loop.anchor2 = triple(data + 3);
    return {loop};
  }
  loop.anchor1 = triple(data + 3);
  loop.anchor2 = triple(data);
  std::vector<RobotLoop> pairs{loop};
  mjtNum turn[9];
  mju_quat2Mat(turn, data + 6);
  for (std::size_t a = 0; a < 2; ++a) {
    RobotLoop tip = loop;
    tip.name += a == 0 ? "_ex" : "_ey";
    for (std::size_t k = 0; k < 3; ++k) tip.anchor1[k] += turn[3 * k + a];
    tip.anchor2[a] += 1;
    pairs.push_back(tip);
  }
  return pairs;
}

// the equality connects and welds as loops, each with the world components whose rows of the
// constraint Jacobian (MuJoCo's, at the initial state) are independent of the rows before them
void read_loops(const mjModel* m, const mjtNum* qpos, Robot& r) {
  std::unique_ptr<mjData, void (*)(mjData*)> data(mj_makeData(m), mj_deleteData);
  mjData* d = data.get();
  for (int i = 0; i < m->nq; ++i) d->qpos[i] = qpos[i];
  mj_kinematics(m, d);
  mj_comPos(m, d);
  IndependentRows independent;
  std::vector<mjtNum> first(std::size_t(3 * m->nv)), second(std::size_t(3 * m->nv));
  for (int e = 0; e < m->neq; ++e) {
    if ((m->eq_type[e] != mjEQ_CONNECT && m->eq_type[e] != mjEQ_WELD) || !m->eq_active[e]) continue;
    for (RobotLoop loop : loops_of(m, e, r.loops.size())) {
      int body[2] = {loop.body1 + 1, loop.body2 + 1};
      const Triple* anchor[2] = {&loop.anchor1, &loop.anchor2};
      mjtNum* jacobian[2] = {first.data(), second.data()};
      for (int k = 0; k < 2; ++k) {
        mjtNum point[3], local[3] = {(*anchor[k])[0], (*anchor[k])[1], (*anchor[k])[2]};
        mju_rotVecMat(point, local, d->xmat + 9 * body[k]);
        mju_addTo3(point, d->xpos + 3 * body[k]);
        mj_jac(m, d, jacobian[k], nullptr, point, body[k]);
      }
      keep_independent_rows(first, second, m->nv, independent, loop);
      r.loops.push_back(loop);
    }
  }
}

// the equality joints between hinges or slides, as couplings in MuJoCo's polynomial
void read_couplings(const mjModel* m, Robot& r) {
  for (int e = 0; e < m->neq; ++e) {
    int first = m->eq_obj1id[e], second = m->eq_obj2id[e];
    if (m->eq_type[e] != mjEQ_JOINT || !m->eq_active[e] || !one_dof_joint(m, first) || (second >= 0 && !one_dof_joint(m, second)))
      continue;
    RobotCoupling c;
    c.name = name_of(m, m->name_eqadr, e);
    if (c.name.empty()) c.name = fmt::format("coupling{}", r.couplings.size() + 1);
    place_joint(m, first, c.body1, c.joint1, c.reference1);
    if (second >= 0) place_joint(m, second, c.body2, c.joint2, c.reference2);
    for (int k = 0; k < 5; ++k) c.coefficients[std::size_t(k)] = m->eq_data[mjNEQDATA * e + k];
    c.equality = e;
    r.couplings.push_back(c);
  }
}

const char* const appell_takes_no_constraints =
    "a robot with ball or free joints takes Appell's equations, which take no constraints here yet; only a linear coupling "
    "of two hinges or slides, not driven by an actuator, becomes a joint that follows the other's coordinate";

// A robot with ball or free joints takes Appell's equations, which take no constraints here yet: its
// couplings stay only where a joint follows another's coordinate, the others are named as not carried.
void keep_followers(Robot& r) {
  std::vector<JointFollower> followers = joint_followers(r);
  std::vector<RobotCoupling> kept;
  for (std::size_t k = 0; k < r.couplings.size(); ++k) {
    const RobotCoupling& c = r.couplings[k];
    bool follows = std::any_of(followers.begin(), followers.end(), [&](const JointFollower& f) { return f.coupling == k; });
    if (follows) kept.push_back(c);
    else if (c.equality < 0)  // (an equality's is named by note_losses)
      r.warnings.push_back({fmt::format("{}: not carried ({})", c.name, appell_takes_no_constraints), "joint", c.name, 0});
  }
  r.couplings = kept;
}

// one line per value of friction loss, naming its joints: a legged robot's file gives every joint
// the same, and twelve lines saying so one dof at a time hide the other warnings
std::vector<std::string> friction_loss_warnings(const mjModel* m) {
  std::vector<std::pair<double, std::vector<std::string>>> by_value;
  for (int v = 0; v < m->nv; ++v) {
    double loss = m->dof_frictionloss[v];
    if (loss == 0) continue;
    auto same = [&](const auto& entry) { return entry.first == loss; };
    auto it = std::find_if(by_value.begin(), by_value.end(), same);
    if (it == by_value.end()) it = by_value.insert(by_value.end(), {loss, {}});
    int j = m->dof_jntid[v];
    std::string joint = name_of(m, m->name_jntadr, j);
    if (joint.empty()) joint = fmt::format("joint {}", j + 1);
    if (it->second.empty() || it->second.back() != joint) it->second.push_back(joint);
  }
  std::vector<std::string> lines;
  for (const auto& [loss, joints] : by_value)
    lines.push_back(fmt::format("{} joint(s) with friction loss {} ({}): dry friction is not carried", joints.size(),
                                loss, fmt::join(joints, ", ")));
  return lines;
}

// what the model cannot carry, each named
void note_losses(const mjModel* m, Robot& r) {
  // a fixed tendon that only transmits a carried actuator's force is carried; its own spring,
  // damping, friction and limits are not, nor is any other tendon
  int lost = 0;
  for (int t = 0; t < m->ntendon; ++t)
    lost += !fixed_tendon(m, t) || m->tendon_frictionloss[t] != 0 || m->tendon_limited[t];
  if (lost)
    r.warnings.push_back({fmt::format("{} tendon(s): not carried (a fixed tendon of hinges and slides is carried with its "
                                      "actuators, spring and damper, not its friction or limits; no other tendon is)", lost),
                          "tendon", "", 0});
  static const char* const kinds[] = {"connect", "weld", "joint", "tendon", "distance"};
  bool loops = !has_spherical_joints(m);
  for (int e = 0; e < m->neq; ++e) {
    std::string name = name_of(m, m->name_eqadr, e);
    int type = m->eq_type[e];
    if ((type == mjEQ_CONNECT || type == mjEQ_WELD) && loops) continue;
    auto coupled = [&](const RobotCoupling& c) { return c.equality == e; };
    if (type == mjEQ_JOINT && std::any_of(r.couplings.begin(), r.couplings.end(), coupled)) continue;
    r.warnings.push_back({fmt::format("equality constraint {} ({}): not carried ({})",
                                      name.empty() ? fmt::format("{} of {}", e + 1, m->neq) : "'" + name + "'",
                                      type >= 0 && type < 5 ? kinds[type] : "of another kind",
                                      type == mjEQ_CONNECT || type == mjEQ_WELD ? "a loop in a robot with ball or free joints, whose Appell equations "
                                                             "take no constraints here yet"
                                      : type == mjEQ_JOINT && !loops ? appell_takes_no_constraints
                                                           : "only connects, welds and joint couplings of hinges and slides become constraints"),
                          "equality", name, e + 1});
  }
  bool contacts = !(m->opt.disableflags & mjDSBL_CONTACT);
  int colliding = 0;
  for (int g = 0; g < m->ngeom && contacts; ++g) colliding += m->geom_contype[g] || m->geom_conaffinity[g];
  if (colliding) r.warnings.push_back({fmt::format("{} geom(s) that make contacts: contacts are not carried", colliding), "", "", 0});
  for (const std::string& w : friction_loss_warnings(m)) r.warnings.push_back({w, "", "", 0});
}


// the springs and dampers of fixed tendons (MuJoCo's passive force along the tendon)
void read_tendon_springs(const mjModel* m, Robot& r) {
  for (int t = 0; t < m->ntendon; ++t) {
    std::optional<std::vector<TendonJoint>> joints = fixed_tendon(m, t);
    if (!joints || (m->tendon_stiffness[t] == 0 && m->tendon_damping[t] == 0)) continue;
    std::string name = name_of(m, m->name_tendonadr, t);
    r.tendon_springs.push_back({name.empty() ? fmt::format("tendon{}", t + 1) : name, *joints, m->tendon_stiffness[t],
                                m->tendon_damping[t], m->tendon_lengthspring[t]});
  }
}

// the text of a URDF file, or nothing for another file
std::string urdf_text_of(const std::string& path) { return is_urdf_file(path) ? text_of_file(path) : ""; }

// a URDF joint's <mimic>, which MuJoCo's reader ignores, as the coupling q = m q_K + o (a joint that
// follows the other's coordinate, joint_followers.hpp, or a holonomic constraint, as an MJCF equality
// joint), or a warning where it cannot be one
void read_mimics(const mjModel* m, const std::string& urdf, Robot& r) {
  for (const UrdfMimic& mimic : urdf_mimics(urdf)) {
    int first = mj_name2id(m, mjOBJ_JOINT, mimic.joint.c_str()), second = mj_name2id(m, mjOBJ_JOINT, mimic.mimicked.c_str());
    if (!one_dof_joint(m, first) || !one_dof_joint(m, second)) {
      r.warnings.push_back({fmt::format("joint '{}' mimics '{}': not carried (only a revolute or prismatic joint that mimics "
                                        "another is carried)", mimic.joint, mimic.mimicked),
                            "joint", mimic.joint, 0});
      continue;
    }
    RobotCoupling c;
    c.name = mimic.joint + "_mimics_" + mimic.mimicked;
    place_joint(m, first, c.body1, c.joint1, c.reference1);
    place_joint(m, second, c.body2, c.joint2, c.reference2);
    c.coefficients = {mimic.offset, mimic.multiplier, 0, 0, 0};
    r.couplings.push_back(c);
  }
}

// a URDF's bodies given their links' inertias as the file states them (a link alone, or a link with
// those MuJoCo fused into it), with a warning naming the links whose inertia no rigid body has (read
// with balanceinertia), and one for those left balanced (in a body that could not be matched)
void note_stated_inertias(const std::string& urdf, Robot& r) {
  StatedInertias stated = with_stated_inertias(r.bodies, urdf);
  if (!stated.given_back.empty())
    r.warnings.push_back({fmt::format("{} link(s) whose <inertia> no rigid body has ({}: a principal moment above the sum of "
                                      "the other two, or below zero), which MuJoCo {} refuses: taken as the file states it, "
                                      "as URDF readers do",
                                      stated.given_back.size(), listed(stated.given_back), mj_version_text()),
                          "link", stated.given_back[0], 0});
  if (!stated.left_balanced.empty())
    r.warnings.push_back({fmt::format("{} link(s) whose <inertia> no rigid body has ({}) are fused with other links by MuJoCo {}: "
                                      "their body's principal moments are MuJoCo's balanced ones (their mean), not the file's",
                                      stated.left_balanced.size(), listed(stated.left_balanced), mj_version_text()),
                          "link", stated.left_balanced[0], 0});
}

}  // namespace

bool is_urdf_file(const std::string& path) { return is_urdf_path(path) || has_robot_root(text_of_file(path)); }

std::string mj_version_text() { return fmt::format("{}.{}.{}", mj_version() / 100, mj_version() / 10 % 10, mj_version() % 10); }


namespace {

// what --right-angles-within did, or what it would do: a turn stated to five digits is a full
// rotation matrix in the generated code (the Panda's rhs takes 1.5x as long as with exact turns;
// UR5's as long either way)
void note_right_angles(const RightAngleRounding& turns, Robot& r) {
  if (turns.rounded > 0)
    r.notes.push_back(fmt::format("{} turn(s) within {:.2g} rad of a right angle written as exact right angles "
                                  "(--right-angles-within): the robot moved by up to that angle",
                                  turns.rounded, turns.largest_rounded));
  if (turns.near > 0) {
    double suggested = std::pow(10.0, std::ceil(std::log10(turns.largest_near)));
    r.notes.push_back(fmt::format("{} turn(s) are within {:.2g} rad of a right angle, not to the last digit (the file states "
                                  "them to fewer digits): written as read, each is a full rotation matrix, which the generated "
                                  "code may have to multiply by; `eomgen import --right-angles-within {:g}` writes them as exact "
                                  "right angles",
                                  turns.near, turns.largest_near, suggested));
  }
}

}  // namespace

std::variant<Robot, UnreadableRobot> read_with_mujoco(const std::string& path, RobotReading reading) {
  char error[1000] = "";
  std::string urdf = urdf_text_of(path);
  if (reading.masses_from_shapes && urdf.empty())
    return UnreadableRobot{1, "--masses-from-shapes weighs a URDF's links without <inertial>; this file is MJCF, whose "
                              "bodies without <inertial> MuJoCo weighs by their geoms already",
                           "import without --masses-from-shapes"};
  std::optional<FreeBase> freed;
  if (reading.free_base && !urdf.empty()) {
    freed = free_base_of(urdf);
    if (!freed->problem.empty()) return UnreadableRobot{freed->line, freed->problem, freed->hint};
    urdf = with_own_fusestatic_off(urdf);
  }
  if (!urdf.empty() && !reading.masses_from_shapes) urdf = without_masses_from_geometry(urdf);
  LeftOut left_out;
  auto loaded = loaded_model(path, urdf, error, sizeof error, left_out);
  if (auto* mistake = std::get_if<UnreadableRobot>(&loaded)) {
    // a joint that moves only links without <inertial>: MuJoCo alone would weigh their shapes
    if (!urdf.empty() && !reading.masses_from_shapes && mistake->moves_no_mass &&
        !colliding_links_without_inertial(urdf).empty())
      mistake->hint += ", or import with --masses-from-shapes to weigh the links without one by their shapes, as MuJoCo does";
    return *mistake;
  }
  std::unique_ptr<mjModel, void (*)(mjModel*)> model(std::get<mjModel*>(loaded), mj_deleteModel);
  if (!model) return urdf.empty() ? unreadable_mjcf(error, path) : unreadable_robot(error);
  const mjModel* m = model.get();
  Robot r;
  r.reader = fmt::format("MuJoCo {}'s compiler", mj_version_text());
  r.name = m->names;  // the model's name comes first; MuJoCo names a nameless model "MuJoCo Model"
  if (r.name == "MuJoCo Model") r.name.clear();
  r.gravity = triple(m->opt.gravity);
  const mjtNum* qpos = m->nkey ? m->key_qpos : m->qpos0;
  std::vector<mjtNum> zero(std::size_t(m->nv), 0.0);
  const mjtNum* qvel = m->nkey ? m->key_qvel : zero.data();
  r.initial_state = m->nkey ? fmt::format("keyframe '{}'", name_of(m, m->name_keyadr, 0)) : "qpos0";
  for (int b = 1; b < m->nbody; ++b) {
    RobotBody body;
    body.name = name_of(m, m->name_bodyadr, b);
    if (body.name.empty()) body.name = fmt::format("body{}", b);
    body.parent = m->body_parentid[b] - 1;
    body.position = triple(m->body_pos + 3 * b);
    body.orientation = quaternion(m->body_quat + 4 * b);
    for (int k = 0; k < m->body_jntnum[b]; ++k) body.joints.push_back(joint_of(m, m->body_jntadr[b] + k, qpos, qvel));
    body.mass = m->body_mass[b];
    body.center = triple(m->body_ipos + 3 * b);
    body.inertia_axes = quaternion(m->body_iquat + 4 * b);
    body.principal_inertia = triple(m->body_inertia + 3 * b);
    r.bodies.push_back(body);
  }
  if (reading.free_base && urdf.empty()) {
    freed = free_base_of_mjcf(r, text_of_file(path));
    if (!freed->problem.empty()) return UnreadableRobot{freed->line, freed->problem, freed->hint};
  }
  if (freed) {
    if (!set_free(r, *freed))
      return UnreadableRobot{1, fmt::format("link '{}' to set free is not a body at the top of what MuJoCo read", freed->link),
                             "import the robot without --free-base"};
    if (!freed->note.empty()) r.notes.push_back(freed->note);
  }
  bool spherical = has_spherical_joints(m) || freed;
  if (left_out.mass_bounds) {
    std::vector<std::string> massless = without_mass_bounds(r.bodies);
    r.notes.push_back(fmt::format("{} moving body(ies) without mass or inertia ({}), which MuJoCo {} refuses: read with its "
                                  "compiler's mass bounds, then taken back to zero",
                                  massless.size(), listed(massless), mj_version_text()));
  }
  // after the bounds: a massless link read with them has its mass back at zero
  if (freed)
    if (std::optional<std::string> singular = massless_free_base(r, *freed))
      return UnreadableRobot{freed->link_line, *singular,
                             fmt::format("give link '{}' its <inertial>, or set free the link below it", freed->link)};
  if (!urdf.empty()) note_stated_inertias(urdf, r);
  if (std::vector<std::string> shaped = colliding_links_without_inertial(urdf); !shaped.empty())
    r.notes.push_back(reading.masses_from_shapes
                          ? fmt::format("{} link(s) without an <inertial> ({}) weighed by their collision shapes at the density "
                                        "of water, as MuJoCo {} does (--masses-from-shapes); URDF has them massless",
                                        shaped.size(), listed(shaped), mj_version_text())
                          : fmt::format("{} link(s) without an <inertial> but with collision shapes ({}): massless, as URDF "
                                        "has them (MuJoCo {} would give them the mass of their shapes at the density of water)",
                                        shaped.size(), listed(shaped), mj_version_text()));
  // the geoms MuJoCo's viewer shows by default (groups 0 to 2), for the animation
  static const char* const geom_types[] = {"plane", "hfield", "sphere", "capsule", "ellipsoid", "cylinder", "box", "mesh"};
  for (int g = 0; g < m->ngeom; ++g) {
    int b = m->geom_bodyid[g];
    if (b == 0 || m->geom_group[g] > 2 || m->geom_type[g] < 0 || m->geom_type[g] > 7) continue;
    if (std::find(left_out.mesh_sized_geoms.begin(), left_out.mesh_sized_geoms.end(), g) != left_out.mesh_sized_geoms.end()) continue;
    r.bodies[std::size_t(b - 1)].geoms.push_back(
        {geom_types[m->geom_type[g]], triple(m->geom_size + 3 * g), triple(m->geom_pos + 3 * g), quaternion(m->geom_quat + 4 * g)});
  }
  for (int s = 0; s < m->nsite; ++s) {
    std::string name = name_of(m, m->name_siteadr, s);
    if (name.empty()) continue;
    r.sites.push_back({name, m->site_bodyid[s] - 1, triple(m->site_pos + 3 * s)});
  }
  for (int k = 0; k < m->nkey; ++k) {
    std::string name = name_of(m, m->name_keyadr, k);
    r.keyframes.push_back({name.empty() ? fmt::format("key{}", k) : name,
                           std::vector<double>(m->key_qpos + k * m->nq, m->key_qpos + (k + 1) * m->nq),
                           std::vector<double>(m->key_qvel + k * m->nv, m->key_qvel + (k + 1) * m->nv)});
  }
  read_actuators(m, left_out, r);
  if (left_out.force_range_as_user) read_joint_force_ranges(m, r);
  if (left_out.automatic_limits) note_automatic_limits(r);
  if (left_out.frames_as_bodies > 0)
    r.notes.push_back(fmt::format("{} <frame> element(s) (MuJoCo 3) read as bodies welded to their parents at the frames' poses: "
                                  "the same kinematics, and their geoms weigh what MuJoCo 3 has them weigh",
                                  left_out.frames_as_bodies));
  if (left_out.servo_damping_as_user)
    r.notes.push_back(fmt::format("the position servos' kv and dampratio (MuJoCo 3's velocity gain, and that gain as the damping "
                                  "ratio ζ of kv = 2 ζ sqrt(kp m), m the inertia the servo sees at qpos0, as MuJoCo 3 takes it) "
                                  "read through MuJoCo {}'s actuator user values, which resolve defaults and classes alike",
                                  mj_version_text()));
  read_tendon_springs(m, r);
  apply_option_forces(m, left_out.passive_flags, r);
  apply_gravity_compensation(m, left_out.gravity_compensation, r);
  if (!spherical) read_loops(m, qpos, r);
  read_couplings(m, r);
  if (!urdf.empty()) read_mimics(m, urdf, r);
  if (spherical) keep_followers(r);
  if (reading.joint_torques) add_joint_torques(urdf, r);
  if (int fixed = urdf_joint_count(urdf, "fixed"); fixed > 0 && urdf_joint_count(urdf, "floating") > 0)
    r.warnings.push_back({fmt::format("{} fixed joint(s): their links are fused into their parents and their names are not "
                                      "kept (MuJoCo puts a floating base's free joint at the top level only)", fixed),
                          "", "", 0});
  if (left_out.meshes > 0)
    r.warnings.push_back({fmt::format("{} <visual> or <collision> mesh(es) not read ({}): the dynamics come from each "
                                      "link's <inertial>; the animation draws no shape for them",
                                      left_out.meshes, unreadable_robot(left_out.mesh_error).message),
                          "", "", 0});
  if (left_out.unread_mesh_files > 0)
    r.warnings.push_back({fmt::format("{} mesh file(s) MuJoCo cannot read ({}): every body's mass and inertia come from its "
                                      "<inertial> (checked), and the animation draws no shape for them",
                                      left_out.unread_mesh_files, left_out.unread_mesh_names),
                          "", "", 0});
  if (!left_out.unread_drawing_files.empty()) {
    const std::vector<std::string>& files = left_out.unread_drawing_files;
    std::string named;
    for (std::size_t k = 0; k < files.size() && k < 3; ++k) named += (k ? ", '" : "'") + files[k] + "'";
    if (files.size() > 3) named += fmt::format(" and {} more", files.size() - 3);
    r.warnings.push_back({fmt::format("{} texture or skin file(s) MuJoCo cannot read ({}): read as plain textures and without "
                                      "the skins, which draw the robot and never act",
                                      files.size(), named),
                          "", "", 0});
  }
  for (const NewerMjcf& a : left_out.newer)
    r.warnings.push_back({fmt::format("'{}' is MuJoCo 2.3's or 3's, which MuJoCo {} does not read: left out; {}{}", a.name,
                                      mj_version_text(), a.consequence, a.enters_equations ? "" : ", which does not enter the equations"),
                          "", "", 0});
  if (RoundingNoise noise = without_rounding_noise(r); noise.numbers > 0)
    r.notes.push_back(fmt::format("{} number(s) at the size of double rounding taken as zero (up to {:.2g} units of rounding of "
                                  "their scale: a unit axis's or quaternion's length, the robot's size, a body's mass times the size "
                                  "squared), such as cos(π/2) printed as 6.12323e-17 in a joint axis",
                                  noise.numbers, noise.largest));
  note_right_angles(rounded_right_angles(r, reading.right_angles_within), r);
  note_losses(m, r);
  return r;
}

}  // namespace eomgen
