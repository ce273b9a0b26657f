/// @file The processes of one run: under `mpirun`, the ranks of MPI_COMM_WORLD; started
/// directly, or built without MPI, a single process. Sweeps and ensembles split their
/// points over the ranks in contiguous blocks and gather the results in rank 0, which
/// alone prints and writes files.
#pragma once

#include <string>
#include <vector>

namespace eomgen::distribute {

struct Block {
  long begin = 0, end = 0;  // [begin, end)
};

class Ranks {
 public:
  /// MPI is started on first use, and only when the environment says the process was
  /// launched by mpirun (an MPI_Init outside mpirun would try to spawn a daemon).
  static Ranks& world();
  ~Ranks();
  Ranks(const Ranks&) = delete;
  Ranks& operator=(const Ranks&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool is_root() const { return rank_ == 0; }
  /// "2 ranks", "1 process" (started directly) or "1 process (built without MPI)".
  std::string description() const;
  static bool built_with_mpi();

  /// This rank's share of `count` items: contiguous, in rank order, sizes differing by at most one.
  Block share(long count) const;
  /// Every rank's values concatenated in rank order, on rank 0; empty on the others.
  std::vector<double> gather(const std::vector<double>& mine) const;
  /// Every rank's text, in rank order, on rank 0; empty on the others.
  std::vector<std::string> gather_text(const std::string& mine) const;
  /// Rank 0's value, on every rank.
  int broadcast(int value) const;
  /// True on every rank when it is true on any.
  bool any(bool mine) const;

 private:
  Ranks();
  int rank_ = 0, size_ = 1;
  bool started_mpi_ = false;
};

}  // namespace eomgen::distribute
