/// @file `eomgen stability`: the equilibrium, its linearization split by force
/// type, eigenvalues, verdict, modes, Hurwitz test, the classical theorems that
/// apply, and with --symbolic the stability conditions in the parameters.
#pragma once

#include <string>
#include <vector>

namespace eomgen::studies {

struct StabilityOptions {
  std::string model;
  std::vector<std::string> at, sets;
  std::string symbolic;
  double period = 0;
  bool json = false;
};

/// The whole `eomgen stability` job for one set of options, printed; its exit status.
int stability(const StabilityOptions& options);
/// `eomgen stability MODEL` (equilibrium searched from the initial values), as text.
int stability_of_model(const std::string& model);

}  // namespace eomgen::studies
