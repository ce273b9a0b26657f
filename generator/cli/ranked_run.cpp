#include "cli/ranked_run.hpp"

namespace eomgen::cli {

std::optional<int> load_on_every_rank(const distribute::Ranks& ranks, const std::string& model,
                                      const std::vector<std::string>& sets, LoadedProblem& out) {
  std::optional<int> status;
  if (ranks.is_root()) status = load_problem(model, sets, out);
  int root_status = ranks.broadcast(status.value_or(0));
  if (root_status != 0) return root_status;
  if (!ranks.is_root()) status = load_problem(model, sets, out);
  return status;
}

}  // namespace eomgen::cli
