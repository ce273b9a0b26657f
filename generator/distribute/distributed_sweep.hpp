/// @file Sweeps split over the ranks of a run (ranks.hpp): each rank computes its block of
/// rows (a map) or points (a 1-D sweep) on its threads; rank 0 gathers them in order and,
/// for a 1-D sweep, bisects the crossings. The gathered result is the one a single process
/// computes, value for value, so the files written from it are byte-identical.
#pragma once

#include "analyse/eigenvalue_sweep.hpp"
#include "analyse/stability_map.hpp"
#include "distribute/ranks.hpp"

namespace eomgen::distribute {

/// The whole map on rank 0; on the other ranks only their rows.
runtime::StabilityMap distributed_map(const Ranks& ranks, const runtime::Problem& base, const std::vector<double>& start,
                                      bool fixed, runtime::SweepAxis x, runtime::SweepAxis y, unsigned threads,
                                      const std::function<void(long, long)>& progress, const std::atomic<bool>& stop);

/// The whole sweep with its crossings on rank 0; on the other ranks only their points.
runtime::EigenvalueSweep distributed_eigenvalue_sweep(const Ranks& ranks, const runtime::Problem& base,
                                                      const runtime::StartState& start, bool fixed, runtime::SweepAxis axis,
                                                      double resolution, unsigned threads,
                                                      const std::function<void(long, long)>& progress,
                                                      const std::atomic<bool>& stop);

}  // namespace eomgen::distribute
