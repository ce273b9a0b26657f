#include "emit/cpp_tree_gradient_loops.hpp"

#include <fmt/format.h>

#include "emit/cpp_tree_gradient_passes.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

// Six-vectors in world Plücker coordinates about the origin, motions (ω; v) and forces (n; f); a
// spatial inertia as (m, h = m c, J_O: xx xy xz yy yz zz); a link's bias D (the symmetric part of
// B x = I (x × v) + x ×* (I v) + v ×* (I x) that is not x ×* P, spatial/joint_tree_derivatives.cpp)
// as its angular block's xx xy xz yy yz zz and the vector c of its off-diagonal blocks
// [c×] and −[c×]: with v = (ω; u), D_ωω = K + Kᵀ − (u hᵀ + h uᵀ) + 2 (h·u) 1, K = [ω×] J_O, and
// c = ω × h + m u, while the linear block vanishes. 9 numbers to sum up the tree, not 21.
constexpr const char* six_vector_helpers = R"(template <class T>
inline void tree_motion_cross(const T* m, const T* x, T* y) {
  y[0] = m[1]*x[2] - m[2]*x[1];
  y[1] = m[2]*x[0] - m[0]*x[2];
  y[2] = m[0]*x[1] - m[1]*x[0];
  y[3] = m[1]*x[5] - m[2]*x[4] + m[4]*x[2] - m[5]*x[1];
  y[4] = m[2]*x[3] - m[0]*x[5] + m[5]*x[0] - m[3]*x[2];
  y[5] = m[0]*x[4] - m[1]*x[3] + m[3]*x[1] - m[4]*x[0];
}

template <class T>
inline void tree_force_cross(const T* m, const T* f, T* y) {
  y[0] = m[1]*f[2] - m[2]*f[1] + m[4]*f[5] - m[5]*f[4];
  y[1] = m[2]*f[0] - m[0]*f[2] + m[5]*f[3] - m[3]*f[5];
  y[2] = m[0]*f[1] - m[1]*f[0] + m[3]*f[4] - m[4]*f[3];
  y[3] = m[1]*f[5] - m[2]*f[4];
  y[4] = m[2]*f[3] - m[0]*f[5];
  y[5] = m[0]*f[4] - m[1]*f[3];
}

template <class T>
inline T tree_power(const T* m, const T* f) {
  return m[0]*f[0] + m[1]*f[1] + m[2]*f[2] + m[3]*f[3] + m[4]*f[4] + m[5]*f[5];
}

// (J ω + h × v; m v − h × ω)
template <class T>
inline void tree_inertia_times(const T* I, const T* x, T* y) {
  y[0] = I[4]*x[0] + I[5]*x[1] + I[6]*x[2] + I[2]*x[5] - I[3]*x[4];
  y[1] = I[5]*x[0] + I[7]*x[1] + I[8]*x[2] + I[3]*x[3] - I[1]*x[5];
  y[2] = I[6]*x[0] + I[8]*x[1] + I[9]*x[2] + I[1]*x[4] - I[2]*x[3];
  y[3] = I[0]*x[3] - I[2]*x[2] + I[3]*x[1];
  y[4] = I[0]*x[4] - I[3]*x[0] + I[1]*x[2];
  y[5] = I[0]*x[5] - I[1]*x[1] + I[2]*x[0];
}

// (D_ωω ω + c × v; ω × c)
template <class T>
inline void tree_bias_times(const T* D, const T* x, T* y) {
  y[0] = D[0]*x[0] + D[1]*x[1] + D[2]*x[2] + D[7]*x[5] - D[8]*x[4];
  y[1] = D[1]*x[0] + D[3]*x[1] + D[4]*x[2] + D[8]*x[3] - D[6]*x[5];
  y[2] = D[2]*x[0] + D[4]*x[1] + D[5]*x[2] + D[6]*x[4] - D[7]*x[3];
  y[3] = x[1]*D[8] - x[2]*D[7];
  y[4] = x[2]*D[6] - x[0]*D[8];
  y[5] = x[0]*D[7] - x[1]*D[6];
}

// the sums of a link's composite quantities into its parent's: the part copied first, so that the
// compiler, which cannot know that a parent is not its child, adds them as vectors
template <std::size_t n, class T>
inline void tree_add_into(T (&sum)[n], const T (&part)[n]) {
  T copy[n];
  for (std::size_t k = 0; k < n; ++k) copy[k] = part[k];
  for (std::size_t k = 0; k < n; ++k) sum[k] = sum[k] + copy[k];
}

