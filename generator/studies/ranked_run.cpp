#include "studies/ranked_run.hpp"

#include "studies/exit_status.hpp"

namespace eomgen::studies {

std::optional<int> load_on_every_rank(const distribute::Ranks& ranks, const std::string& model,
                                      const std::vector<std::string>& sets, LoadedProblem& out,
                                      const ModelChoice& choice) {
  std::optional<int> status;
  if (ranks.is_root()) status = load_problem(model, sets, out, {}, choice);
  int root_status = ranks.broadcast(status.value_or(0));
  if (root_status != 0) return root_status;
  if (!ranks.is_root()) status = load_problem(model, sets, out, {}, choice);
  // every rank must know, or the others would wait for it in the sweep's first gather
  if (ranks.any(status.has_value())) {
    if (ranks.is_root())
      std::cerr << "eomgen: error: another rank could not load the model that rank 0 loaded\n"
                   "  hint: on several hosts, eomgen, the C++ compiler and the model file must be at the same paths on "
                   "each, and the cache folder (EOMGEN_CACHE_DIR) writable\n";
    return status.value_or(exit_internal_error);
  }
  return status;
}

std::string refusal_on_root(const distribute::Ranks& ranks, const std::function<std::string()>& check) {
  std::string refusal = ranks.is_root() ? check() : "";
  // the text stays on rank 0, which alone prints it; the others need only know there is one
  return ranks.broadcast(refusal.empty() ? 0 : 1) == 0 ? "" : refusal.empty() ? "refused on rank 0" : refusal;
}

}  // namespace eomgen::studies
