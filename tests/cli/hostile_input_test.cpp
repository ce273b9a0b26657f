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
  EXPECT_NE(r.err.find("swelling.toml: the derivation ran past its limit of 0.2 s while forming Lagrange's equations of the "
                       "second kind"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("--max-seconds"), std::string::npos) << "the hint names the option";
  EXPECT_FALSE(fs::exists(out)) << "nothing is written";
  CommandOutput refused = run_eomgen("derive '" + path + "' --max-seconds -1");
  EXPECT_EQ(refused.status, 2) << "a negative limit is a usage error";
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
