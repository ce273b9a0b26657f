/// @file Ranks when eomgen is built without MPI: one process does all the work.
#include "distribute/ranks.hpp"

namespace eomgen::distribute {

Ranks::Ranks() = default;
Ranks::~Ranks() = default;
bool Ranks::built_with_mpi() { return false; }
std::vector<double> Ranks::gather(const std::vector<double>& mine) const { return mine; }
std::vector<std::string> Ranks::gather_text(const std::string& mine) const { return {mine}; }
int Ranks::broadcast(int value) const { return value; }
bool Ranks::any(bool mine) const { return mine; }

}  // namespace eomgen::distribute
