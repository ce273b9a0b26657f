// Featherstone's articulated-body algorithm (Rigid Body Dynamics Algorithms, 2008, table 7.1),
// written by hand over Eigen for the tree of an mjModel: the generic peer that the tree
// benchmark times the generated rhs against, beside MuJoCo's mj_forward. It is checked
// against MuJoCo's accelerations in tests/crosscheck/articulated_body_test.cpp.
//
// Textbook form: every call forms each body's 6×6 transform X from its parent, and the
// articulated inertias are carried up as Xᵀ I X in 6×6 products; nothing is specialized to the
// robot. Spatial vectors are (angular; linear) in the body's coordinates about its origin.
// Joints: hinge and slide about their axis through their anchor, ball
// (angular velocity in the body's axes) and free (MuJoCo's layout: the origin's velocity in the
// world, the angular velocity in the body's axes); a body of several joints is a chain of massless
// links, one per joint. Armature, damping and joint springs (a ball's and a free joint's turn
// pulled back by its rotation vector, as MuJoCo's mj_passive has it) enter as MuJoCo has them;
// contacts, limits and tendons are not modelled.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Dense>
#include <mujoco/mujoco.h>

namespace featherstone {

// the scalar's 3- and 6-vectors, 6×6 matrices and a joint's S (a column per velocity)
template <class Scalar>
struct Spatial {
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;
  using Vector6 = Eigen::Matrix<Scalar, 6, 1>;
  using Matrix6 = Eigen::Matrix<Scalar, 6, 6>;
  using Subspace = Eigen::Matrix<Scalar, 6, Eigen::Dynamic, 0, 6, 6>;
  using JointVector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1, 0, 6, 1>;
  using JointMatrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;

  static Vector3 vector(const double* x) { return Eigen::Map<const Eigen::Vector3d>(x).cast<Scalar>(); }

  static Matrix3 skew(const Vector3& a) {
    Matrix3 s;
    s << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
    return s;
  }

  static Matrix3 rotation(const double* quaternion) {  // w, x, y, z
    Eigen::Quaternion<Scalar> q{Scalar(quaternion[0]), Scalar(quaternion[1]), Scalar(quaternion[2]), Scalar(quaternion[3])};
    return q.normalized().toRotationMatrix();
  }

  // v × m: the motion cross product
  static Vector6 motion_cross(const Vector6& v, const Vector6& m) {
    Vector6 out;
    out.template head<3>() = v.template head<3>().cross(m.template head<3>());
    out.template tail<3>() = v.template head<3>().cross(m.template tail<3>()) + v.template tail<3>().cross(m.template head<3>());
    return out;
  }

  // v ×* f: the force cross product
  static Vector6 force_cross(const Vector6& v, const Vector6& f) {
    Vector6 out;
    out.template head<3>() = v.template head<3>().cross(f.template head<3>()) + v.template tail<3>().cross(f.template tail<3>());
    out.template tail<3>() = v.template head<3>().cross(f.template tail<3>());
    return out;
  }

  // the motion transform into a frame whose axes are the columns of E and whose origin is r,
  // both in the parent's coordinates
  static Matrix6 motion_transform(const Matrix3& E, const Vector3& r) {
    Matrix6 X = Matrix6::Zero();
    X.template topLeftCorner<3, 3>() = E.transpose();
    X.template bottomRightCorner<3, 3>() = E.transpose();
    X.template bottomLeftCorner<3, 3>() = -E.transpose() * skew(r);
    return X;
  }
};

/// Scalar: double for the benchmark, long double for the test that tells its rounding from MuJoCo's
template <class Scalar = double>
class ArticulatedBody : Spatial<Scalar> {
  using S_ = Spatial<Scalar>;
  using typename S_::Vector3, typename S_::Matrix3, typename S_::Vector6, typename S_::Matrix6;
  using typename S_::Subspace, typename S_::JointVector, typename S_::JointMatrix;
  using S_::vector, S_::skew, S_::rotation, S_::motion_cross, S_::force_cross, S_::motion_transform;

