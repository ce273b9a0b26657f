/// @file The coordinates each link's recursion runs in (Featherstone's joint frames, Hiller
/// §3.9's freedom to choose the body axes): for a revolute or prismatic joint about a numeric
/// axis, axes whose z is the joint's axis, and for a revolute or ball joint an origin on the
/// joint's anchor. The joint's motion is then q̇ along z with no velocity of the origin, so that
/// τ = N_z, M_ji = L_z, and the link's turn is K·rot_z(q) with K constant: the cost of an oblique
/// axis is paid once, in K, at generation.
///
/// An axis along ±x, ±y or ±z gets a signed permutation, exact; an oblique one axes computed in
/// 40-digit floating point (they involve square roots of no known angle) and rounded to exact
/// multiples of 10^-36, beyond the precision of any scalar a header is instantiated with, so
/// that everything after is exact rational arithmetic and the output the same on every run
/// (floating-point sums would depend on the order GiNaC keeps terms in). Rounding residues are
/// cut to exact 0 and ±1 where the exact value is one.
#pragma once

#include <ginac/ginac.h>

#include "model/model.hpp"

namespace eomgen {

struct JointFrame {
  GiNaC::matrix axes{3, 3};   // C: the recursion's axes as columns, in the frame's coordinates
  Vector3 origin{0, 0, 0};    // o: the recursion's origin, in the frame's coordinates
  bool floating = false;      // C is an oblique axis's, orthonormal to 36 digits
};

/// The joint frame of a link with joint `joint` (identity axes at the frame's origin unless the
/// joint is revolute, prismatic or ball as above).
JointFrame joint_frame(const FrameLink::Joint& joint);

/// x, a number, cut to exact 0 when it is below 1e-30·|scale|; x unchanged when it is not a number.
GiNaC::ex without_rounding_residue(const GiNaC::ex& x, const GiNaC::ex& scale);

/// x without the terms of a sum whose numeric coefficients are below 1e-30 of its largest: the
/// residue of axes that are orthonormal to 36 digits.
GiNaC::ex without_small_terms(const GiNaC::ex& x);

/// A constant entry of a rotation matrix, such as cos(7/10), or one that the approximate axes of an
/// oblique joint entered: 0 or ±1 when within 1e-30 of one, else the nearest multiple of 10^-36;
/// x itself when it is symbolic, or rational and not `approximate`.
GiNaC::ex rotation_entry(const GiNaC::ex& x, bool approximate);

/// x, a number, to 36 digits below the leading one of `scale` (x unchanged when either is not
/// a number): keeps the exact numbers that the axes multiply from growing through the tree.
GiNaC::ex rounded_to(const GiNaC::ex& x, const GiNaC::ex& scale);

}  // namespace eomgen
