/// @file Comparing two derivations entry by entry, in levels: `identical` (the same
/// canonical text, after renaming), `equivalent` (the difference is zero: by exact
/// simplification, else at random points in 50-digit arithmetic, so trigonometric
/// identities count), or `different` with the size of the difference. Beyond entries:
/// `same_motion` when M and f differ but the accelerations they give agree (rows
/// scaled or combined, another derivation method, other velocities).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "compare/derivation_record.hpp"

namespace eomgen {

struct DiffOptions {
  std::vector<std::pair<std::string, std::string>> renames;  // old name → new name
  /// numeric level: |old − new| ≤ tolerance · max(|old|, |new|, the size of their terms), the terms'
  /// size the sum of their absolute values (of a sum that cancels to rounding, the size it rounds at)
  double tolerance = 1e-30;
  int samples = 16;
  unsigned seed = 20261123;  // fixed: the same inputs give the same verdict
};

struct EntryComparison {
  std::string entry, status, decided_by;  // identical | equivalent | different; text | symbolic | numeric
  std::string old_text, new_text;  // long numbers as 17-digit decimals
  double max_abs_difference = 0, max_rel_difference = 0;
  bool beyond_the_decimals = false;  // the texts agree where the exact numbers differ
};

struct DefaultChange {
  std::string name;
  double old_value, new_value;
};

/// A tree's intermediate quantity (world poses, composite inertias: derived equations of robots)
/// whose definition differs, by name; the text of a side that lacks it is empty.
struct IntermediateChange {
  std::string name, old_text, new_text;
  bool beyond_the_decimals = false;  // as EntryComparison's
};

struct EquationDiff {
  std::string verdict;  // identical | equivalent | equal_on_samples (branches: abs, atan2, roots) | same_motion | different
  std::string old_path, new_path;
  std::vector<std::string> added, removed;  // symbols: "parameter k", "output tip_z"
  std::vector<std::pair<std::string, std::string>> renamed;
  std::vector<DefaultChange> defaults_changed;
  std::vector<EntryComparison> entries;  // the entries both sides have, in the new side's order
  std::vector<std::string> entries_only_old, entries_only_new;  // e.g. Appell's S and s[...] against Lagrange II
  std::string motion;                    // how the accelerations compared, when M or f differ
  /// the intermediates whose definitions differ, in the new side's order of computation and then the
  /// old side's own: what changed in the tree, where the entries' texts are the same
  std::vector<IntermediateChange> intermediates_changed;
};

/// Compares `old_side` with `new_side`. An expression that does not read back (a
/// hand-edited JSON) is a mistake in `diagnostics`.
EquationDiff compare_derivations(const DerivationRecord& old_side, const DerivationRecord& new_side, const DiffOptions& options,
                                 Diagnostics& diagnostics);

}  // namespace eomgen
