// Hostile input that used to crash, hang or break the generated header: an expression
// 20,000 parentheses deep (a stack overflow in the recursive parser), a derivation that
// swells past its time limit, parameters named like the members of the header's
// Parameters struct, and a run whose trajectory would not fit in memory. Each ends with a
// message and exit status 2, or with a header that compiles, and never with a signal or a
// partial file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include <sys/resource.h>

#include "common/deadline.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

namespace fs = std::filesystem;

std::string pendulum_with(const std::string& from, const std::string& to, const std::string& name) {
  std::string text = read_file(model_path("pendulum"));
  std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("no '" + from + "' in pendulum.toml");
  text.replace(at, from.size(), to);
  std::string path = temporary_directory() + "/" + name + ".toml";
  std::ofstream(path) << text;
  return path;
}

TEST(HostileInput, TwentyThousandNestedParenthesesGetALocatedDiagnostic) {
  std::string deep = std::string(20000, '(') + "l" + std::string(20000, ')');
  std::string path = pendulum_with("position = [\"l*sin(phi)\"", "position = [\"" + deep + "*sin(phi)\"", "deep");
  std::string out = temporary_directory() + "/out";
  CommandOutput r = run_eomgen("generate '" + path + "' -o '" + out + "'");
  EXPECT_EQ(r.status, 2) << "a signal shows as a status above 128: " << r.status << "\n" << r.err.substr(0, 400);
  EXPECT_NE(r.err.find("deep.toml:22:270: error: particles[0].position[0]: the expression is nested more than 256 levels deep"),
            std::string::npos)
      << r.err.substr(0, 400);
  EXPECT_FALSE(fs::exists(out)) << "nothing is written";
}

TEST(HostileInput, ADerivationPastItsTimeLimitStopsWithExitTwoAndWritesNothing) {
  // thirty nested sines of phi*der(phi) in T: small to write, slow to differentiate twice
  std::string nested = "";
  for (int i = 0; i < 30; ++i) nested += "sin(";
  nested += "phi*der(phi)" + std::string(30, ')');
  std::string path = pendulum_with("[energy]\n", "[energy]\nkinetic = \"" + nested + "^2\"\n", "swelling");
  std::string out = temporary_directory() + "/out";
  CommandOutput r = run_eomgen("generate '" + path + "' -o '" + out + "' --max-seconds 0.2");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("swelling.toml: the derivation ran past its limit of 0.2 s while forming the simplified M and f"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("--max-seconds"), std::string::npos) << "the hint names the option";
  EXPECT_FALSE(fs::exists(out)) << "nothing is written";
  CommandOutput refused = run_eomgen("derive '" + path + "' --max-seconds -1");
  EXPECT_EQ(refused.status, 2) << "a negative limit is a usage error";
}

