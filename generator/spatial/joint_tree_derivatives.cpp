#include "spatial/joint_tree_derivatives.hpp"

#include <fmt/format.h>

#include "kinematics/vector3.hpp"
#include "model/recursive_frames.hpp"

namespace eomgen {

using GiNaC::ex;

namespace {

using eomgen::operator+;
using eomgen::operator-;

// a motion (ω; v_O) or a force (n_O; f) in world Plücker coordinates, about the world origin O
struct Six {
  Vector3 top{0, 0, 0}, bottom{0, 0, 0};
  const ex& operator[](unsigned k) const { return k < 3 ? top[k] : bottom[k - 3]; }
};

Six operator+(const Six& a, const Six& b) { return {a.top + b.top, a.bottom + b.bottom}; }
Six scaled(const ex& s, const Six& a) { return {eomgen::scaled(s, a.top), eomgen::scaled(s, a.bottom)}; }

Six motion_cross(const Six& m, const Six& x) {
  return {cross(m.top, x.top), cross(m.top, x.bottom) + cross(m.bottom, x.top)};
}

Six force_cross(const Six& m, const Six& f) {
  return {cross(m.top, f.top) + cross(m.bottom, f.bottom), cross(m.top, f.bottom)};
}

// the components' dot product: a motion's power against a force
ex power(const Six& m, const Six& f) { return dot(m.top, f.top) + dot(m.bottom, f.bottom); }

// mass, first moment h = m c and inertia J about O
struct SpatialInertia {
  ex mass = 0;
  Vector3 first{0, 0, 0};
  GiNaC::matrix J{3, 3};
};

// the momentum of the twist x: (J ω + h × v; m v − h × ω)
Six apply(const SpatialInertia& I, const Six& x) {
  return {times(I.J, x.top) + cross(I.first, x.bottom), eomgen::scaled(I.mass, x.bottom) - cross(I.first, x.top)};
}

Six times(const GiNaC::matrix& B, const Six& x, bool transposed = false) {
  Six y;
  for (unsigned r = 0; r < 6; ++r) {
    ex sum = 0;
    for (unsigned c = 0; c < 6; ++c) sum += (transposed ? B(c, r) : B(r, c)) * x[c];
    (r < 3 ? y.top[r] : y.bottom[r - 3]) = sum;
  }
  return y;
}

class Gradient {
 public:
  Gradient(const std::vector<TreeLink>& links, std::vector<Intermediate>& out) : links_(links), out_(out) {
    std::size_t n = links.size();
    R_.resize(n, GiNaC::matrix(3, 3));
    origin_.resize(n);
    S_.resize(n), v_.resize(n), a_.resize(n), dS_.resize(n), ddS_.resize(n);
    inertia_.resize(n), force_.resize(n), momentum_.resize(n);
    D_.resize(n, GiNaC::matrix(6, 6));
  }

  // world poses, twists, accelerations and the links' own inertias, forces and B, parents first
  void forward(const Vector3& gravity, const std::vector<ex>& ddq) {
    Six rest, fall{{0, 0, 0}, eomgen::scaled(-1, gravity)};
    for (std::size_t i = 0; i < links_.size(); ++i) {
      const TreeLink& l = links_[i];
      bool root = l.parent < 0;
      std::size_t p = root ? 0 : std::size_t(l.parent);
      const Six& vp = root ? rest : v_[p];
      const Six& ap = root ? fall : a_[p];
      GiNaC::matrix R = root ? l.turn : R_[p].mul(l.turn);
      for (unsigned a = 0; a < 3; ++a)
        for (unsigned b = 0; b < 3; ++b)
          R_[i](a, b) = name(i, fmt::format("gR{}{}", a, b), R(a, b));
      origin_[i] = named(i, "go", root ? l.offset : origin_[p] + eomgen::times(R_[p], l.offset));
      v_[i] = vp;
      a_[i] = ap;
      if (l.velocity >= 0) {
        Vector3 s = eomgen::times(R_[i], l.axis);
        S_[i] = named(i, "gS", Six{s, cross(origin_[i], s) + eomgen::times(R_[i], l.origin_velocity)});
        v_[i] = named(i, "gv", vp + scaled(l.rate, S_[i]));
        a_[i] = named(i, "ga", ap + scaled(ddq[std::size_t(l.velocity)], S_[i]) + scaled(l.rate, motion_cross(v_[i], S_[i])));
        dS_[i] = named(i, "gdS", motion_cross(vp, S_[i]));
        ddS_[i] = named(i, "gddS", motion_cross(ap, S_[i]) + motion_cross(vp, dS_[i]));
      }
      own_inertia(i);
    }
  }

