// Sweeps and ensembles split over MPI ranks (`mpirun -np 2` and 3 on this machine): the
// files they write are byte-identical to a single-process run, and the summary says how
// many ranks took part.
#include <gtest/gtest.h>

#include <tuple>

#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

#define SKIP_WITHOUT_MPI() \
  if (!can_run_on_ranks()) GTEST_SKIP() << "eomgen was built without MPI (Debian's libopenmpi-dev and openmpi-bin)"

struct SweepFiles {
  std::string csv, png, out;
};

SweepFiles sweep_on(int ranks, const std::string& arguments) {
  std::string dir = temporary_directory();
  std::string files = " -o '" + dir + "/sweep.csv' --plot '" + dir + "/sweep.png'";
  CommandOutput r = ranks == 0 ? run_eomgen("sweep " + arguments + files) : run_eomgen_on_ranks(ranks, "sweep " + arguments + files);
  EXPECT_EQ(r.status, 0) << r.err;
  return {read_file(dir + "/sweep.csv"), read_file(dir + "/sweep.png"), r.out};
}

TEST(DistributedRuns, AnEigenvalueSweepOnTwoAndThreeRanksWritesWhatOneProcessWrites) {
  SKIP_WITHOUT_MPI();
  // 200 points do not divide by 3: the shares differ in size
  std::string arguments = "'" + model_path("whipple_linear") + "' --param v=0:10:200";
  SweepFiles one = sweep_on(0, arguments), two = sweep_on(2, arguments), three = sweep_on(3, arguments);
  ASSERT_GT(one.csv.size(), 1000u);
  ASSERT_GT(one.png.size(), 1000u);
  EXPECT_EQ(two.csv, one.csv);
  EXPECT_EQ(three.csv, one.csv);
  EXPECT_EQ(two.png, one.png);
  EXPECT_NE(one.out.find("on 1 process"), std::string::npos) << one.out;
  EXPECT_NE(two.out.find("on 2 ranks"), std::string::npos) << two.out;
  EXPECT_NE(three.out.find("on 3 ranks"), std::string::npos) << three.out;
  // the crossings are bisected on rank 0 from the gathered points: the same weave and capsize speeds
  auto after_summary = [](const std::string& out) { return out.substr(out.find('\n')); };
  EXPECT_NE(one.out.find("crosses into the left half-plane"), std::string::npos) << one.out;
  EXPECT_EQ(after_summary(two.out), after_summary(one.out));
  EXPECT_EQ(after_summary(three.out), after_summary(one.out));
}

TEST(DistributedRuns, AStabilityMapOnTwoRanksWritesWhatOneProcessWrites) {
  SKIP_WITHOUT_MPI();
  std::string arguments = "'" + model_path("watt_governor") + "' --param b=0.05:2:41 --param J=0.05:3:31 --symbolic";
  SweepFiles one = sweep_on(0, arguments), two = sweep_on(2, arguments);
  ASSERT_GT(one.csv.size(), 1000u);
  EXPECT_EQ(two.csv, one.csv);
  EXPECT_EQ(two.png, one.png);
  EXPECT_NE(two.out.find("1271 of 1271 points computed"), std::string::npos) << two.out;
  EXPECT_NE(two.out.find("on 2 ranks"), std::string::npos) << two.out;
  CommandOutput json = run_eomgen_on_ranks(2, "sweep " + arguments + " --format json");
  ASSERT_EQ(json.status, 0) << json.err;
  EXPECT_NE(json.out.find("\"ranks\": 2"), std::string::npos) << json.out;
  // only rank 0 speaks
  EXPECT_EQ(json.out.find('\n'), json.out.size() - 1) << json.out;
}

TEST(DistributedRuns, AMistakeIsReportedOnceAndEveryRankStops) {
  SKIP_WITHOUT_MPI();
  CommandOutput r = run_eomgen_on_ranks(2, "sweep '" + model_path("watt_governor") + "' --param nosuch=0:1:10");
  EXPECT_NE(r.status, 0);
  std::size_t first = r.err.find("not a parameter");
  ASSERT_NE(first, std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("not a parameter", first + 1), std::string::npos) << r.err;
}

TEST(DistributedRuns, AnEnsembleHasTheSameStatisticsOnOneTwoAndThreeRanks) {
  SKIP_WITHOUT_MPI();
  std::string arguments = "ensemble '" + model_path("double_pendulum") +
                          "' --samples 31 --vary 'm2=normal(1,0.05)' --vary 'phi1=uniform(0.4,0.6)' --measure 'max(phi2)' "
                          "--t-end 3 --dt-out 0.05 --threads 2";
  auto run = [&](int ranks) {
    std::string dir = temporary_directory();
    std::string files = " -o '" + dir + "/e.csv' --plot '" + dir + "/e.png' --format json";
    CommandOutput r = ranks == 1 ? run_eomgen(arguments + files) : run_eomgen_on_ranks(ranks, arguments + files);
    EXPECT_EQ(r.status, 0) << r.err;
    return std::make_tuple(read_file(dir + "/e.csv"), read_file(dir + "/e.png"), r.out);
  };
  auto [csv1, png1, out1] = run(1);
  auto [csv2, png2, out2] = run(2);
  auto [csv3, png3, out3] = run(3);
  ASSERT_GT(csv1.size(), 1000u);
  EXPECT_EQ(csv2, csv1);
  EXPECT_EQ(csv3, csv1);
  EXPECT_EQ(png2, png1);
  // the statistics of the measure, to the last digit
  auto measures = [](const std::string& out) { return out.substr(out.find("\"measures\"")); };
  EXPECT_EQ(measures(out2), measures(out1));
  EXPECT_EQ(measures(out3), measures(out1));
  EXPECT_NE(out1.find("\"ranks\": 1"), std::string::npos) << out1;
  EXPECT_NE(out2.find("\"ranks\": 2"), std::string::npos) << out2;
}

}  // namespace
}  // namespace eomgen::test