// a joint column's world twist from its axis a and origin velocity b in the link's coordinates:
// (R a; o x R a + R b)
template <class T>
inline void tree_column_twist(const T* R, const T* o, const T* column, T* S) {
  const T s0 = R[0]*column[0] + R[1]*column[1] + R[2]*column[2];
  const T s1 = R[3]*column[0] + R[4]*column[1] + R[5]*column[2];
  const T s2 = R[6]*column[0] + R[7]*column[1] + R[8]*column[2];
  const T b0 = R[0]*column[3] + R[1]*column[4] + R[2]*column[5];
  const T b1 = R[3]*column[3] + R[4]*column[4] + R[5]*column[5];
  const T b2 = R[6]*column[3] + R[7]*column[4] + R[8]*column[5];
  S[0] = s0;
  S[1] = s1;
  S[2] = s2;
  S[3] = o[1]*s2 - o[2]*s1 + b0;
  S[4] = o[2]*s0 - o[0]*s2 + b1;
  S[5] = o[0]*s1 - o[1]*s0 + b2;
}

template <class T>
inline void tree_own_bias(const T* I, const T* v, T* D) {
  const T J[3][3] = {{I[4], I[5], I[6]}, {I[5], I[7], I[8]}, {I[6], I[8], I[9]}};
  T K[3][3];
  for (int s = 0; s < 3; ++s) {
    K[0][s] = v[1]*J[2][s] - v[2]*J[1][s];
    K[1][s] = v[2]*J[0][s] - v[0]*J[2][s];
    K[2][s] = v[0]*J[1][s] - v[1]*J[0][s];
  }
  const T* h = I + 1;
  const T* u = v + 3;
  const T hu = h[0]*u[0] + h[1]*u[1] + h[2]*u[2];
  D[0] = T(2)*(K[0][0] - u[0]*h[0] + hu);
  D[1] = K[0][1] + K[1][0] - (u[0]*h[1] + h[0]*u[1]);
  D[2] = K[0][2] + K[2][0] - (u[0]*h[2] + h[0]*u[2]);
  D[3] = T(2)*(K[1][1] - u[1]*h[1] + hu);
  D[4] = K[1][2] + K[2][1] - (u[1]*h[2] + h[1]*u[2]);
  D[5] = T(2)*(K[2][2] - u[2]*h[2] + hu);
  D[6] = v[1]*h[2] - v[2]*h[1] + I[0]*u[0];
  D[7] = v[2]*h[0] - v[0]*h[2] + I[0]*u[1];
  D[8] = v[0]*h[1] - v[1]*h[0] + I[0]*u[2];
}

// a link's force C a + v x* C v, momentum P = C v and bias D; with Solves its own C and v x* C v too,
// for its force again at the solved accelerations (tree_link_force_again)
template <bool Solves, class T>
inline void tree_link_forces(const T* C, const T* v, const T* a, T* force, T* P, T* D, T* own, T* vP_kept) {
  T Ca[6], vP[6];
  tree_inertia_times(C, v, P);
  tree_inertia_times(C, a, Ca);
  tree_force_cross(v, P, vP);
  for (int k = 0; k < 6; ++k) force[k] = Ca[k] + vP[k];
  tree_own_bias(C, v, D);
  if constexpr (Solves) {
    for (int k = 0; k < 10; ++k) own[k] = C[k];
    for (int k = 0; k < 6; ++k) vP_kept[k] = vP[k];
  }
}

template <class T>
inline void tree_link_force_again(const T* own, const T* a, const T* vP, T* force) {
  T Ca[6];
  tree_inertia_times(own, a, Ca);
  for (int k = 0; k < 6; ++k) force[k] = Ca[k] + vP[k];
}

// each link's composite quantities summed into its parent's, leaves first
template <std::size_t L, class T>
inline void tree_composites(const int* parent, T (&C)[L][10], T (&force)[L][6], T (&P)[L][6], T (&D)[L][9]) {
  for (std::size_t i = L; i-- > 0;) {
    const int p = parent[i];
    if (p < 0) continue;
    tree_add_into(C[p], C[i]);
    tree_add_into(force[p], force[i]);
    tree_add_into(P[p], P[i]);
    tree_add_into(D[p], D[i]);
  }
}