  // composite inertias, forces and B, leaves first
  void backward() {
    for (std::size_t i = links_.size(); i-- > 0;) {
      for (std::size_t c = i + 1; c < links_.size(); ++c) {
        if (links_[c].parent != int(i)) continue;
        inertia_[i].mass += inertia_[c].mass;
        inertia_[i].first = inertia_[i].first + inertia_[c].first;
        inertia_[i].J = inertia_[i].J.add(inertia_[c].J);
        force_[i] = force_[i] + force_[c];
        momentum_[i] = momentum_[i] + momentum_[c];
        D_[i] = D_[i].add(D_[c]);
      }
      inertia_[i] = named(i, "gC", inertia_[i]);
      force_[i] = named(i, "gF", force_[i]);
      momentum_[i] = named(i, "gP", momentum_[i]);
      for (unsigned r = 0; r < 6; ++r)
        for (unsigned c = r; c < 6; ++c) D_[i](r, c) = D_[i](c, r) = name(i, fmt::format("gD{}{}", r, c), D_[i](r, c));
    }
  }

  InverseDynamicsGradient pairs(std::size_t n) {
    InverseDynamicsGradient g{GiNaC::matrix(unsigned(n), unsigned(n)), GiNaC::matrix(unsigned(n), unsigned(n))};
    std::vector<Six> IS(links_.size()), BS(links_.size()), G(links_.size()), H(links_.size());
    for (std::size_t j = 0; j < links_.size(); ++j) {
      if (links_[j].velocity < 0) continue;
      // B^C x = D x + x ×* P, so B^C S = D S + S ×* P and B^Cᵀ S = D S − S ×* P
      Six DS = named(j, "gDS", times(D_[j], S_[j])), SP = named(j, "gSP", force_cross(S_[j], momentum_[j]));
      IS[j] = named(j, "gIS", apply(inertia_[j], S_[j]));
      BS[j] = named(j, "gBS", DS + scaled(-1, SP));
      G[j] = named(j, "gG", force_cross(S_[j], force_[j]) + apply(inertia_[j], ddS_[j]) + times(D_[j], dS_[j]) +
                                force_cross(dS_[j], momentum_[j]));
      H[j] = named(j, "gH", apply(inertia_[j], scaled(2, dS_[j])) + DS + SP);
    }
    for (std::size_t k = 0; k < links_.size(); ++k) {
      if (links_[k].velocity < 0) continue;
      unsigned row = unsigned(links_[k].velocity);
      for (int j = int(k); j >= 0; j = links_[std::size_t(j)].parent) {
        std::size_t at = std::size_t(j);
        if (links_[at].velocity < 0) continue;
        unsigned column = unsigned(links_[at].velocity);
        // k carries j's joint (k in Φ_j)
        g.coordinates(row, column) = (power(ddS_[at], IS[k]) + power(dS_[at], BS[k])).expand();
        g.velocities(row, column) = (2 * power(dS_[at], IS[k]) + power(S_[at], BS[k])).expand();
        if (at == k) continue;
        // j above k: τ_j sees Φ_k's change through F_j only
        g.coordinates(column, row) = power(S_[at], G[k]).expand();
        g.velocities(column, row) = power(S_[at], H[k]).expand();
      }
    }
    return g;
  }

