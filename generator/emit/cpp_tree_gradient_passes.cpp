#include "emit/cpp_tree_gradient_passes.hpp"

namespace eomgen {

// spatial/joint_tree_derivatives.hpp's formulas for a hinge or a slide: T = S, w = v_λ, W = a_λ,
// A = 2 Ψ'
const char* one_column_gradient_pass() {
  return R"(/// d tau/d(q, q') of a tree of hinges and slides (one column per link), its bodies' part, added into F
/// (rows of width W, the velocities' columns after the nq coordinates' ones): the analytic derivatives of the Newton-Euler
/// recursion (Carpentier and Mansard 2018) in world coordinates, from each link's joint twist S,
/// its rate and its bodies' spatial inertia about the origin, at the accelerations ddq. With
/// `Solves`, ddq are M^-1 f instead: the pass at the given ddq (zeros) adds the bodies' M (n x n)
/// and f = -tau into M and f, which already hold the rest of them, and solve() then writes ddq
/// (and, for the jointed roots, their motion at them) before the accelerations are formed again.
template <bool Solves, std::size_t L, std::size_t Columns, std::size_t Directions, std::size_t Roots, class T, class Solve>
void tree_gradient_pass(const tree_link_tables<L, Columns, Directions, Roots, T>& tree, const T* ddq, std::size_t nq, std::size_t W,
                        T* F, std::size_t n, T* M, T* f, Solve&& solve) {
  static_assert(Columns == 1 && Directions == 1, "a link of several columns takes the general pass");
  const int* parent = tree.parent;
  // a link's one velocity and coordinate, -1 for a fixed link
  auto velocity = [&](std::size_t i) { return tree.velocity[i][0]; };
  auto coordinate = [&](std::size_t i) { return tree.coordinate[i][0]; };
  // world poses, twists S and inertias C; v, a (the root's a is -gravity), Psi' = v_p x S,
  // Psi'' = a_p x S + v_p x Psi'; each link's force C a + v x* C v, momentum P = C v and bias D,
  // summed into the composites; with Solves each link's own C and v x* C v, for its force again
  T R[L][9], o[L][3], S[L][1][6], v[L][6], a[L][6], dS[L][6], ddS[L][6], C[L][10], force[L][6], P[L][6], D[L][9];
  [[maybe_unused]] T own[Solves ? L : 1][10], vPs[Solves ? L : 1][6];
  const T rest[6] = {T(0), T(0), T(0), T(0), T(0), T(0)};
  const T fall[6] = {T(0), T(0), T(0), -tree.gravity[0], -tree.gravity[1], -tree.gravity[2]};
  const T identity[9] = {T(1), T(0), T(0), T(0), T(1), T(0), T(0), T(0), T(1)};
  auto parent_twist = [&](std::size_t i) { return tree.motion_above(i, v, &tree_jointed_root<T>::v, rest); };
  auto parent_acceleration = [&](std::size_t i) { return tree.motion_above(i, a, &tree_jointed_root<T>::a, fall); };
  // link i's a and Psi'' at the accelerations ddq, into a[i] and ddS[i] (its motion formed)
  auto accelerate = [&](std::size_t i) {
    const T* vp = parent_twist(i);
    const T* ap = parent_acceleration(i);
    if (velocity(i) < 0) {
      for (int k = 0; k < 6; ++k) a[i][k] = ap[k], ddS[i][k] = T(0);
      return;
    }
    T aS[6], vdS[6];
    tree_motion_cross(ap, S[i][0], aS);
    tree_motion_cross(vp, dS[i], vdS);
    const T s = tree.rate[i][0], dds = ddq[velocity(i)];
    for (int k = 0; k < 6; ++k) a[i][k] = ap[k] + dds*S[i][0][k] + s*dS[i][k], ddS[i][k] = aS[k] + vdS[k];
  };
  for (std::size_t i = 0; i < L; ++i) {
    tree_place(parent[i] < 0 ? identity : R[parent[i]], parent[i] < 0 ? rest : o[parent[i]], tree.turn[i], tree.offset[i],
               tree.column[i][0], tree.inertia[i], R[i], o[i], S[i][0], C[i]);
    const T* vp = parent_twist(i);
    if (velocity(i) < 0) {
      for (int k = 0; k < 6; ++k) v[i][k] = vp[k], dS[i][k] = T(0);
    } else {
      tree_motion_cross(vp, S[i][0], dS[i]);
      for (int k = 0; k < 6; ++k) v[i][k] = vp[k] + tree.rate[i][0]*S[i][0][k];
    }
    accelerate(i);
    tree_link_forces<Solves>(C[i], v[i], a[i], force[i], P[i], D[i], own[Solves ? i : 0], vPs[Solves ? i : 0]);
  }
  tree_composites(parent, C, force, P, D);
  if constexpr (Solves) {
    tree_mass_matrix_and_bias(tree, S, C, force, n, M, f);
    solve();
    for (std::size_t i = 0; i < L; ++i) {
      accelerate(i);
      tree_link_force_again(own[i], a[i], vPs[i], force[i]);
    }
    tree_composite_forces(parent, force);
  }
  // per joint: C S, B^T S = D S - S x* P, G = S x* F + C Psi'' + D Psi' + Psi' x* P and
  // H = C A + D S + S x* P with A = 2 Psi'
  T CS[L][6], BS[L][6], G[L][6], H[L][6];
  for (std::size_t j = 0; j < L; ++j) {
    if (velocity(j) < 0) continue;
    T DS[6], SP[6], SF[6], Cdd[6], Dd[6], dP[6], Cd[6];
    tree_inertia_times(C[j], S[j][0], CS[j]);
    tree_bias_times(D[j], S[j][0], DS);
    tree_force_cross(S[j][0], P[j], SP);
    tree_force_cross(S[j][0], force[j], SF);
    tree_inertia_times(C[j], ddS[j], Cdd);
    tree_bias_times(D[j], dS[j], Dd);
    tree_force_cross(dS[j], P[j], dP);
    tree_inertia_times(C[j], dS[j], Cd);
    for (int k = 0; k < 6; ++k) {
      BS[j][k] = DS[k] - SP[k];
      G[j][k] = SF[k] + Cdd[k] + Dd[k] + dP[k];
      H[j][k] = T(2)*Cd[k] + DS[k] + SP[k];
    }
  }
  // each joint k and each joint j at or above it: j's coordinate and velocity in k's row, k's in j's
  for (std::size_t k = 0; k < L; ++k) {
    if (velocity(k) < 0) continue;
    T* row = F + std::size_t(velocity(k))*W;
    const std::size_t qk = std::size_t(coordinate(k)), sk = nq + std::size_t(velocity(k));
    int top = int(k);
    for (int j = int(k); j >= 0; j = parent[j]) {
      top = j;
      if (velocity(j) < 0) continue;
      const std::size_t q = std::size_t(coordinate(j)), s = nq + std::size_t(velocity(j));
      row[q] = row[q] + tree_power(ddS[j], CS[k]) + tree_power(dS[j], BS[k]);
      row[s] = row[s] + T(2)*tree_power(dS[j], CS[k]) + tree_power(S[j][0], BS[k]);
      if (j == int(k)) continue;
      T* above = F + std::size_t(velocity(j))*W;
      above[qk] = above[qk] + tree_power(S[j][0], G[k]);
      above[sk] = above[sk] + tree_power(S[j][0], H[k]);
    }
    const tree_jointed_root<T>* root = tree.jointed(std::size_t(top));
    if (!root) continue;
    for (std::size_t d = 0; d < root->directions; ++d) {
      T& x = row[root->coordinate[d]];
      x = x + tree_power(root->ddS[d], CS[k]) + tree_power(root->dS[d], BS[k]);
    }
    for (std::size_t c = 0; c < root->columns; ++c) {
      T& x = row[nq + std::size_t(root->velocity[c])];
      x = x + tree_power(root->A[c], CS[k]) + tree_power(root->S[c], BS[k]);
      T* above = F + std::size_t(root->velocity[c])*W;
      above[qk] = above[qk] + tree_power(root->S[c], G[k]);
      above[sk] = above[sk] + tree_power(root->S[c], H[k]);
    }
  }
  for (std::size_t r = 0; r != Roots; ++r) {
    const std::size_t i = std::size_t(tree.root_link[r]);
    tree_root_pairs(tree.root_joint[r], C[i], force[i], P[i], D[i], nq, W, F);
  }
}

)";
}

