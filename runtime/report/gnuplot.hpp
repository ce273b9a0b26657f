/// @file Running gnuplot: one quoting rule for paths and titles, one way to run a
/// script and report why it failed. Shared by every chart writer.
#pragma once

#include <string>

namespace eomgen::runtime {

/// A gnuplot single-quoted string ('' inside stands for ').
std::string gnuplot_quoted(const std::string& text);

/// Runs `script` through gnuplot, the script file named after `stem`; removes the
/// script and its log. Empty on success, else why it failed.
std::string run_gnuplot(const std::string& script, const std::string& stem);

}  // namespace eomgen::runtime