template <std::size_t L, class T>
inline void tree_composite_forces(const int* parent, T (&force)[L][6]) {
  for (std::size_t i = L; i-- > 0;)
    if (parent[i] >= 0) tree_add_into(force[parent[i]], force[i]);
}

)";

// The recursion and the pairs of spatial/joint_tree_derivatives.hpp for joints whose columns turn with
// their links (w = v_λ, W = a_λ; a hinge's or slide's T = S and A = 2 Ψ'), over the links' tables;
// and for a first link's joint of several velocities (a floating base), the general formulas with
// its motion given.
constexpr const char* gradient_template = R"(/// A root joint of several velocities (a floating base) in world coordinates: per velocity its S,
/// A = (w + u) x S and whether it turns with the link; per coordinate its twist, Psi' and Psi'';
/// the link's v and a.
template <class T>
struct tree_jointed_root {
  std::size_t columns, directions;
  int velocity[6], coordinate[7];
  bool turns[6];
  T S[6][6], A[6][6], twist[7][6], dS[7][6], ddS[7][6], v[6], a[6];
};

/// The root joint's own pairs, from the whole tree's composite inertia C, force, momentum P and bias
/// D: a row r of a column that turns with the link takes a direction d as Psi''_d . C S_r +
/// Psi'_d . B^T S_r, a row that keeps the parent's axes as S_r . G_d, G_d = T_d x* F + C Psi''_d
/// + D Psi'_d + Psi'_d x* P; a column c as A_c . C S_r + S_c . B^T S_r.
template <class T>
void tree_root_pairs(const tree_jointed_root<T>& root, const T* C, const T* force, const T* P, const T* D,
                     std::size_t nq, std::size_t W, T* F) {
  T CS[6][6], BS[6][6], G[7][6];
  for (std::size_t c = 0; c < root.columns; ++c) {
    T DS[6], SP[6];
    tree_inertia_times(C, root.S[c], CS[c]);
    tree_bias_times(D, root.S[c], DS);
    tree_force_cross(root.S[c], P, SP);
    for (int k = 0; k < 6; ++k) BS[c][k] = DS[k] - SP[k];
  }
  for (std::size_t d = 0; d < root.directions; ++d) {
    T TF[6], Cdd[6], Dd[6], dP[6];
    tree_force_cross(root.twist[d], force, TF);
    tree_inertia_times(C, root.ddS[d], Cdd);
    tree_bias_times(D, root.dS[d], Dd);
    tree_force_cross(root.dS[d], P, dP);
    for (int k = 0; k < 6; ++k) G[d][k] = TF[k] + Cdd[k] + Dd[k] + dP[k];
  }
  for (std::size_t r = 0; r < root.columns; ++r) {
    T* row = F + std::size_t(root.velocity[r])*W;
    for (std::size_t d = 0; d < root.directions; ++d) {
      T& x = row[root.coordinate[d]];
      x = x + (root.turns[r] ? tree_power(root.ddS[d], CS[r]) + tree_power(root.dS[d], BS[r])
                             : tree_power(root.S[r], G[d]));
    }
    for (std::size_t c = 0; c < root.columns; ++c) {
      T& x = row[nq + std::size_t(root.velocity[c])];
      x = x + tree_power(root.A[c], CS[r]) + tree_power(root.S[c], BS[r]);
    }
  }
}

