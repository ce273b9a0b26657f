/// @file The eomgen command line: one subcommand per job, exit statuses as in DESIGN.md.
#include <csignal>
#include <iostream>

#include "cli/commands.hpp"
#include "common/deadline.hpp"
#include "common/version.hpp"

int main(int argc, char** argv) {
  using namespace eomgen::cli;
  // past a file-size limit (ulimit -f) a write fails with EFBIG instead of killing the process,
  // so the half-written temporary file is removed and the failure said
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"eomgen: equations of motion from a model file, derived symbolically"};
  app.set_version_flag("--version", std::string("eomgen ") + eomgen::version_string);
  app.require_subcommand(1);
  // options the subcommands do not know are the main command's: --max-seconds after any command
  app.fallthrough();
  double max_seconds = eomgen::default_derivation_seconds;
  app.add_option("--max-seconds", max_seconds,
                 "Stop a derivation that runs longer than this, with exit status 2 (0: no limit)")
      ->default_val(eomgen::default_derivation_seconds)
      ->check(eomgen::cli::positive_number(true));
  bool timings = false;
  app.add_flag("--timings", timings, "Print the wall time of each stage of the derivation and the header's writing");
  double max_memory = eomgen::default_derivation_gigabytes();
  app.add_option("--max-memory", max_memory,
                 "Stop a derivation whose process grows past this many GB of memory, with exit status 2 (0: no limit; "
                 "default: the smaller of 8 GB and three quarters of the machine's memory)")
      ->check(eomgen::cli::positive_number(true));
  std::vector<Command> commands = {add_derive_command(app), add_generate_command(app), add_simulate_command(app), add_stability_command(app),
                                  add_sweep_command(app), add_bench_command(app), add_run_command(app),
                                  add_diff_command(app), add_check_integral_command(app), add_linear_command(app),
                                  add_scene_command(app), add_fmu_command(app), add_ensemble_command(app),
                                  add_import_command(app), add_animate_command(app)};
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int status = app.exit(e);
    return status == 0 ? exit_success : exit_user_error;
  }
  eomgen::set_derivation_time_limit(max_seconds);
  eomgen::set_derivation_memory_limit(max_memory);
  if (timings) eomgen::keep_stage_timings();
  try {
    for (const Command& command : commands)
      if (int status = command(); status >= 0) {
        if (timings) std::cerr << "eomgen: time by stage\n" << eomgen::stage_timings();
        return status;
      }
    return exit_user_error;
  } catch (const std::exception& e) {
    std::cerr << "eomgen: internal error: " << e.what()
              << "\nThis is a bug in eomgen. Please report it with the model file and the command line.\n";
    return exit_internal_error;
  }
}
