/// @file Mesh files an MJCF names that MuJoCo cannot read (a robot's XML copied without its
/// assets folder, an OBJ its reader rejects). A body's dynamics come from its <inertial>, or from
/// its geoms when it has none (MuJoCo's inertiafromgeom="auto"), meshes included: leaving a mesh
/// out could change a mass silently. So each unreadable file is given to MuJoCo as a placeholder,
/// a tetrahedron in its format, and the robot is compiled twice with tetrahedra of two sizes:
/// a body whose mass, centre or inertia differs between the two takes them from a mesh, and the
/// robot is refused naming it; otherwise the meshes only drew the robot, and it is read without
/// them. Geoms sized by a mesh (MJCF's fitted primitives) differ too, and are not drawn.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <mujoco/mujoco.h>

namespace eomgen {

/// A mesh file MuJoCo's message says it could not open or parse: its path as MuJoCo gives it, and
/// its format (STL, OBJ, MSH).
struct UnreadableMesh {
  std::string file, format;
};

/// The mesh file of MuJoCo 2.2.2's message, or nothing when it is about something else.
std::optional<UnreadableMesh> unreadable_mesh(const std::string& message);

/// A tetrahedron of edge `size` (metres) in the mesh's format, under its file name: what MuJoCo's
/// virtual file system gives it in place of the file. Nothing for a format without a placeholder (MSH).
std::optional<std::pair<std::string, std::string>> placeholder_mesh(const UnreadableMesh& mesh, double size);

/// What the placeholders of two sizes changed: the first body whose inertial quantities differ
/// (empty: none), and the geoms whose size or placement differ.
struct MeshDependence {
  std::string body;
  std::vector<int> geoms;
};

MeshDependence mesh_dependence(const mjModel* small, const mjModel* large);

}  // namespace eomgen