 private:
  // the link's bodies about O: J_O = Σ R J_c Rᵀ + m(|c|² 1 − c cᵀ) with c = o + R c_local; then
  // f = I a + v ×* I v, and B x = I (x × v) + x ×* (I v) + v ×* (I x) as D x + x ×* P with the momentum
  // P = I v and the symmetric D = −(K + Kᵀ), K = I (v×), since v ×* = −(v×)ᵀ: 21 entries to carry up
  // the tree instead of 36
  void own_inertia(std::size_t i) {
    const TreeLink& l = links_[i];
    SpatialInertia I;
    for (std::size_t k = 0; k < l.bodies.size(); ++k) {
      const TreeLink::Body& b = l.bodies[k];
      Vector3 c = named(i, fmt::format("gB{}c", k), origin_[i] + eomgen::times(R_[i], b.center));
      GiNaC::matrix RJ = R_[i].mul(b.inertia);
      for (unsigned r = 0; r < 3; ++r)
        for (unsigned s = 0; s < 3; ++s) RJ(r, s) = name(i, fmt::format("gB{}RJ{}{}", k, r, s), RJ(r, s));
      ex cc = dot(c, c);
      for (unsigned r = 0; r < 3; ++r)
        for (unsigned s = 0; s < 3; ++s) {
          ex turned = 0;
          for (unsigned t = 0; t < 3; ++t) turned += RJ(r, t) * R_[i](s, t);
          I.J(r, s) += turned + b.mass * ((r == s ? cc : ex(0)) - c[r] * c[s]);
        }
      I.mass += b.mass;
      I.first = I.first + eomgen::scaled(b.mass, c);
    }
    if (l.bodies.empty()) return;
    inertia_[i] = named(i, "gI", I);
    Six Iv = named(i, "gIv", apply(inertia_[i], v_[i]));
    force_[i] = apply(inertia_[i], a_[i]) + force_cross(v_[i], Iv);
    momentum_[i] = Iv;
    GiNaC::symbol x[6];
    Six X{{x[0], x[1], x[2]}, {x[3], x[4], x[5]}};
    Six Dx = apply(inertia_[i], motion_cross(X, v_[i])) + force_cross(v_[i], apply(inertia_[i], X));
    for (unsigned r = 0; r < 6; ++r) {
      ex row = Dx[r].expand();
      for (unsigned c = r; c < 6; ++c) D_[i](r, c) = D_[i](c, r) = row.coeff(x[c]);
    }
  }

  ex name(std::size_t i, const std::string& label, const ex& value) {
    return intermediate(out_, fmt::format("{}.{}", links_[i].name, label), fmt::format("k_{}_{}", links_[i].name, label),
                        value.expand());
  }
  Vector3 named(std::size_t i, const std::string& label, const Vector3& x) {
    return {name(i, label + "_x", x[0]), name(i, label + "_y", x[1]), name(i, label + "_z", x[2])};
  }
  Six named(std::size_t i, const std::string& label, const Six& x) {
    return {named(i, label + "w", x.top), named(i, label + "v", x.bottom)};
  }
  SpatialInertia named(std::size_t i, const std::string& label, const SpatialInertia& I) {
    SpatialInertia J;
    J.mass = name(i, label + "m", I.mass);
    J.first = named(i, label + "h", I.first);
    for (unsigned r = 0; r < 3; ++r)
      for (unsigned s = r; s < 3; ++s) J.J(r, s) = J.J(s, r) = name(i, fmt::format("{}J{}{}", label, r, s), I.J(r, s));
    return J;
  }

  const std::vector<TreeLink>& links_;
  std::vector<Intermediate>& out_;
  std::vector<GiNaC::matrix> R_;
  std::vector<Vector3> origin_;
  std::vector<Six> S_, v_, a_, dS_, ddS_;
  std::vector<SpatialInertia> inertia_;
  std::vector<Six> force_, momentum_;
  std::vector<GiNaC::matrix> D_;  // symmetric
};

}  // namespace

InverseDynamicsGradient joint_tree_gradient(const std::vector<TreeLink>& links, const Vector3& gravity,
                                            const std::vector<ex>& ddq, std::size_t n, std::vector<Intermediate>& out) {
  Gradient g(links, out);
  g.forward(gravity, ddq);
  g.backward();
  return g.pairs(n);
}

}  // namespace eomgen