// spatial/joint_tree_derivatives.hpp's formulas for joints whose columns all turn with their links:
// w = v_λ, W = a_λ, a direction's twist T = Σ weight S over its link's columns, A = (2 v_λ + V_b) × S
const char* several_columns_gradient_pass() {
  return R"(/// d tau/d(q, q') of a tree with links of several columns (ball joints), its bodies' part, added into F (rows of width W, the velocities' columns after
/// the nq coordinates' ones): the analytic derivatives of the Newton-Euler recursion (Carpentier and
/// Mansard 2018) in world coordinates, from each link's joint twists S, their rates and its bodies'
/// spatial inertia about the origin, at the accelerations ddq. With `Solves`, ddq are M^-1 f
/// instead: the pass at the given ddq (zeros) adds the bodies' M (n x n) and f = -tau into M and f,
/// which already hold the rest of them, and solve() then writes ddq (and, for the jointed roots,
/// their motion at them) before the accelerations are formed again.
template <bool Solves, std::size_t L, std::size_t Columns, std::size_t Directions, std::size_t Roots, class T, class Solve>
void tree_gradient_pass(const tree_link_tables<L, Columns, Directions, Roots, T>& tree, const T* ddq, std::size_t nq, std::size_t W,
                        T* F, std::size_t n, T* M, T* f, Solve&& solve) {
  const int* parent = tree.parent;
  // world poses, the columns' twists S and inertias C; v, a (the root's a is -gravity), per direction
  // of twist T Psi' = v_p x T, Psi'' = a_p x T + v_p x Psi'; each link's force C a + v x* C v,
  // momentum P = C v and bias D, summed into the composites; with Solves each link's own C and
  // v x* C v, for its force again. A link of several columns keeps its directions' twists T and the
  // twist V_b of its joint's velocity, which turns with it: a = a_p + S s'' + v_p x V_b.
  T R[L][9], o[L][3], S[L][Columns][6], v[L][6], a[L][6], dS[L][Directions][6], ddS[L][Directions][6], C[L][10],
      force[L][6], P[L][6], D[L][9];
  T twist[L][Directions][6], turning[L][6];
  [[maybe_unused]] T own[Solves ? L : 1][10], vPs[Solves ? L : 1][6];
  const T rest[6] = {T(0), T(0), T(0), T(0), T(0), T(0)};
  const T fall[6] = {T(0), T(0), T(0), -tree.gravity[0], -tree.gravity[1], -tree.gravity[2]};
  const T identity[9] = {T(1), T(0), T(0), T(0), T(1), T(0), T(0), T(0), T(1)};
  auto parent_twist = [&](std::size_t i) { return tree.motion_above(i, v, &tree_jointed_root<T>::v, rest); };
  auto parent_acceleration = [&](std::size_t i) { return tree.motion_above(i, a, &tree_jointed_root<T>::a, fall); };
  // link i's a and Psi'' at the accelerations ddq, into a[i] and ddS[i] (its motion formed)
  auto accelerate = [&](std::size_t i) {
    const T* vp = parent_twist(i);
    const T* ap = parent_acceleration(i);
    if (tree.columns[i] == 0) {
      for (int k = 0; k < 6; ++k) a[i][k] = ap[k];
      return;
    }
    T vV[6];
    tree_motion_cross(vp, turning[i], vV);
    for (int k = 0; k < 6; ++k) a[i][k] = ap[k] + vV[k];
    for (int c = 0; tree.has_column(i, c); ++c) {
      const T dds = ddq[tree.velocity[i][c]];
      for (int k = 0; k < 6; ++k) a[i][k] = a[i][k] + dds*S[i][c][k];
    }
    for (int d = 0; tree.has_direction(i, d); ++d) {
      T aT[6], vdS[6];
      tree_motion_cross(ap, twist[i][d], aT);
      tree_motion_cross(vp, dS[i][d], vdS);
      for (int k = 0; k < 6; ++k) ddS[i][d][k] = aT[k] + vdS[k];
    }
  };
  for (std::size_t i = 0; i < L; ++i) {
    tree_place(parent[i] < 0 ? identity : R[parent[i]], parent[i] < 0 ? rest : o[parent[i]], tree.turn[i], tree.offset[i],
               tree.column[i][0], tree.inertia[i], R[i], o[i], S[i][0], C[i]);
    for (int c = 1; tree.has_column(i, c); ++c) tree_column_twist(R[i], o[i], tree.column[i][c], S[i][c]);
    const T* vp = parent_twist(i);
    for (int k = 0; k < 6; ++k) turning[i][k] = T(0);
    for (int c = 0; tree.has_column(i, c); ++c)
      for (int k = 0; k < 6; ++k) turning[i][k] = turning[i][k] + tree.rate[i][c]*S[i][c][k];
    for (int k = 0; k < 6; ++k) v[i][k] = vp[k] + turning[i][k];
    for (int d = 0; tree.has_direction(i, d); ++d) {
      for (int k = 0; k < 6; ++k) twist[i][d][k] = T(0);
      for (int c = 0; tree.has_column(i, c); ++c)
        for (int k = 0; k < 6; ++k) twist[i][d][k] = twist[i][d][k] + tree.weight[i][d][c]*S[i][c][k];
      tree_motion_cross(vp, twist[i][d], dS[i][d]);
    }
    accelerate(i);
    tree_link_forces<Solves>(C[i], v[i], a[i], force[i], P[i], D[i], own[Solves ? i : 0], vPs[Solves ? i : 0]);
  }
  tree_composites(parent, C, force, P, D);
  if constexpr (Solves) {
    tree_mass_matrix_and_bias(tree, S, C, force, n, M, f);
    solve();
    for (std::size_t i = 0; i < L; ++i) {
      accelerate(i);
      tree_link_force_again(own[i], a[i], vPs[i], force[i]);
    }
    tree_composite_forces(parent, force);
  }
  // per column: C S, B^T S = D S - S x* P and H = C A + D S + S x* P with A = (2 v_p + V_b) x S (a
  // hinge's or slide's 2 Psi'); per direction G = T x* F + C Psi'' + D Psi' + Psi' x* P
  T CS[L][Columns][6], BS[L][Columns][6], H[L][Columns][6], G[L][Directions][6];
  T A[L][Columns][6];
  for (std::size_t j = 0; j < L; ++j) {
    for (int c = 0; tree.has_column(j, c); ++c) {
      T DS[6], SP[6], CA[6];
      tree_inertia_times(C[j], S[j][c], CS[j][c]);
      tree_bias_times(D[j], S[j][c], DS);
      tree_force_cross(S[j][c], P[j], SP);
      const T* vp = parent_twist(j);
      T u[6];
      for (int k = 0; k < 6; ++k) u[k] = T(2)*vp[k] + turning[j][k];
      tree_motion_cross(u, S[j][c], A[j][c]);
      tree_inertia_times(C[j], A[j][c], CA);
      for (int k = 0; k < 6; ++k) BS[j][c][k] = DS[k] - SP[k], H[j][c][k] = CA[k] + DS[k] + SP[k];
    }
    for (int d = 0; tree.has_direction(j, d); ++d) {
      T TF[6], Cdd[6], Dd[6], dP[6];
      tree_force_cross(twist[j][d], force[j], TF);
      tree_inertia_times(C[j], ddS[j][d], Cdd);
      tree_bias_times(D[j], dS[j][d], Dd);
      tree_force_cross(dS[j][d], P[j], dP);
      for (int k = 0; k < 6; ++k) G[j][d][k] = TF[k] + Cdd[k] + Dd[k] + dP[k];
    }
  }
  // each link k and each link j at or above it: j's coordinates and velocities in k's rows, k's in j's
  for (std::size_t k = 0; k < L; ++k) {
    if (tree.columns[k] == 0) continue;
    // k's rows, and the places of its coordinates and velocities in a row
    T* rows[Columns];
    std::size_t own_coordinate[Directions], own_velocity[Columns];
    for (int r = 0; tree.has_column(k, r); ++r)
      rows[r] = F + std::size_t(tree.velocity[k][r])*W, own_velocity[r] = nq + std::size_t(tree.velocity[k][r]);
    for (int d = 0; tree.has_direction(k, d); ++d) own_coordinate[d] = std::size_t(tree.coordinate[k][d]);
    // k's coordinates and velocities in the row of a column s above k, through F_k
    auto into_the_row_above = [&](const T* s, int velocity_of_s) {
      T* above = F + std::size_t(velocity_of_s)*W;
      for (int d = 0; tree.has_direction(k, d); ++d) {
        T& x = above[own_coordinate[d]];
        x = x + tree_power(s, G[k][d]);
      }
      for (int c = 0; tree.has_column(k, c); ++c) {
        T& x = above[own_velocity[c]];
        x = x + tree_power(s, H[k][c]);
      }
    };
    int top = int(k);
    for (int j = int(k); j >= 0; j = parent[j]) {
      top = j;
      for (int r = 0; tree.has_column(k, r); ++r) {
        T* row = rows[r];
        for (int d = 0; tree.has_direction(j, d); ++d) {
          T& x = row[tree.coordinate[j][d]];
          x = x + tree_power(ddS[j][d], CS[k][r]) + tree_power(dS[j][d], BS[k][r]);
        }
        for (int c = 0; tree.has_column(j, c); ++c) {
          T& x = row[nq + std::size_t(tree.velocity[j][c])];
          x = x + tree_power(A[j][c], CS[k][r]) + tree_power(S[j][c], BS[k][r]);
        }
      }
      if (j == int(k)) continue;
      for (int c = 0; tree.has_column(j, c); ++c) into_the_row_above(S[j][c], tree.velocity[j][c]);
    }
    const tree_jointed_root<T>* root = tree.jointed(std::size_t(top));
    if (!root) continue;
    for (int r = 0; tree.has_column(k, r); ++r) {
      T* row = rows[r];
      for (std::size_t d = 0; d < root->directions; ++d) {
        T& x = row[root->coordinate[d]];
        x = x + tree_power(root->ddS[d], CS[k][r]) + tree_power(root->dS[d], BS[k][r]);
      }
      for (std::size_t c = 0; c < root->columns; ++c) {
        T& x = row[nq + std::size_t(root->velocity[c])];
        x = x + tree_power(root->A[c], CS[k][r]) + tree_power(root->S[c], BS[k][r]);
      }
    }
    for (std::size_t c = 0; c < root->columns; ++c) into_the_row_above(root->S[c], root->velocity[c]);
  }
  for (std::size_t r = 0; r != Roots; ++r) {
    const std::size_t i = std::size_t(tree.root_link[r]);
    tree_root_pairs(tree.root_joint[r], C[i], force[i], P[i], D[i], nq, W, F);
  }
}

)";
}

}  // namespace eomgen
