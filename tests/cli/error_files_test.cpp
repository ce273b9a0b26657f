// tests/errors/NAME.toml holds one mistake each, with the expected diagnostic in
// its second line (`# expect: LINE:COLUMN: message`), and tests/errors/fixed/NAME.toml
// its corrected twin. `eomgen derive` must exit 2 on the first with that
// diagnostic and write nothing, and exit 0 on the second.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>

#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

namespace fs = std::filesystem;

const std::string errors_dir = std::string(EOMGEN_SOURCE_DIR) + "/tests/errors";

std::vector<std::string> error_files() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(errors_dir))
    if (entry.path().extension() == ".toml") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

struct DeriveRun {
  int status;
  std::string errors;
  bool wrote;
};

DeriveRun derive(const std::string& model, const std::string& scratch) {
  std::string out = scratch + "/out.txt", err = scratch + "/stderr.txt";
  fs::remove(out);
  int status = run_command("cd " + errors_dir + " && '" + std::string(EOMGEN_EXECUTABLE) + "' derive " + model +
                           " -o '" + out + "' 2> '" + err + "' > /dev/null");
  return {status, read_file(err), fs::exists(out)};
}

std::string line_starting(const std::string& file, const std::string& prefix) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) return line.substr(prefix.size());
  return {};
}

class ErrorFile : public ::testing::TestWithParam<std::string> {};

TEST_P(ErrorFile, IsReportedWithItsLocationAndNothingIsWritten) {
  std::string scratch = temporary_directory();
  std::string name = GetParam() + ".toml";
  std::string expected = line_starting(errors_dir + "/" + name, "# expect: ");
  ASSERT_FALSE(expected.empty()) << name << " has no '# expect:' line";
  std::size_t colon = expected.find(':', expected.find(':') + 1);
  std::string diagnostic = name + ":" + expected.substr(0, colon) + ": error:" + expected.substr(colon + 1);
  DeriveRun run = derive(name, scratch);
  EXPECT_EQ(run.status, 2) << run.errors;
  EXPECT_NE(run.errors.find(diagnostic), std::string::npos) << "expected: " << diagnostic << "\ngot:\n" << run.errors;
  EXPECT_FALSE(run.wrote) << "an output file was written despite the error";
}

TEST_P(ErrorFile, CorrectedTwinIsAccepted) {
  std::string scratch = temporary_directory();
  std::string name = "fixed/" + GetParam() + ".toml";
  ASSERT_TRUE(fs::exists(errors_dir + "/" + name)) << name << " is missing";
  DeriveRun run = derive(name, scratch);
  EXPECT_EQ(run.status, 0) << run.errors;
  EXPECT_TRUE(run.wrote);
}

INSTANTIATE_TEST_SUITE_P(EveryFile, ErrorFile, ::testing::ValuesIn(error_files()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// tests/errors/robots/NAME.xml, NAME.urdf or NAME.xacro: a robot file with one mistake and its expected diagnostic in its
// second line (`<!-- expect: LINE:COLUMN: message -->`, or `FILE:LINE:COLUMN: message` for a mistake in a
// file it includes, FILE as the include names it): `eomgen import` exits 2 with it and writes nothing
std::vector<std::string> robot_error_files() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(errors_dir + "/robots"))
    if (entry.path().extension() == ".xml" || entry.path().extension() == ".urdf" || entry.path().extension() == ".xacro")
      names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

class RobotErrorFile : public ::testing::TestWithParam<std::string> {};

TEST_P(RobotErrorFile, IsReportedWithItsLineAndNothingIsWritten) {
  std::string scratch = temporary_directory(), name = GetParam(), out = scratch + "/robot.toml";
  std::string expected = line_starting(errors_dir + "/robots/" + name, "<!-- expect: ");
  ASSERT_FALSE(expected.empty()) << name << " has no '<!-- expect:' line";
  expected = expected.substr(0, expected.rfind(" -->"));
  std::string file = name;
  if (!std::isdigit(static_cast<unsigned char>(expected[0]))) {
    file = expected.substr(0, expected.find(':'));
    expected = expected.substr(file.size() + 1);
  }
  std::size_t colon = expected.find(':', expected.find(':') + 1);
  std::string diagnostic = file + ":" + expected.substr(0, colon) + ": error:" + expected.substr(colon + 1);
  int status = run_command("cd " + errors_dir + "/robots && '" + std::string(EOMGEN_EXECUTABLE) + "' import " + name + " -o '" +
                           out + "' 2> '" + scratch + "/stderr.txt' > /dev/null");
  std::string errors = read_file(scratch + "/stderr.txt");
  EXPECT_EQ(status, 2) << errors;
  EXPECT_NE(errors.find(diagnostic), std::string::npos) << "expected: " << diagnostic << "\ngot:\n" << errors;
  EXPECT_FALSE(fs::exists(out)) << "a model file was written despite the error";
}

INSTANTIATE_TEST_SUITE_P(EveryRobotFile, RobotErrorFile, ::testing::ValuesIn(robot_error_files()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '.', '_');
                           return name;
                         });

TEST(ErrorFiles, AtLeastFifteenRobotMistakesAreCovered) { EXPECT_GE(robot_error_files().size(), 15u); }

TEST(ErrorFiles, AtLeastTwentyMistakesAreCovered) { EXPECT_GE(error_files().size(), 20u); }

TEST(ErrorFiles, HugeFileIsRefusedWithoutParsing) {
  std::string scratch = temporary_directory();
  std::string path = scratch + "/huge.toml";
  {
    std::ofstream out(path);
    out << "[model]\nname = \"huge\"\n[parameters]\n";
    for (int i = 0; out.tellp() < (1 << 20) + 1000; ++i) out << "p" << i << " = 1.0\n";
  }
  int status = run_command("'" + std::string(EOMGEN_EXECUTABLE) + "' derive '" + path + "' -o '" + scratch +
                           "/out.txt' 2> '" + scratch + "/stderr.txt'");
  std::string errors = read_file(scratch + "/stderr.txt");
  EXPECT_EQ(status, 2);
  EXPECT_NE(errors.find("model files are limited to 1048576 bytes"), std::string::npos) << errors;
  EXPECT_FALSE(fs::exists(scratch + "/out.txt"));
}

TEST(ErrorFiles, CommandLineMistakeExitsTwo) {
  EXPECT_EQ(run_command("'" + std::string(EOMGEN_EXECUTABLE) + "' derive --format pdf x.toml 2>/dev/null"), 2);
  EXPECT_EQ(run_command("'" + std::string(EOMGEN_EXECUTABLE) + "' derive /no/such/model.toml 2>/dev/null"), 2);
  EXPECT_EQ(run_command("'" + std::string(EOMGEN_EXECUTABLE) + "' derive --help >/dev/null"), 0);
}

}  // namespace
}  // namespace eomgen::test