/// The tables of a tree whose joints' velocities all turn with their links (hinges, slides, ball
/// joints), which the generated code fills: each link's parent, its joint's columns (velocities) and
/// directions (coordinates), both 0 for a fixed link and for a root link whose joint is one of the
/// Roots jointed ones (root_joint giving it, root_link its link); per column its velocity, its
/// twist in the link's coordinates (axis; origin velocity) and rate; per direction its coordinate
/// and, where a link may have several columns (Columns > 1), its twist's weights over them; the link's turn, offset and its bodies'
/// inertia about its origin. With Columns = 1 every joint is a hinge or a slide, its direction's
/// twist its column's.
template <std::size_t L, std::size_t Columns, std::size_t Directions, std::size_t Roots, class T>
struct tree_link_tables {
  const int* parent;
  const int* columns;
  const int* directions;
  const int (*velocity)[Columns];
  const int (*coordinate)[Directions];
  T turn[L][9], offset[L][3], column[L][Columns][6], rate[L][Columns], inertia[L][10], gravity[3];
  T weight[Columns > 1 ? L : 1][Directions][Columns];
  int root_link[Roots > 0 ? Roots : 1];
  tree_jointed_root<T> root_joint[Roots > 0 ? Roots : 1];  // their motion at the accelerations
  // the joint of link i when it is a jointed root, else null
  const tree_jointed_root<T>* jointed(std::size_t i) const {
    for (std::size_t r = 0; r != Roots; ++r)
      if (std::size_t(root_link[r]) == i) return &root_joint[r];
    return nullptr;
  }
  // the motion (a twist or an acceleration) link i hangs from: its parent's in `links`, its jointed
  // root's (`of_root`: &tree_jointed_root<T>::v or ::a), or the world's (at rest; falling against gravity)
  const T* motion_above(std::size_t i, const T (*links)[6], T (tree_jointed_root<T>::*of_root)[6], const T* world) const {
    if (parent[i] >= 0) return links[parent[i]];
    const tree_jointed_root<T>* root = jointed(i);
    return root ? root->*of_root : world;
  }
  // whether link i has a column c, a direction d: bounded by the tables' extents, so that the loops
  // of a tree of hinges (one column) compile as its one column's code
  bool has_column(std::size_t i, int c) const { return c < int(Columns) && c < columns[i]; }
  bool has_direction(std::size_t i, int d) const { return d < int(Directions) && d < directions[i]; }
};

/// The bodies' M (n x n, row-major) and f = -tau from the pass's S, composite C and forces, added:
/// M_jk = S_j . C_k S_k for each column k and each column j of its link or a link above it (a jointed
/// root's columns above every link below it), f_k = -S_k . F_k; joints that follow one coordinate add
/// their shares, a pair of two of them twice.
template <std::size_t L, std::size_t Columns, std::size_t Directions, std::size_t Roots, class T>
void tree_mass_matrix_and_bias(const tree_link_tables<L, Columns, Directions, Roots, T>& tree, const T (&S)[L][Columns][6],
                               const T (&C)[L][10], const T (&force)[L][6], std::size_t n, T* M, T* f) {
  auto add = [&](std::size_t j, std::size_t k, const T& x) {
    M[j*n + k] = M[j*n + k] + x;
    if (j != k) M[k*n + j] = M[k*n + j] + x;
  };
  for (std::size_t k = 0; k < L; ++k)
    for (int r = 0; tree.has_column(k, r); ++r) {
      const std::size_t vk = std::size_t(tree.velocity[k][r]);
      T CS[6];
      tree_inertia_times(C[k], S[k][r], CS);
      f[vk] = f[vk] - tree_power(S[k][r], force[k]);
      int top = int(k);
      for (int j = int(k); j >= 0; j = tree.parent[j]) {
        top = j;
        // of k's own link the columns up to r, each entry once
        for (int c = 0; tree.has_column(std::size_t(j), c) && (j != int(k) || c <= r); ++c) {
          const std::size_t vj = std::size_t(tree.velocity[j][c]);
          const T x = tree_power(S[j][c], CS);
          add(vj, vk, j != int(k) && vj == vk ? T(2)*x : x);
        }
      }
      if (const tree_jointed_root<T>* root = tree.jointed(std::size_t(top)))
        for (std::size_t c = 0; c < root->columns; ++c) add(std::size_t(root->velocity[c]), vk, tree_power(root->S[c], CS));
    }
  for (std::size_t j = 0; j != Roots; ++j) {
    const tree_jointed_root<T>& root = tree.root_joint[j];
    const std::size_t i = std::size_t(tree.root_link[j]);
    for (std::size_t c = 0; c < root.columns; ++c) {
      const std::size_t vc = std::size_t(root.velocity[c]);
      T CS[6];
      tree_inertia_times(C[i], root.S[c], CS);
      f[vc] = f[vc] - tree_power(root.S[c], force[i]);
      for (std::size_t d = 0; d <= c; ++d) add(std::size_t(root.velocity[d]), vc, tree_power(root.S[d], CS));
    }
  }
}

)";

