// The studies behind `simulate`, `ensemble`, `bench`, `diff`, `fmu`, `generate --split` and the
// runs on several ranks (generator/studies/), called in the test process: inputs that vary in
// time, the ensemble's flags, the streamed CSV, all-or-nothing files, the comparison of two
// models and the integrators a model admits.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "studies/bench_study.hpp"
#include "studies/diff_study.hpp"
#include "studies/ensemble_options.hpp"
#include "studies/fmu_package.hpp"
#include "studies/input_signal.hpp"
#include "studies/scene_runs.hpp"
#include "studies/split_output.hpp"
#include "studies/trajectory_output.hpp"
#include "study_support.hpp"
#include "support/small_models.hpp"

namespace eomgen::test {
namespace {

using namespace eomgen::studies;


double input_at(const LoadedProblem& loaded, double t) {
  double u = NAN;
  loaded.problem.input_signal(t, &u);
  return u;
}

TEST(InputSignal, AnExpressionInTimeAndTheParameters) {
  LoadedProblem loaded = load(write_model("pushed_mass", pushed_mass_model));
  double end = INFINITY;
  StudyOutput r = run_study([&] { return set_input_signal(loaded, {"F=3*sin(2*t)*m"}, "", end).value_or(exit_success); });
  ASSERT_EQ(r.status, exit_success) << r.err;
  ASSERT_TRUE(loaded.problem.input_signal);
  EXPECT_NEAR(input_at(loaded, 0.3), 3 * std::sin(0.6) * 2.0, 1e-15);
  StudyOutput misspelt = run_study([&] { return set_input_signal(loaded, {"G=1"}, "", end).value_or(exit_success); });
  EXPECT_EQ(misspelt.status, exit_user_error);
  EXPECT_NE(misspelt.err.find("did you mean 'F'"), std::string::npos) << misspelt.err;
  StudyOutput state = run_study([&] { return set_input_signal(loaded, {"F=x"}, "", end).value_or(exit_success); });
  EXPECT_EQ(state.status, exit_user_error) << "an input signal depends on t and the parameters only";
}

TEST(InputSignal, ATableIsInterpolatedLinearlyAndHeldBeyondItsEnds) {
  LoadedProblem loaded = load(write_model("pushed_mass", pushed_mass_model));
  std::string dir = temporary_directory();
  std::ofstream(dir + "/u.csv") << "t,F\n0,0\n1,1\n5,3\n";
  double end = INFINITY;
  StudyOutput r = run_study([&] { return set_input_signal(loaded, {}, dir + "/u.csv", end).value_or(exit_success); });
  ASSERT_EQ(r.status, exit_success) << r.err;
  EXPECT_EQ(end, 5.0);
  EXPECT_DOUBLE_EQ(input_at(loaded, 0.25), 0.25);
  EXPECT_DOUBLE_EQ(input_at(loaded, 3.0), 2.0);
  EXPECT_DOUBLE_EQ(input_at(loaded, 7.0), 3.0);
  EXPECT_DOUBLE_EQ(input_at(loaded, -1.0), 0.0);
  std::ofstream(dir + "/bad.csv") << "t,G\n0,0\n";
  StudyOutput bad = run_study([&] { return set_input_signal(loaded, {}, dir + "/bad.csv", end).value_or(exit_success); });
  EXPECT_EQ(bad.status, exit_user_error);
  EXPECT_NE(bad.err.find("bad.csv:1: column 2 'G' is not an input"), std::string::npos) << bad.err;
}

TEST(EnsembleFlags, VariationsMeasuresAndQuantiles) {
  LoadedProblem loaded = load(write_model("pushed_mass", pushed_mass_model));
  const eomgen_model_abi& m = *loaded.compiled->abi();
  auto mass = parse_variation(m, "m=normal(2,0.05)");
  ASSERT_TRUE(mass);
  EXPECT_EQ(mass->target, runtime::Variation::Target::parameter);
  EXPECT_EQ(mass->distribution.kind, runtime::Distribution::Kind::normal);
  EXPECT_EQ(mass->distribution.b, 0.05);
  auto start = parse_variation(m, "x=uniform(-1,1)");
  ASSERT_TRUE(start);
  EXPECT_EQ(start->target, runtime::Variation::Target::state);
  auto force = parse_variation(m, "F=lognormal(0,0.1)");
  ASSERT_TRUE(force);
  EXPECT_EQ(force->target, runtime::Variation::Target::input);
  StudyOutput unknown = run_study([&] { return parse_variation(m, "mm=normal(1,2)") ? 0 : 2; });
  EXPECT_EQ(unknown.status, 2);
  EXPECT_NE(unknown.err.find("did you mean 'm'"), std::string::npos) << unknown.err;
  StudyOutput negative_spread = run_study([&] { return parse_variation(m, "m=normal(1,-2)") ? 0 : 2; });
  EXPECT_EQ(negative_spread.status, 2);
  auto period = parse_measure(m, "period(x)");
  ASSERT_TRUE(period);
  EXPECT_EQ(period->signal, "x");
  EXPECT_EQ(period->text(), "period(x)");
  StudyOutput not_a_signal = run_study([&] { return parse_measure(m, "max(y)") ? 0 : 2; });
  EXPECT_EQ(not_a_signal.status, 2);
  EXPECT_EQ(parse_probabilities("0.05,0.5,0.95"), (std::vector<double>{0.05, 0.5, 0.95}));
  StudyOutput beyond = run_study([&] { return parse_probabilities("0.5,1.5") ? 0 : 2; });
  EXPECT_EQ(beyond.status, 2);
}

runtime::Trajectory rows_from(double t0, int count) {
  runtime::Trajectory rows;
  for (int k = 0; k < count; ++k) {
    rows.times.push_back(t0 + k);
    rows.states.push_back({double(k), 2.0 * k});
    rows.energies.push_back(0.5 * k);
    rows.outputs.emplace_back();  // the model has no outputs and no first integrals
    rows.first_integrals.emplace_back();
  }
  return rows;
}

TEST(TrajectoryOutput, TheCsvIsWholeOrAbsent) {
  LoadedProblem loaded = load(write_model("pushed_mass", pushed_mass_model));
  const eomgen_model_abi& m = *loaded.compiled->abi();
  std::string csv = temporary_directory() + "/run.csv";
  {
    TrajectoryOutput output(m, csv);
    ASSERT_TRUE(output.take(rows_from(0, 3)));
    ASSERT_TRUE(output.take(rows_from(3, 2)));
    EXPECT_FALSE(std::filesystem::exists(csv)) << "the CSV is moved into place at the end";
    ASSERT_TRUE(output.finish()) << output.failure();
    EXPECT_EQ(output.chart_rows().times.back(), 4.0);
  }
  std::string header;
  auto rows = read_numeric_csv(csv, &header);
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[4][0], 4.0);
  EXPECT_EQ(rows[4][1], 1.0);  // the second batch's second row
  EXPECT_EQ(rows[4][2], 2.0);
  EXPECT_NE(header.find("x"), std::string::npos) << header;
  // a folder that does not exist: the failure is named, and no file is left
  std::string nowhere = temporary_directory() + "/missing/run.csv";
  TrajectoryOutput failing(m, nowhere);
  failing.take(rows_from(0, 2));
  EXPECT_FALSE(failing.finish());
  EXPECT_FALSE(failing.failure().empty());
  EXPECT_FALSE(std::filesystem::exists(nowhere));
}

TEST(SplitOutput, AllFilesOrNone) {
  std::string dir = temporary_directory();
  std::vector<GeneratedFile> files{{"pushed_mass_split.hpp", "// written by eomgen\n"},
                                   {"pushed_mass_rhs.cpp", "// written by eomgen\n#include \"pushed_mass.hpp\"\n"}};
  EXPECT_EQ(write_split_files(dir, "pushed_mass", "pushed_mass.hpp", files), "");
  EXPECT_TRUE(std::filesystem::exists(dir + "/pushed_mass_rhs.cpp"));
  std::string failure = write_split_files(dir + "/missing", "pushed_mass", "pushed_mass.hpp", files);
  EXPECT_FALSE(failure.empty());
  EXPECT_FALSE(std::filesystem::exists(dir + "/missing/pushed_mass_split.hpp"));
}

TEST(DiffStudy, AModelAgainstItselfAndAgainstAChangedOne) {
  std::string pendulum = model_path("pendulum");
  std::string text = read_file(pendulum);
  std::string changed = write_model("pendulum", text.replace(text.find("position = [\"l*sin(phi)\""),
                                                                    std::string("position = [\"l*sin(phi)\"").size(),
                                                                    "position = [\"l*sin(phi)*1.5\""));
  ComparisonOptions same;
  same.inputs = {pendulum, pendulum};
  StudyOutput r = run_study([&] { return diff(same); });
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  ComparisonOptions different;
  different.inputs = {pendulum, changed};
  StudyOutput d = run_study([&] { return diff(different); });
  EXPECT_EQ(d.status, 1) << d.out << d.err;
  ComparisonOptions missing;
  missing.inputs = {pendulum, temporary_directory() + "/none.toml"};
  EXPECT_EQ(run_study([&] { return diff(missing); }).status, 2);
}

TEST(BenchStudy, EveryIntegratorButTheReference) {
  LoadedProblem loaded = load(model_path("pendulum"));
  std::vector<std::string> names = applicable_integrators(*loaded.compiled->abi());
  EXPECT_EQ(std::count(names.begin(), names.end(), "reference"), 0);
  EXPECT_EQ(std::count(names.begin(), names.end(), "cvode-bdf"), 1);
  EXPECT_EQ(std::count(names.begin(), names.end(), "verlet"), 1) << "the pendulum is separable";
}

TEST(FmuStudy, ALagrangeIModelIsRefusedAndNothingIsWritten) {
  std::string dir = temporary_directory(), path;
  Equations equations = derive_model("pendulum_cartesian");
  std::string refusal = write_fmu(equations, dir, FmuKinds{}, path);
  EXPECT_NE(refusal.find("Lagrange I"), std::string::npos) << refusal;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(SceneRuns, OutputsByNameAndTheirRange) {
  LoadedProblem loaded = load(write_model("pushed_mass", pushed_mass_model));
  runtime::Trajectory rows = rows_from(0, 4);
  std::string missing;
  auto outputs = scene_outputs(*loaded.compiled->abi(), rows, {"x", "der(x)"}, missing);
  ASSERT_TRUE(outputs) << missing;
  EXPECT_EQ((*outputs)[1], (std::vector<double>{0, 2, 4, 6}));
  EXPECT_EQ(range_of((*outputs)[1]), 6.0);
  EXPECT_FALSE(scene_outputs(*loaded.compiled->abi(), rows, {"y"}, missing));
  EXPECT_EQ(missing, "y");
  EXPECT_EQ(range_of({}), 0.0);
}

}  // namespace
}  // namespace eomgen::test
