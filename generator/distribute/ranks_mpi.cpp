/// @file Ranks over MPI_COMM_WORLD (Open MPI from Debian).
#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>

#include "distribute/ranks.hpp"

namespace eomgen::distribute {

namespace {

// set by Open MPI's mpirun, and by the PMI/PMIx launchers of other implementations and of Slurm
bool launched_by_mpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

}  // namespace

Ranks::Ranks() {
  if (!launched_by_mpirun()) return;
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) {
    MPI_Init(nullptr, nullptr);
    started_mpi_ = true;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

Ranks::~Ranks() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (started_mpi_ && !finalized) MPI_Finalize();
}

bool Ranks::built_with_mpi() { return true; }

std::vector<double> Ranks::gather(const std::vector<double>& mine) const {
  if (size_ == 1) return mine;
  if (mine.size() > static_cast<std::size_t>(INT32_MAX)) throw std::length_error("a rank's share is too large to gather");
  int count = static_cast<int>(mine.size());
  std::vector<int> counts(is_root() ? std::size_t(size_) : 0), offsets(counts.size());
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  long total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    if (total + counts[r] > INT32_MAX) throw std::length_error("the gathered results are too large for one message");
    offsets[r] = static_cast<int>(total);
    total += counts[r];
  }
  std::vector<double> all(static_cast<std::size_t>(total));
  MPI_Gatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  return all;
}

std::vector<std::string> Ranks::gather_text(const std::string& mine) const {
  if (size_ == 1) return {mine};
  int count = static_cast<int>(std::min<std::size_t>(mine.size(), 1 << 20));
  std::vector<int> counts(is_root() ? std::size_t(size_) : 0), offsets(counts.size());
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  int total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) offsets[r] = total, total += counts[r];
  std::string all(static_cast<std::size_t>(total), '\0');
  MPI_Gatherv(mine.data(), count, MPI_CHAR, all.data(), counts.data(), offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD);
  std::vector<std::string> texts;
  for (std::size_t r = 0; r < counts.size(); ++r) texts.push_back(all.substr(std::size_t(offsets[r]), std::size_t(counts[r])));
  return texts;
}

int Ranks::broadcast(int value) const {
  if (size_ > 1) MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value;
}

bool Ranks::any(bool mine) const {
  if (size_ == 1) return mine;
  int in = mine, out = 0;
  MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_LOR, MPI_COMM_WORLD);
  return out != 0;
}

}  // namespace eomgen::distribute