// the pass's callers, after it
constexpr const char* bodies_gradient_template = R"(/// d tau/d(q, q') of the tree's bodies at the accelerations ddq, added into F (tree_gradient_pass).
template <std::size_t L, std::size_t Columns, std::size_t Directions, std::size_t Roots, class T>
void tree_bodies_gradient(const tree_link_tables<L, Columns, Directions, Roots, T>& tree, const T* ddq, std::size_t nq, std::size_t W,
                          T* F) {
  tree_gradient_pass<false>(tree, ddq, nq, W, F, 0, static_cast<T*>(nullptr), static_cast<T*>(nullptr), [] {});
}

)";

// tree_gradient_pass's recursion at q'' = 0 for M and f alone, where they go by the loops
constexpr const char* mass_matrix_template = R"(/// The bodies' M (n x n) and f = -tau at q'' = 0, added into M and f, for mass_matrix_and_forcing:
/// tree_gradient_pass's world recursion at q'' = 0 with only what M and f need (the jointed roots'
/// motion in the tables at q'' = 0 too), composite inertias and forces, and tree_mass_matrix_and_bias.
template <std::size_t L, std::size_t Columns, std::size_t Directions, std::size_t Roots, class T>
void tree_loops_mass_matrix_and_forcing(const tree_link_tables<L, Columns, Directions, Roots, T>& tree, std::size_t n, T* M, T* f) {
  const int* parent = tree.parent;
  T R[L][9], o[L][3], S[L][Columns][6], v[L][6], a[L][6], C[L][10], force[L][6];
  const T rest[6] = {T(0), T(0), T(0), T(0), T(0), T(0)};
  const T fall[6] = {T(0), T(0), T(0), -tree.gravity[0], -tree.gravity[1], -tree.gravity[2]};
  const T identity[9] = {T(1), T(0), T(0), T(0), T(1), T(0), T(0), T(0), T(1)};
  for (std::size_t i = 0; i < L; ++i) {
    tree_place(parent[i] < 0 ? identity : R[parent[i]], parent[i] < 0 ? rest : o[parent[i]], tree.turn[i], tree.offset[i],
               tree.column[i][0], tree.inertia[i], R[i], o[i], S[i][0], C[i]);
    const T* vp = tree.motion_above(i, v, &tree_jointed_root<T>::v, rest);
    const T* ap = tree.motion_above(i, a, &tree_jointed_root<T>::a, fall);
    // v = v_p + V, a = a_p + v_p x V at q'' = 0, the joint's velocity V = S s
    if (tree.columns[i] == 0) {
      for (int k = 0; k < 6; ++k) v[i][k] = vp[k], a[i][k] = ap[k];
    } else if constexpr (Columns == 1) {
      T dS[6];
      tree_motion_cross(vp, S[i][0], dS);
      const T s = tree.rate[i][0];
      for (int k = 0; k < 6; ++k) v[i][k] = vp[k] + s*S[i][0][k], a[i][k] = ap[k] + s*dS[k];
    } else {
      T V[6], vV[6];
      for (int k = 0; k < 6; ++k) V[k] = tree.rate[i][0]*S[i][0][k];
      for (int c = 1; tree.has_column(i, c); ++c) {
        tree_column_twist(R[i], o[i], tree.column[i][c], S[i][c]);
        for (int k = 0; k < 6; ++k) V[k] = V[k] + tree.rate[i][c]*S[i][c][k];
      }
      tree_motion_cross(vp, V, vV);
      for (int k = 0; k < 6; ++k) v[i][k] = vp[k] + V[k], a[i][k] = ap[k] + vV[k];
    }
    T P[6], Ca[6], vP[6];
    tree_inertia_times(C[i], v[i], P);
    tree_inertia_times(C[i], a[i], Ca);
    tree_force_cross(v[i], P, vP);
    for (int k = 0; k < 6; ++k) force[i][k] = Ca[k] + vP[k];
  }
  for (std::size_t i = L; i-- > 0;) {
    if (parent[i] < 0) continue;
    tree_add_into(C[parent[i]], C[i]);
    tree_add_into(force[parent[i]], force[i]);
  }
  tree_mass_matrix_and_bias(tree, S, C, force, n, M, f);
}

)";