// From its second second on, a derivation, and the header's writing, show what they are forming and
// for how long, once a second and in place, on a terminal (script(1) gives eomgen one) and nowhere
// else: a log or a pipe gets none
TEST(HostileInput, ALongDerivationShowsItsProgressOnATerminalOnly) {
  if (run_command("command -v script > /dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1) to give eomgen a terminal";
  // the swelling potential below, stopped by the time limit (by its memory, were a machine 4x as fast)
  std::string path = pendulum_with("[energy]\n", "[energy]\npotential = \"(phi + m + l + g + d + 2*phi^2 + m*l + g*d)^30\"\n",
                                   "slow_swelling");
  std::string arguments = "derive '" + path + "' --max-seconds 3.5 --max-memory 1.5";
  std::string terminal = temporary_directory() + "/terminal";
  run_command("script -qec \"'" + std::string(EOMGEN_EXECUTABLE) + "' " + arguments + "\" /dev/null > '" + terminal + "' 2>&1");
  std::string shown = read_file(terminal);
  EXPECT_NE(shown.find("slow_swelling.toml: forming "), std::string::npos) << shown;
  EXPECT_NE(shown.find(", 2 s (limit 3.5 s, --max-seconds)"), std::string::npos) << shown;
  EXPECT_NE(shown.find("the derivation ran past its limit of 3.5 s"), std::string::npos) << shown;
  CommandOutput piped = run_eomgen(arguments);
  EXPECT_EQ(piped.status, 2);
  EXPECT_EQ(piped.err.find(" s (limit 3.5 s"), std::string::npos) << piped.err;
  EXPECT_EQ(derivation_progress_line("arm.toml", "the first integrals", 12.7, 0), "eomgen: arm.toml: forming the first integrals, 12 s");
  // the header's writing shows its progress too, without a limit: 32 nested sines and as many
  // cosines derive in about two seconds and take four to nine to write
  auto nested = [](const std::string& function) {
    std::string text;
    for (int i = 0; i < 32; ++i) text += function + "(";
    return text + "phi*der(phi)" + std::string(32, ')');
  };
  std::string sines = pendulum_with("[energy]\n", "[energy]\nkinetic = \"" + nested("sin") + "^2 + " + nested("cos") + "^2\"\n",
                                    "slow_header");
  std::string writing = temporary_directory() + "/writing";
  run_command("script -qec \"'" + std::string(EOMGEN_EXECUTABLE) + "' generate '" + sines + "' -o '" + temporary_directory() +
              "'\" /dev/null > '" + writing + "' 2>&1");
  std::string written = read_file(writing);
  EXPECT_NE(written.find("slow_header.toml: forming the C++ header (common subexpressions, printing), 2 s"), std::string::npos)
      << written;
  EXPECT_NE(written.find("eomgen: generated "), std::string::npos) << written;
}

TEST(HostileInput, ADerivationPastItsMemoryLimitStopsWithExitTwoAndWritesNothing) {
  // a potential whose powers multiply out: 4.8 GB within a minute, were it not stopped
  std::string path = pendulum_with("[energy]\n", "[energy]\npotential = \"(phi + m + l + g + d + 2*phi^2 + m*l + g*d)^30\"\n",
                                   "swelling");
  std::string out = temporary_directory() + "/out.txt";
  CommandOutput r = run_eomgen("derive '" + path + "' -o '" + out + "' --max-memory 0.3");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("swelling.toml: the derivation grew past its memory limit of 0.3 GB"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("raise the limit with --max-memory GB"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out)) << "nothing is written";
}

TEST(HostileInput, ParametersNamedLikeTheHeadersOwnMembersStillCompile) {
  for (const std::string name : {"values", "Scalar", "Parameters"}) {
    std::string path = pendulum_with("m = 1.0", name + " = 1.0", "named_" + name);
    std::string text = read_file(path);
    text = std::regex_replace(text, std::regex("mass     = \"m\""), "mass     = \"" + name + "\"");
    std::ofstream(path) << text;
    std::string dir = temporary_directory();
    CommandOutput g = run_eomgen("generate '" + path + "' -o '" + dir + "'");
    ASSERT_EQ(g.status, 0) << g.err;
    std::string header = read_file(dir + "/pendulum.hpp");
    EXPECT_NE(header.find("Scalar " + name + "_ = Scalar(1);"), std::string::npos) << "the member gets a trailing _";
    EXPECT_NE(header.find("\"" + name + "\""), std::string::npos) << "parameter_names keeps the name as written";
    std::ofstream(dir + "/use.cpp") << "#include \"pendulum.hpp\"\nint main() {\n"
                                       "  eomgen::models::pendulum::Parameters<double> p;\n  p."
                                    << name
                                    << "_ = 2;\n  auto v = p.values();\n  double x[2] = {0.1, 0}, xdot[2];\n"
                                       "  eomgen::models::pendulum::rhs(0.0, x, nullptr, v.data(), xdot);\n"
                                       "  return xdot[1] < 0 ? 0 : 1;\n}\n";
    EXPECT_EQ(run_command("cd '" + dir + "' && c++ -std=c++17 -Wall -Wextra -Wpedantic -Werror use.cpp -o use && ./use"), 0)
        << name;
    CommandOutput s = run_eomgen("simulate '" + path + "' --t-end 1");
    EXPECT_EQ(s.status, 0) << name << ": " << s.err;
  }
}

TEST(HostileInput, ALongRunStreamsItsRowsInBoundedMemory) {
  ASSERT_EQ(run_eomgen("simulate '" + model_path("double_pendulum") + "' --t-end 0.1").status, 0) << "compiled first";
  // two million rows: held in memory they took about 400 MB; streamed, the run takes about 20 MB
  std::string dir = temporary_directory();
  int status = run_command("EOMGEN_CACHE_DIR='" + std::string(EOMGEN_BINARY_DIR) + "/test-cache' '" +
                           std::string(EOMGEN_EXECUTABLE) + "' simulate '" + model_path("double_pendulum") +
                           "' --t-end 20000 --dt-out 0.01 --integrator rk4 --step 0.01 --max-rows 3e6 --format json > '" + dir +
                           "/out.json' 2> '" + dir + "/err.txt'");
  ASSERT_EQ(status, 0) << read_file(dir + "/err.txt");
  rusage children{};
  getrusage(RUSAGE_CHILDREN, &children);
  EXPECT_LT(children.ru_maxrss, 150 * 1024) << "kB of the largest child process";
  Diagnostics d;
  std::optional<JsonValue> parsed = parse_json(read_file(dir + "/out.json"), "out.json", d);
  ASSERT_TRUE(parsed) << d.format();
  const JsonValue& run = *parsed;
  EXPECT_EQ(at(run, "rows"), 2000001);
  EXPECT_EQ(at(run, "t_end"), 20000);
  EXPECT_LT(at(run, "relative_energy_drift"), 1e-3) << "the summary covers every row";
}

TEST(HostileInput, ARunTooLongToHoldIsRefusedBeforeItStarts) {
  CommandOutput r = run_eomgen("simulate '" + model_path("pendulum") + "' --t-end 1e308");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("more than the 1e+06 allowed"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("raise --dt-out, or allow more with --max-rows"), std::string::npos) << r.err;
  // 1,002 rows at the defaults (t = 0, 0.01, …, 10, and the end)
  CommandOutput few = run_eomgen("simulate '" + model_path("pendulum") + "' --max-rows 1000");
  EXPECT_EQ(few.status, 2) << few.err;
  CommandOutput enough = run_eomgen("simulate '" + model_path("pendulum") + "' --max-rows 1002");
  EXPECT_EQ(enough.status, 0) << enough.err;
}

TEST(HostileInput, AStringForANumberHidesNoOtherMistake) {
  std::string dir = std::string(EOMGEN_SOURCE_DIR) + "/tests/errors";
  CommandOutput r = run_eomgen("derive '" + dir + "/string_for_a_number.toml'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("10:5: error: parameters.g: expected a number, got a string"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("22:29: error: particles[0].position[1]: unknown symbol 'l2'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("2 errors"), std::string::npos) << r.err;
}

TEST(HostileInput, AMisspeltNameInTheWrongCaseSuggestsTheRightOne) {
  std::string path = pendulum_with("position = [\"l*sin(phi)\"", "position = [\"L*sin(phi)\"", "capital");
  CommandOutput r = run_eomgen("derive '" + path + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("unknown symbol 'L'\n  hint: did you mean 'l'?"), std::string::npos) << r.err;
}

TEST(HostileInput, AFullDiskEndsTheRunWithAMessageAndNoPartialFile) {
  // a file-size limit of 4 blocks stands in for a full disk: the trajectory needs more
  std::string dir = temporary_directory();
  // compiled first without the limit, which would stop the compiler too
  ASSERT_EQ(run_eomgen("simulate '" + model_path("double_pendulum") + "' --t-end 0.1").status, 0);
  int status = run_command("ulimit -f 4; EOMGEN_CACHE_DIR='" + std::string(EOMGEN_BINARY_DIR) + "/test-cache' '" +
                           std::string(EOMGEN_EXECUTABLE) + "' simulate '" + model_path("double_pendulum") +
                           "' -o '" + dir + "/x.csv' 2> '" + dir + "/err.txt' > /dev/null");
  std::string err = read_file(dir + "/err.txt");
  EXPECT_EQ(status, 2) << err;
  EXPECT_NE(err.find("cannot write " + dir + "/x.csv (the disk is full, or a file-size limit is reached): File too large"),
            std::string::npos)
      << err;
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(dir)) left.push_back(entry.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"err.txt"}) << "neither the CSV nor its temporary file is left";
}

