/// @file What a command needs to run on several ranks (distribute/ranks.hpp): the model
/// compiled once, by rank 0, and loaded from the cache by the others; and only rank 0
/// speaking.
#pragma once

#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "studies/loaded_problem.hpp"
#include "distribute/ranks.hpp"

namespace eomgen::studies {

/// Rank 0 derives and compiles first; the others follow once the header is in the cache,
/// or return rank 0's exit status when it failed (which rank 0 has said). When another
/// rank fails (a host without the compiler), rank 0 says so and every rank returns.
/// `choice` as load_problem's.
std::optional<int> load_on_every_rank(const distribute::Ranks& ranks, const std::string& model,
                                      const std::vector<std::string>& sets, LoadedProblem& out,
                                      const ModelChoice& choice = {});

/// Rank 0's answer to a question about the file system (an output file's folder), on every
/// rank: empty when rank 0 found nothing wrong.
std::string refusal_on_root(const distribute::Ranks& ranks, const std::function<std::string()>& check);

/// Silences std::cerr on every rank but 0 while it lives: the ranks meet the same mistakes,
/// and the user should read each once.
class QuietUnlessRoot {
 public:
  explicit QuietUnlessRoot(const distribute::Ranks& ranks)
      : saved_(ranks.is_root() ? nullptr : std::cerr.rdbuf(nullptr)), quiet_(!ranks.is_root()) {}
  ~QuietUnlessRoot() {
    if (quiet_) {
      std::cerr.rdbuf(saved_);
      std::cerr.clear();
    }
  }
  QuietUnlessRoot(const QuietUnlessRoot&) = delete;
  QuietUnlessRoot& operator=(const QuietUnlessRoot&) = delete;

 private:
  std::streambuf* saved_;
  bool quiet_;
};

}  // namespace eomgen::studies