 public:
  explicit ArticulatedBody(const mjModel* m) : m_(m) {
    gravity_ = vector(m->opt.gravity);
    std::vector<int> last_link(std::size_t(m->nbody), 0);  // a body's link: the last of its joints
    links_.resize(1);
    for (int i = 1; i < m->nbody; ++i) {
      // a body of several joints is a chain of massless links, one per joint in MuJoCo's order,
      // each turning about its axis in the body's coordinates as the ones before left them
      int joints = std::max(1, m->body_jntnum[i]);
      for (int k = 0; k < joints; ++k) {
        Link l;
        l.parent = k == 0 ? last_link[std::size_t(m->body_parentid[i])] : int(links_.size()) - 1;
        l.offset = k == 0 ? vector(m->body_pos + 3 * i) : Vector3::Zero();
        l.turn = k == 0 ? rotation(m->body_quat + 4 * i) : Matrix3::Identity();
        if (m->body_jntnum[i] > 0) add_joint(l, m->body_jntadr[i] + k);
        if (k == joints - 1) l.inertia = spatial_inertia(i);
        links_.push_back(l);
      }
      last_link[std::size_t(i)] = int(links_.size()) - 1;
    }
    std::size_t n = links_.size();
    X_.resize(n), IA_.resize(n), v_.resize(n), c_.resize(n), pA_.resize(n), a_.resize(n), U_.resize(n), D_.resize(n), u_.resize(n);
  }

  // q'' from MuJoCo's qpos and qvel and the applied generalized forces tau (nv: actuators and
  // anything else outside the model's gravity, damping and springs)
  void accelerations(const double* qpos, const double* qvel, const double* tau, Scalar* qacc) {
    Vector6 fall;
    fall << Vector3::Zero(), -gravity_;  // the base accelerating against gravity
    for (std::size_t i = 1; i < links_.size(); ++i) {
      Link& b = links_[i];
      Matrix3 E = b.turn;
      Vector3 r = b.offset;
      place(b, qpos, E, r);
      X_[i] = motion_transform(E, r);
      Vector6 joint = Vector6::Zero(), bias = Vector6::Zero();
      if (b.velocities) joint = b.S * Eigen::Map<const Eigen::VectorXd>(qvel + b.dof, b.velocities).cast<Scalar>();
      v_[i] = (b.parent ? Vector6(X_[i] * v_[std::size_t(b.parent)]) : Vector6::Zero()) + joint;
      // a free joint's S turns with the body: S' q' = (0; −ω × v)
      if (b.type == mjJNT_FREE) bias.template tail<3>() = -v_[i].template head<3>().cross(v_[i].template tail<3>());
      c_[i] = bias + motion_cross(v_[i], joint);
      IA_[i] = b.inertia;
      pA_[i] = force_cross(v_[i], b.inertia * v_[i]);
    }
    for (std::size_t i = links_.size(); i-- > 1;) {
      Link& b = links_[i];
      Matrix6 Ia = IA_[i];
      Vector6 pa = pA_[i];
      if (b.velocities) {
        U_[i] = IA_[i] * b.S;
        JointMatrix D = b.S.transpose() * U_[i];
        u_[i] = Eigen::Map<const Eigen::VectorXd>(tau + b.dof, b.velocities).cast<Scalar>() - b.S.transpose() * pA_[i];
        for (int k = 0; k < b.velocities; ++k) {
          D(k, k) += Scalar(m_->dof_armature[b.dof + k]);
          u_[i](k) -= Scalar(m_->dof_damping[b.dof + k]) * Scalar(qvel[b.dof + k]);
        }
        if (b.stiffness != 0) spring(b, qpos, u_[i]);
        D_[i] = D.inverse();
        Ia -= U_[i] * D_[i] * U_[i].transpose();
        pa += Ia * c_[i] + U_[i] * (D_[i] * u_[i]);
      } else {
        pa += Ia * c_[i];
      }
      if (b.parent) {
        IA_[std::size_t(b.parent)] += X_[i].transpose() * Ia * X_[i];
        pA_[std::size_t(b.parent)] += X_[i].transpose() * pa;
      }
    }
    for (std::size_t i = 1; i < links_.size(); ++i) {
      Link& b = links_[i];
      a_[i] = X_[i] * (b.parent ? a_[std::size_t(b.parent)] : fall) + c_[i];
      if (!b.velocities) continue;
      JointVector acceleration = D_[i] * (u_[i] - U_[i].transpose() * a_[i]);
      a_[i] += b.S * acceleration;
      Eigen::Map<JointVector>(qacc + b.dof, b.velocities) = acceleration;
    }
  }

 private:
  struct Link {
    int parent = 0, type = -1, qpos = 0, dof = 0, velocities = 0;
    Vector3 offset, axis, anchor;  // in the parent's and the link's coordinates
    Matrix3 turn;                  // the link's axes in the parent's, with the joint at its reference
    Scalar reference = 0, stiffness = 0;
    Subspace S;
    Matrix6 inertia = Matrix6::Zero();
  };

