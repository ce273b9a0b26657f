/// @file `eomgen diff OLD NEW`: the derived equations of two versions of a model (model
/// files, robot files or derived-equations JSON) compared entry by entry; and `--self OLD_EOMGEN`,
/// what another eomgen executable derives from the same models against this one.
/// Exit status like diff and cmp: 0 the same, 1 different, 2 a mistake in an input,
/// 4 an internal error (1 is taken by "different").
#include "cli/commands.hpp"
#include "studies/diff_study.hpp"

namespace eomgen::cli {

Command add_diff_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("diff", "Compare the derived equations of two versions of a model; exit 0 the same, "
                                             "1 different, 2 a mistake, 4 an internal error");
  auto o = std::make_shared<ComparisonOptions>();
  cmd->add_option("INPUTS", o->inputs, "OLD NEW: model files (.toml), robot files (MJCF .xml, URDF .urdf: imported as "
                                       "eomgen import reads them) or derived-equations JSON (eomgen derive --format json, "
                                       "generated/*.json); with --self: model files or folders. Equations are written out "
                                       "in q up to 4 velocities; a larger tree is compared in its quantities (poses, "
                                       "inertias), which the report names where they differ")->required();
  cmd->add_option("--rename", o->renames, "A symbol renamed from OLD to NEW, one per flag: --rename k=stiffness");
  cmd->add_option("--tolerance", o->options.tolerance, "Numeric level: |old - new| <= T max(|old|, |new|, the size of their "
                  "terms) at every random point, in 50-digit arithmetic (default 1e-30)");
  cmd->add_option("--samples", o->options.samples, "Random points of the numeric level (default 16; the seed is fixed)");
  cmd->add_option("--self", o->self, "Another eomgen executable: compare what it derives from each model with what this "
                  "one derives, one line per model");
  cmd->add_flag("--region", o->region_is_enough, "Take equations equal on the sampled region as the same (exit 0): coordinates "
               "in (0.2, 1.3) and (-4, 4), velocities in (-2, 2), parameters 0.5 to 2 times their defaults; without it, "
               "an expression with branches (abs, atan2, a fractional power) equal there only exits 1");
  auto format = std::make_shared<std::string>("text");
  cmd->add_option("--format", *format, "text or json")->check(CLI::IsMember({"text", "json"}));
  return [cmd, o, format]() -> int {
    if (!cmd->parsed()) return -1;
    o->json = *format == "json";
    return diff(*o);
  };
}

}  // namespace eomgen::cli
