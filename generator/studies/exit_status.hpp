/// @file The exit statuses of DESIGN.md, which every study returns to its command.
#pragma once

namespace eomgen::studies {

enum ExitStatus { exit_success = 0, exit_internal_error = 1, exit_user_error = 2, exit_numerical_failure = 3 };

}  // namespace eomgen::studies