TEST(HostileInput, AnOutputFolderThatCannotBeMadeIsSaidBeforeTheWork) {
  std::string file = temporary_directory() + "/a_file";
  std::ofstream(file) << "not a folder";
  for (const std::string& command : {"bench '" + model_path("pendulum") + "' -o '" + file + "/bench'",
                                    "scene '" + model_path("pendulum") + "' small_swing -o '" + file + "/scene'",
                                    "run '" + model_path("pendulum") + "' -o '" + file + "/run'"}) {
    CommandOutput r = run_eomgen(command);
    EXPECT_EQ(r.status, 2) << command << "\n" << r.err;
    EXPECT_NE(r.err.find("error: cannot create the output folder " + file), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  }
}

TEST(HostileInput, ATerminatedSimulationKeepsItsRowsAndSaysTheyArePartial) {
  std::string dir = temporary_directory();
  ASSERT_EQ(run_eomgen("simulate '" + model_path("double_pendulum") + "' --t-end 0.1").status, 0) << "compiled first";
  // RK4 at 1e-5 s over 1000 s: far longer than the test waits; TERM once the run has begun
  std::string script = "EOMGEN_CACHE_DIR='" + std::string(EOMGEN_BINARY_DIR) + "/test-cache' '" +
                        std::string(EOMGEN_EXECUTABLE) + "' simulate '" + model_path("double_pendulum") +
                        "' --t-end 1000 --dt-out 0.01 --integrator rk4 --step 1e-5 -o '" + dir + "/x.csv' 2> '" + dir +
                        "/err.txt' > /dev/null & pid=$!; "
                        "for i in $(seq 200); do grep -q simulating '" + dir + "/err.txt' 2>/dev/null && break; sleep 0.05; done; "
                        "sleep 0.5; kill -TERM $pid; wait $pid; echo $? > '" + dir + "/status'\n";
  std::ofstream(dir + "/run.sh") << script;
  ASSERT_EQ(run_command("bash '" + dir + "/run.sh'"), 0);
  std::string err = read_file(dir + "/err.txt");
  EXPECT_EQ(read_file(dir + "/status"), "3\n") << err;
  EXPECT_NE(err.find("the simulation was interrupted at t = "), std::string::npos) << err;
  auto rows = read_numeric_csv(dir + "/x.csv");
  EXPECT_GT(rows.size(), 1u) << "the rows computed so far are kept";
  EXPECT_LT(rows.size(), 100001u) << "and only those";
  EXPECT_NE(err.find("holds the " + std::to_string(rows.size()) + " rows computed before the interruption: a partial run"),
            std::string::npos)
      << err;
}

// runs `arguments` in the background, sends `signal` once a line of standard error contains `started`
// (and 0.3 s more), and returns the exit status with standard error and output
struct Interrupted {
  std::string status, err, out;
};
Interrupted interrupt_when(const std::string& arguments, const std::string& started, const char* signal, const std::string& dir) {
  std::string script = "cd '" + dir + "' || exit 1\nEOMGEN_CACHE_DIR='" + std::string(EOMGEN_BINARY_DIR) + "/test-cache' '" +
                       std::string(EOMGEN_EXECUTABLE) + "' " + arguments + " 2> err.txt > out.txt & pid=$!; "
                       "for i in $(seq 600); do grep -q '" + started + "' '" + dir + "/err.txt' 2>/dev/null && break; sleep 0.05; done; "
                       "sleep 0.3; kill -" + signal + " $pid; wait $pid; echo $? > '" + dir + "/status'\n";
  std::ofstream(dir + "/run.sh") << script;
  if (run_command("bash '" + dir + "/run.sh'") != 0) return {};
  return {read_file(dir + "/status"), read_file(dir + "/err.txt"), read_file(dir + "/out.txt")};
}

TEST(HostileInput, AnInterruptedBenchKeepsItsRunsAndSaysTheyArePartial) {
  std::string dir = temporary_directory();
  // RK4 down to a step of 1e-5 s over 50 s: the last runs take seconds; INT after the first run
  Interrupted r = interrupt_when("bench '" + model_path("double_pendulum") +
                                     "' --t-end 50 --integrators rk4 --step-count 14 -o bench",
                                 "bench: rk4", "INT", dir);
  EXPECT_EQ(r.status, "3\n") << r.err;
  std::smatch runs;
  ASSERT_TRUE(std::regex_search(r.err, runs, std::regex("the bench was interrupted \\(SIGINT or SIGTERM\\) after ([0-9]+) runs: "
                                                         "a partial bench, whose verdict covers those runs only; kept in bench/")))
      << r.err;
  std::string csv = read_file(dir + "/bench/runs.csv");
  std::size_t rows = std::size_t(std::count(csv.begin(), csv.end(), '\n')) - 1;  // below the header
  EXPECT_EQ(rows, std::stoul(runs[1])) << "every finished run is kept, the one interrupted is not\n" << csv;
  EXPECT_LT(rows, 14u);
  EXPECT_NE(read_file(dir + "/bench/report.md").find("**Partial:** the bench was interrupted"), std::string::npos);
}

TEST(HostileInput, AnInterruptedSceneKeepsItsRunsAndSaysTheyArePartial) {
  std::string dir = temporary_directory();
  std::string model = dir + "/pendulum.toml";
  std::ofstream(model) << read_file(model_path("pendulum"))
                       << "\n[scenes.long_swing]\nt_end = 400.0\ndt_out = 0.05\ninitial = { phi = 2.0 }\noutputs = [\"phi\"]\n";
  Interrupted r = interrupt_when("scene '" + model + "' long_swing -o scene", "candidate", "TERM", dir);
  EXPECT_EQ(r.status, "3\n") << r.err;
  EXPECT_NE(r.err.find("the scene was interrupted after "), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("interrupted (SIGINT or SIGTERM) after "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("not run: the scene was interrupted first"), std::string::npos) << r.out;
  EXPECT_NE(read_file(dir + "/scene/report.md").find("a partial scene"), std::string::npos);
}

TEST(HostileInput, ATerminatedSweepKeepsItsPointsAndSaysTheyArePartial) {
  std::string dir = temporary_directory();
  // 2.25 million points, about four seconds: TERM once the progress line shows
  Interrupted r = interrupt_when("sweep '" + model_path("two_mass_chain") + "' --param k1=1:200:1500 --param k2=1:200:1500",
                                 "points", "TERM", dir);
  EXPECT_EQ(r.status, "3\n") << r.err;
  EXPECT_NE(r.err.find("eomgen sweep: interrupted; keeping the points computed so far"), std::string::npos) << r.err;
  std::smatch counted;
  ASSERT_TRUE(std::regex_search(r.out, counted, std::regex("([0-9]+) of 2250000 points computed"))) << r.out;
  EXPECT_LT(std::stoul(counted[1]), 2250000u);
}

TEST(HostileInput, AnOutputPathThatIsAFolderIsRefusedBeforeTheWork) {
  std::string dir = temporary_directory();
  CommandOutput simulate = run_eomgen("simulate '" + model_path("pendulum") + "' -o '" + dir + "'");
  EXPECT_EQ(simulate.status, 2);
  EXPECT_NE(simulate.err.find("error: -o: " + dir + " is a folder, not a file: name a file in it"), std::string::npos)
      << simulate.err;
  EXPECT_EQ(simulate.err.find("simulating"), std::string::npos) << "refused before the run";
  CommandOutput derive = run_eomgen("derive '" + model_path("pendulum") + "' -o '" + dir + "'");
  EXPECT_EQ(derive.status, 2);
  EXPECT_NE(derive.err.find(dir + " is a folder, not a file"), std::string::npos) << derive.err;
  CommandOutput missing = run_eomgen("simulate '" + model_path("pendulum") + "' -o '" + dir + "/no/x.csv'");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("the folder " + dir + "/no does not exist"), std::string::npos) << missing.err;
  EXPECT_TRUE(fs::is_empty(dir)) << "nothing written, no temporary file";
}

TEST(HostileInput, AMissingOrFailingCompilerIsSaidWithWhereTheHeaderIsKept) {
  std::string cache = temporary_directory();
  std::string model = pendulum_with("d = 0.0", "d = 0.0123", "compiled_here");  // a header no cache has yet
  auto simulate_with = [&](const std::string& compiler) {
    std::string dir = temporary_directory();
    int status = run_command("EOMGEN_CACHE_DIR='" + cache + "' EOMGEN_CXX='" + compiler + "' '" +
                             std::string(EOMGEN_EXECUTABLE) + "' simulate '" + model + "' 2> '" + dir + "/err.txt' > /dev/null");
    return std::pair<int, std::string>{status, read_file(dir + "/err.txt")};
  };
  auto [missing_status, missing] = simulate_with("/no/such/c++");
  EXPECT_EQ(missing_status, 2) << missing;
  EXPECT_NE(missing.find("error: the C++ compiler '/no/such/c++' was not found: install one (apt-get install g++) or name it "
                         "in EOMGEN_CXX; the generated header is kept in " + cache + "/failed-pendulum-"),
            std::string::npos)
      << missing;
  // a "compiler" that fails with a message of its own
  std::string failing = temporary_directory() + "/failing_cxx";
  std::ofstream(failing) << "#!/bin/sh\necho 'driver.cpp:3:10: error: the compiler refused this' >&2\nexit 1\n";
  fs::permissions(failing, fs::perms::owner_all);
  auto [failed_status, failed] = simulate_with(failing);
  EXPECT_EQ(failed_status, 1) << failed;
  EXPECT_NE(failed.find("internal error: compiling the generated code with '" + failing + "' failed; the header and the full "
                        "log are kept in " + cache + "/failed-pendulum-"),
            std::string::npos)
      << failed;
  EXPECT_NE(failed.find("driver.cpp:3:10: error: the compiler refused this"), std::string::npos) << failed;
  std::size_t at = failed.find(cache + "/failed-pendulum-");
  std::string kept = failed.substr(at, failed.find(' ', at) - at);
  EXPECT_TRUE(fs::exists(kept + "/pendulum.hpp")) << kept;
}

TEST(HostileInput, TwoProcessesGeneratingIntoOneFolderLeaveAWholeFile) {
  std::string dir = temporary_directory(), single = temporary_directory();
  ASSERT_EQ(run_eomgen("generate '" + model_path("double_pendulum") + "' -o '" + single + "'").status, 0);
  std::string whole = read_file(single + "/double_pendulum.hpp");
  std::string generate = "'" + std::string(EOMGEN_EXECUTABLE) + "' generate '" + model_path("double_pendulum") + "' -o '" + dir +
                         "' 2>/dev/null";
  for (int round = 0; round < 5; ++round) {
    ASSERT_EQ(run_command("(" + generate + " & " + generate + " & wait)"), 0);
    EXPECT_EQ(read_file(dir + "/double_pendulum.hpp"), whole) << "round " << round;
  }
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(dir)) left.push_back(entry.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"double_pendulum.hpp"}) << "no temporary file is left";
}

TEST(HostileInput, ADirectoryIsNamedAsOne) {
  CommandOutput r = run_eomgen("derive '" + temporary_directory() + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("error: this is a directory, not a model file"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace eomgen::test