// The link's pose R, o from its parent's and its turn E and offset r; its joint's twist S from the
// column (axis a; origin velocity b) in its own coordinates: (R a; o × R a + R b), the first column's
// here (tree_column_twist the others'); its inertia about the world origin from its own about its
// origin (m, h, J): (m, m o + R h, R J Rᵀ + m (|o|² 1 − o oᵀ) + 2 (o·R h) 1 − (R h oᵀ + o (R h)ᵀ)).
// Written out entry by entry, with the results in locals until the end: as loops over pointers that
// may alias, g++ -O2 neither unrolled nor kept them in registers (723 instructions per link of the
// 21-joint tree, 494 written out).
std::string tree_place_function() {
  std::string f = "// the link's pose, its joint's (first) twist and its inertia about the world origin (R J R^T shifted\n"
                  "// to the origin), from its parent's pose and its own constants\n"
                  "template <class T>\n"
                  "inline void tree_place(const T* Rp, const T* op, const T* E, const T* r, const T* column, const T* own, "
                  "T* R, T* o,\n                       T* S, T* C) {\n";
  auto line = [&](const std::string& text) { f += "  " + text + "\n"; };
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      line(fmt::format("const T R{0}{1} = Rp[{2}]*E[{1}] + Rp[{3}]*E[{4}] + Rp[{5}]*E[{6}];", i, j, 3 * i, 3 * i + 1,
                       3 + j, 3 * i + 2, 6 + j));
  for (int i = 0; i < 3; ++i)
    line(fmt::format("const T o{0} = op[{0}] + Rp[{1}]*r[0] + Rp[{2}]*r[1] + Rp[{3}]*r[2];", i, 3 * i, 3 * i + 1, 3 * i + 2));
  line("const T m = own[0], J00 = own[4], J01 = own[5], J02 = own[6], J11 = own[7], J12 = own[8], J22 = own[9];");
  const char* J[3][3] = {{"J00", "J01", "J02"}, {"J01", "J11", "J12"}, {"J02", "J12", "J22"}};
  for (int i = 0; i < 3; ++i) {
    line(fmt::format("const T s{0} = R{0}0*column[0] + R{0}1*column[1] + R{0}2*column[2];", i));
    line(fmt::format("const T b{0} = R{0}0*column[3] + R{0}1*column[4] + R{0}2*column[5];", i));
    line(fmt::format("const T h{0} = R{0}0*own[1] + R{0}1*own[2] + R{0}2*own[3];", i));
    for (int j = 0; j < 3; ++j)
      line(fmt::format("const T RJ{0}{1} = R{0}0*{2} + R{0}1*{3} + R{0}2*{4};", i, j, J[0][j], J[1][j], J[2][j]));
  }
  line("S[0] = s0; S[1] = s1; S[2] = s2;");
  line("S[3] = o1*s2 - o2*s1 + b0;");
  line("S[4] = o2*s0 - o0*s2 + b1;");
  line("S[5] = o0*s1 - o1*s0 + b2;");
  line("const T oo = o0*o0 + o1*o1 + o2*o2, oh2 = T(2)*(o0*h0 + o1*h1 + o2*h2);");
  line("const T c0 = m*o0 + h0, c1 = m*o1 + h1, c2 = m*o2 + h2;");
  line("C[0] = m; C[1] = c0; C[2] = c1; C[3] = c2;");
  const int rows[6] = {0, 0, 0, 1, 1, 2}, cols[6] = {0, 1, 2, 1, 2, 2};
  for (int k = 0; k < 6; ++k) {
    int i = rows[k], j = cols[k];
    // m o_i o_j + (R h)_i o_j + o_i (R h)_j = c_i o_j + o_i (R h)_j
    line(fmt::format("C[{0}] = RJ{1}0*R{2}0 + RJ{1}1*R{2}1 + RJ{1}2*R{2}2 - (c{1}*o{2} + o{1}*h{2}){3};", 4 + k, i, j,
                     i == j ? " + m*oo + oh2" : ""));
  }
  for (int i = 0; i < 3; ++i) line(fmt::format("R[{0}] = R{1}0; R[{2}] = R{1}1; R[{3}] = R{1}2;", 3 * i, i, 3 * i + 1, 3 * i + 2));
  line("o[0] = o0; o[1] = o1; o[2] = o2;");
  return f + "}\n\n";
}

std::string table(const std::vector<int>& entries) {
  std::string text;
  for (std::size_t i = 0; i < entries.size(); ++i) text += (i ? ", " : "") + std::to_string(entries[i]);
  return text;
}

