/// @file MuJoCo 2.3's gravcomp on a <body>, which MuJoCo 2.2.2's schema refuses: the part c of the
/// body's weight that MuJoCo takes off by a force −c·m·g at its centre of mass, among the passive
/// forces (off with them, and without gravity). The file is read without the attribute
/// (carried_newer_mjcf.hpp), so the parts are read from its text first, and the import carries them
/// as that force (model_writer.hpp).
#pragma once

#include <string>
#include <vector>

#include <mujoco/mujoco.h>

#include "import/robot.hpp"

namespace eomgen {

/// One body's gravcomp as its file states it.
struct GravityCompensation {
  std::string body;         // the body's name; empty for an unnamed body
  int ordinal = 0;          // its place among the <body> elements of its file, from 0
  std::size_t source = 0;   // its file: 0 the file read, else one that file includes
  double part = 0;          // c
};

/// What the file and those it includes state.
struct GravityCompensations {
  std::vector<GravityCompensation> bodies;  // those with a gravcomp other than 0, in the texts' order
  int body_elements = 0;                    // the <body> elements of the file read itself
  bool includes = false;                    // it includes other files
};

/// `out` with the gravcomp of every <body> of the file text `mjcf` (`source` as above); a value that
/// is not a number is taken as 0 (MuJoCo's schema refuses it before this is read).
void read_gravity_compensations(const std::string& mjcf, std::size_t source, GravityCompensations& out);

/// Whether MuJoCo's error is its schema refusing gravcomp.
bool refuses_gravcomp(const std::string& mujoco_error);

/// `r`'s bodies with their parts of `found`, each body found by its name in `m`, an unnamed one by its
/// place where the file includes none and its <body> elements are all of `m`'s bodies; a note says
/// what is carried, a warning what could not be placed. Nothing where `m` has no gravity or its
/// passive forces are switched off (a note then).
void apply_gravity_compensation(const mjModel* m, const GravityCompensations& found, Robot& r);

}  // namespace eomgen
