#include "distribute/ranks.hpp"

#include <fmt/format.h>

namespace eomgen::distribute {

Ranks& Ranks::world() {
  static Ranks ranks;
  return ranks;
}

std::string Ranks::description() const {
  if (size_ > 1) return fmt::format("{} ranks", size_);
  return built_with_mpi() ? "1 process" : "1 process (built without MPI)";
}

Block Ranks::share(long count) const {
  long base = count / size_, extra = count % size_;
  long begin = rank_ * base + std::min<long>(rank_, extra);
  return {begin, begin + base + (rank_ < extra ? 1 : 0)};
}

}  // namespace eomgen::distribute