// the tree's jointed root r: its link, its tables, constants
void declare_jointed_root(BodyWriter& w, const JointedRoot& root, std::size_t r) {
  const std::string joint = fmt::format("tree.root_joint[{}].", r);
  w.line(fmt::format("tree.root_link[{}] = {}; {}columns = {}; {}directions = {};", r, root.link, joint, root.velocity.size(), joint,
                     root.coordinate.size()));
  for (std::size_t c = 0; c < root.velocity.size(); ++c)
    w.line(fmt::format("{0}velocity[{1}] = {2}; {0}turns[{1}] = {3};", joint, c, root.velocity[c], root.turns[c] ? "true" : "false"));
  for (std::size_t d = 0; d < root.coordinate.size(); ++d) w.line(fmt::format("{}coordinate[{}] = {};", joint, d, root.coordinate[d]));
}

// the statements that set the tree's jointed roots' motion at the accelerations ddq
std::string root_motion_body(const Equations& e) {
  BodyWriter w(e);
  std::vector<ex> values;
  std::vector<std::string> targets;
  const std::vector<JointedRoot>& roots = e.gradient_loops()->roots;
  for (std::size_t r = 0; r < roots.size(); ++r) {
    const JointedRoot& root = roots[r];
    auto add = [&](const std::string& array, const std::array<ex, 6>& x) {
      for (std::size_t k = 0; k < 6; ++k)
        values.push_back(x[k]), targets.push_back(fmt::format("tree.root_joint[{}].{}[{}]", r, array, k));
    };
    auto add_rows = [&](const std::string& array, const std::vector<std::array<ex, 6>>& rows) {
      for (std::size_t i = 0; i < rows.size(); ++i) add(fmt::format("{}[{}]", array, i), rows[i]);
    };
    add_rows("S", root.S), add_rows("A", root.A), add_rows("twist", root.twist), add_rows("dS", root.dS), add_rows("ddS", root.ddS);
    add("v", root.v), add("a", root.a);
  }
  w.assign(values, targets);
  return without_unused_locals(w.finish(all_unused + std::string(" (void)ddq;")));
}

// L, Columns, Directions, Roots of detail::tree_link_tables: the links, the most columns and
// directions of one, the jointed roots
std::string tree_size(const Equations& e) {
  const TreeLinkTables& links = *e.gradient_loops();
  return fmt::format("{}, {}, {}, {}", links.parent.size(), links.most_columns(), links.most_directions(), links.roots.size());
}

// per link its `entries` (columns' velocities or directions' coordinates), padded with −1 to `most`
std::string padded_rows(const std::vector<std::vector<int>>& entries, std::size_t most) {
  std::string text;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    std::vector<int> row = entries[i];
    row.resize(most, -1);
    text += (i ? ", {" : "{") + table(row) + "}";
  }
  return text;
}

// per link how many `entries` it has
std::string counts(const std::vector<std::vector<int>>& entries) {
  std::vector<int> sizes;
  for (const std::vector<int>& row : entries) sizes.push_back(int(row.size()));
  return table(sizes);
}

