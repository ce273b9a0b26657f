// eomgen import FILE.xml|FILE.urdf [-o MODEL.toml] [--name NAME] [--free-base] [--masses-from-shapes]
// [--right-angles-within RAD] [--joint-torques]: a robot description as a model file.
#include <iostream>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "common/output_file.hpp"
#include "import/model_writer.hpp"

namespace eomgen::cli {

namespace {

int import_robot(const std::string& file, const std::string& output, const std::string& name, RobotReading reading) {
  Diagnostics diagnostics;
  std::optional<std::string> text = imported_model_text(file, diagnostics, false, name, reading);
  if (report_diagnostics(diagnostics, file)) return exit_user_error;
  if (output.empty()) {
    std::cout << *text;
    return exit_success;
  }
  if (std::string failure = write_file_atomically(output, *text); !failure.empty()) {
    std::cerr << "eomgen: " << failure << "\n";
    return exit_user_error;
  }
  std::cerr << fmt::format("eomgen: imported {} into {}\n", file, output);
  return exit_success;
}

}  // namespace

Command add_import_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("import", "Write a robot description (MJCF or URDF, read by MuJoCo's compiler) as a model file");
  auto file = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  auto name = std::make_shared<std::string>();
  cmd->add_option("file", *file, "The robot's MJCF (.xml) or URDF (.urdf) file; every command also takes one directly")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", *output, "The model file to write (default: standard output)");
  cmd->add_option("--name", *name, "The model's name, a C++ identifier (default: the robot's, or the file's)");
  auto free_base = std::make_shared<bool>(false);
  cmd->add_flag("--free-base", *free_base,
                "Hang the robot's base from the world by a free joint (position, unit quaternion, angular velocity), "
                "as a humanoid's or a quadruped's base floats. URDF: the root link, which URDF fixes to the world (a robot "
                "mounted on a link named world by a fixed joint floats by that joint); MJCF: the body in <worldbody> without "
                "joints that carries the robot");
  auto masses_from_shapes = std::make_shared<bool>(false);
  cmd->add_flag("--masses-from-shapes", *masses_from_shapes,
                "URDF: weigh each link without an <inertial> by its <collision> shapes at the density of water, as MuJoCo reads a URDF; "
                "URDF has such a link massless");
  auto right_angles_within = std::make_shared<double>(0);
  cmd->add_option("--right-angles-within", *right_angles_within,
                  "Write each body's turn that is within RAD radians of a right angle as that right angle (a file's "
                  "rpy = \"1.5708 0 0\" as exactly pi/2): the generated code then need not multiply by those turns, and "
                  "the robot moves by up to RAD; the import notes the turns near a right angle (default 0: as read)")
      ->type_name("RAD")
      ->check(CLI::Range(0.0, 0.1));
  auto joint_torques = std::make_shared<bool>(false);
  cmd->add_flag("--joint-torques", *joint_torques,
                "Drive every hinge and slide by an input of its own, tau_JOINT: a torque or force on its coordinate, as "
                "Pinocchio's tau (a URDF robot has no actuators MuJoCo reads), besides the file's actuators");
  return [cmd, file, output, name, free_base, masses_from_shapes, right_angles_within, joint_torques]() -> int {
    if (!cmd->parsed()) return -1;
    return import_robot(*file, *output, *name, {*free_base, *masses_from_shapes, *right_angles_within, *joint_torques});
  };
}

}  // namespace eomgen::cli
