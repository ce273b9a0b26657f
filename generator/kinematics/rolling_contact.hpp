/// @file A thin disk rolling without slipping on the ground plane z = 0 (Hiller §4.3):
/// the contact point, the holonomic contact condition and the two no-slip conditions.
#pragma once

#include <optional>

#include "model/model.hpp"

namespace eomgen {

/// With n the disk's axis in inertial components, the contact point is the lowest point
/// of the rim: ρ = r·(n_z·n − e_z)/√(1 − n_z²) from the centre c. The disk touches the
/// plane when c_z + ρ_z = c_z − r·√(1 − n_z²) = 0, and rolls without slipping when its
/// material point there is at rest: v_c + ω × ρ = 0 in x and y (z follows from the contact).
struct RollingContact {
  GiNaC::ex height;             // c_z − r·√(1 − n_z²): zero when the coordinates already keep it on the plane
  Vector3 contact;              // the contact point, inertial
  GiNaC::ex slip_x, slip_y;     // x and y velocity of the material point at the contact, linear in q'
};

/// `axis` in body components (any length; the model builder admits only x, y or z); √(1 − n_z²)
/// is written as |cos a| or |sin a| when n_z = ±sin a or ±cos a, with the sign it has at the
/// initial state. Nothing when the disk lies flat at the initial state (its axis vertical): then
/// no point of the rim is the lowest.
std::optional<RollingContact> rolling_contact(const Vector3& center, const Rotation& rotation, const Vector3& axis,
                               const GiNaC::ex& radius, const Symbols& symbols);

}  // namespace eomgen