// the statements that fill `tree`'s tables
std::string tree_tables_body(const Equations& e) {
  const TreeLinkTables& links = *e.gradient_loops();
  BodyWriter w(e);
  std::size_t L = links.parent.size(), columns = links.most_columns(), directions = links.most_directions();
  w.line(fmt::format("static constexpr int tree_parent[{}] = {{{}}};", L, table(links.parent)));
  w.line(fmt::format("static constexpr int tree_columns[{}] = {{{}}};", L, counts(links.velocity)));
  w.line(fmt::format("static constexpr int tree_directions[{}] = {{{}}};", L, counts(links.coordinate)));
  w.line(fmt::format("static constexpr int tree_velocity[{}][{}] = {{{}}};", L, columns, padded_rows(links.velocity, columns)));
  w.line(fmt::format("static constexpr int tree_coordinate[{}][{}] = {{{}}};", L, directions,
                     padded_rows(links.coordinate, directions)));
  w.line("tree.parent = tree_parent; tree.columns = tree_columns; tree.directions = tree_directions;");
  w.line("tree.velocity = tree_velocity; tree.coordinate = tree_coordinate;");
  std::vector<ex> values;
  std::vector<std::string> targets;
  auto add = [&](const std::string& entry, const ex& value) {
    values.push_back(value);
    targets.push_back("tree." + entry);
  };
  for (std::size_t i = 0; i < L; ++i) {
    for (std::size_t k = 0; k < 9; ++k) add(fmt::format("turn[{}][{}]", i, k), links.turn[i][k]);
    for (std::size_t k = 0; k < 3; ++k) add(fmt::format("offset[{}][{}]", i, k), links.offset[i][k]);
    // a fixed link's first column zero: tree_place reads it
    if (links.velocity[i].empty())
      for (std::size_t k = 0; k < 6; ++k) add(fmt::format("column[{}][0][{}]", i, k), 0);
    for (std::size_t c = 0; c < links.velocity[i].size(); ++c) {
      for (std::size_t k = 0; k < 6; ++k) add(fmt::format("column[{}][{}][{}]", i, c, k), links.column[i][c][k]);
      add(fmt::format("rate[{}][{}]", i, c), links.rate[i][c]);
    }
    // a tree of hinges and slides takes each direction's twist as its column's
    for (std::size_t d = 0; d < links.coordinate[i].size() && columns > 1; ++d)
      for (std::size_t c = 0; c < links.weight[i][d].size(); ++c) add(fmt::format("weight[{}][{}][{}]", i, d, c), links.weight[i][d][c]);
    for (std::size_t k = 0; k < 10; ++k) add(fmt::format("inertia[{}][{}]", i, k), links.inertia[i][k]);
  }
  for (unsigned k = 0; k < 3; ++k) add(fmt::format("gravity[{}]", k), links.gravity[k]);
  for (std::size_t r = 0; r < links.roots.size(); ++r) declare_jointed_root(w, links.roots[r], r);
  w.assign(values, targets);
  return without_unused_locals(w.finish(all_unused));
}

}  // namespace

std::string tree_gradient_loops_function(const Equations& e, bool with_mass_matrix_and_forcing) {
  if (!e.gradient_loops()) return "";
  std::string tree = "tree_link_tables<" + tree_size(e) + ", T>& tree";
  std::string root_motion =
      !e.gradient_loops()->roots.empty() ? function("/// The tree's jointed roots' motion at the accelerations ddq.\n",
                                          "void tree_root_motion(T t, const T* x, const T* ddq, const input_t<T>* u, const T* p, " + tree + ")",
                                          root_motion_body(e))
                               : "";
  const char* pass = e.gradient_loops()->most_columns() > 1 ? several_columns_gradient_pass() : one_column_gradient_pass();
  return "namespace detail {\n\n" + std::string(six_vector_helpers) + tree_place_function() + gradient_template + pass +
         bodies_gradient_template +
         (with_mass_matrix_and_forcing ? mass_matrix_template : "") +
         function("/// The tree's tables for the configuration x, written once for the functions that go through it.\n",
                  "void tree_tables(T t, const T* x, const input_t<T>* u, const T* p, " + tree + ")", tree_tables_body(e)) +
         root_motion + "}  // namespace detail\n\n";
}

void call_tree_tables(BodyWriter& w, const Equations& e) {
  w.line("detail::tree_link_tables<" + tree_size(e) + ", T> tree;");
  w.line("detail::tree_tables(t, x, u, p, tree);");
  call_root_motion(w, e);
}

void call_root_motion(BodyWriter& w, const Equations& e) {
  if (!e.gradient_loops()->roots.empty()) w.line("detail::tree_root_motion(t, x, ddq, u, p, tree);");
}

void call_tree_mass_matrix_and_forcing(BodyWriter& w, const Equations& e) {
  std::size_t n = e.num_velocities();
  if (!e.gradient_loops()->roots.empty()) w.line(fmt::format("const T ddq[{}] = {{}};", n));  // the roots' motion at q'' = 0
  call_tree_tables(w, e);
  w.line(fmt::format("tree_loops_mass_matrix_and_forcing(tree, {}, M, f);", n));
}

void call_tree_gradient_loops(BodyWriter& w, const Equations& e, std::size_t coordinates, std::size_t width) {
  call_tree_tables(w, e);
  w.line(fmt::format("tree_bodies_gradient(tree, ddq, {}, {}, F);", coordinates, width));
}

}  // namespace eomgen