  void add_joint(Link& l, int j) {
    l.type = m_->jnt_type[j], l.qpos = m_->jnt_qposadr[j], l.dof = m_->jnt_dofadr[j];
    l.axis = vector(m_->jnt_axis + 3 * j).normalized();
    l.anchor = vector(m_->jnt_pos + 3 * j);
    l.reference = Scalar(m_->qpos0[l.qpos]);
    l.stiffness = Scalar(m_->jnt_stiffness[j]);
    l.velocities = l.type == mjJNT_FREE ? 6 : l.type == mjJNT_BALL ? 3 : 1;
    l.S = Subspace::Zero(6, l.velocities);
    if (l.type == mjJNT_HINGE) l.S.col(0) << l.axis, l.anchor.cross(l.axis);
    if (l.type == mjJNT_SLIDE) l.S.col(0) << Vector3::Zero(), l.axis;
    if (l.type == mjJNT_BALL) l.S << Matrix3::Identity(), skew(l.anchor);
    if (l.type == mjJNT_FREE) l.S.template topRightCorner<3, 3>() = Matrix3::Identity();
  }

  // the joint spring's generalized force, subtracted from u: −k (q − q_s) on a hinge or slide and on a
  // free joint's position; on a turn, −k times the rotation vector of conj(q_s) ⊗ q/|q| (the angle
  // 2 atan2(|v|, w), taken the other way round beyond π)
  void spring(const Link& b, const double* qpos, JointVector& u) const {
    const double* s = m_->qpos_spring + b.qpos;
    int turn = 0;
    if (b.type == mjJNT_HINGE || b.type == mjJNT_SLIDE) {
      u(0) -= b.stiffness * (Scalar(qpos[b.qpos]) - Scalar(s[0]));
      return;
    }
    if (b.type == mjJNT_FREE) {
      for (int k = 0; k < 3; ++k) u(k) -= b.stiffness * (Scalar(qpos[b.qpos + k]) - Scalar(s[k]));
      turn = 3;
    }
    const double* q = qpos + b.qpos + turn;
    const double* r = s + turn;
    double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    double w = q[0] / length, x = q[1] / length, y = q[2] / length, z = q[3] / length;
    // conj(r) ⊗ (w, x, y, z)
    double dw = r[0] * w + r[1] * x + r[2] * y + r[3] * z;
    Vector3 dv(Scalar(r[0] * x - r[1] * w - r[2] * z + r[3] * y), Scalar(r[0] * y + r[1] * z - r[2] * w - r[3] * x),
               Scalar(r[0] * z - r[1] * y + r[2] * x - r[3] * w));
    Scalar sine = dv.norm();
    if (sine == Scalar(0)) return;
    Scalar angle = 2 * std::atan2(sine, Scalar(dw));
    if (angle > Scalar(M_PI)) angle -= Scalar(2 * M_PI);
    u.template segment<3>(turn) -= b.stiffness * angle / sine * dv;
  }

  // body i's spatial inertia about its origin: [J_c + m c̃ c̃ᵀ, m c̃; m c̃ᵀ, m 1]
  Matrix6 spatial_inertia(int i) const {
    Scalar mass = Scalar(m_->body_mass[i]);
    Vector3 c = vector(m_->body_ipos + 3 * i);
    Matrix3 R = rotation(m_->body_iquat + 4 * i), C = skew(c);
    Matrix3 J = R * vector(m_->body_inertia + 3 * i).asDiagonal() * R.transpose();
    Matrix6 I;
    I << J + mass * C * C.transpose(), mass * C, mass * C.transpose(), mass * Matrix3::Identity();
    return I;
  }

  // the link's axes E and origin r in its parent's coordinates, its joint moved to qpos
  static void place(Link& b, const double* qpos, Matrix3& E, Vector3& r) {
    if (b.type == mjJNT_HINGE || b.type == mjJNT_BALL) {
      // MuJoCo turns a hinge by its angle from the reference (qpos0) and slides a slide likewise
      Matrix3 R = b.type == mjJNT_BALL ? rotation(qpos + b.qpos)
                                       : Eigen::AngleAxis<Scalar>(Scalar(qpos[b.qpos]) - b.reference, b.axis).toRotationMatrix();
      r += E * (b.anchor - R * b.anchor);
      E = E * R;
    } else if (b.type == mjJNT_SLIDE) {
      r += E * (b.axis * (Scalar(qpos[b.qpos]) - b.reference));
    } else if (b.type == mjJNT_FREE) {
      r = vector(qpos + b.qpos);
      E = rotation(qpos + b.qpos + 3);
      b.S.template bottomLeftCorner<3, 3>() = E.transpose();  // the origin's world velocity in the body's axes
    }
  }

  const mjModel* m_;
  Vector3 gravity_;
  std::vector<Link> links_;  // links_[0]: the world
  std::vector<Matrix6> X_, IA_;
  std::vector<Vector6> v_, c_, pA_, a_;
  std::vector<Subspace> U_;
  std::vector<JointMatrix> D_;  // inverses
  std::vector<JointVector> u_;
};

}  // namespace featherstone
