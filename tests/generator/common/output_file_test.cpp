// All-or-nothing output, and output into a pipe: `-o /dev/null` or a FIFO is written into
// and stays a pipe, never replaced by a renamed file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "common/output_file.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

namespace fs = std::filesystem;

TEST(OutputFile, AFileAppearsWholeAndReplacesTheOldOne) {
  std::string folder = temporary_directory(), path = folder + "/out.txt";
  std::ofstream(path) << "old";
  EXPECT_EQ(write_file_atomically(path, "new text\n"), "");
  EXPECT_EQ(read_file(path), "new text\n");
  for (const auto& entry : fs::directory_iterator(folder))
    EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos) << "no temporary file is left";
}

TEST(OutputFile, APipeTakesTheTextAndStaysAPipe) {
  std::string fifo = temporary_directory() + "/pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // a reader that does not wait for a writer, so that the writer's open returns at once
  int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  EXPECT_EQ(write_file_atomically(fifo, "through the pipe\n"), "");
  char buffer[64] = {};
  ssize_t got = ::read(reader, buffer, sizeof buffer);
  ::close(reader);
  EXPECT_EQ(std::string(buffer, got > 0 ? std::size_t(got) : 0), "through the pipe\n");
  EXPECT_TRUE(fs::is_fifo(fifo)) << "a renamed file would have replaced the pipe";
}

TEST(OutputFile, AFolderIsRefusedWithWhatToDo) {
  std::string folder = temporary_directory();
  EXPECT_EQ(write_file_atomically(folder, "x"), folder + " is a folder, not a file: name a file in it");
}

}  // namespace
}  // namespace eomgen::test
