// The order of a generated function's statements (emit/statement_order): the same lines, each
// after what it reads, array entries written and read in their order, other lines in place, and
// fewer values alive at once.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "emit/statement_order.hpp"

namespace eomgen::test {
namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::string name_defined(const std::string& line) {
  static const std::string head = "  const T ";
  if (line.compare(0, head.size(), head) != 0) return "";
  return line.substr(head.size(), line.find(' ', head.size()) - head.size());
}

// The largest number of locals written and still to be read by a later line.
std::size_t most_alive(const std::vector<std::string>& lines) {
  std::map<std::string, std::size_t> last_read;
  for (std::size_t i = 0; i < lines.size(); ++i)
    for_each_identifier(lines[i], 0, lines[i].size(), [&](std::string_view id) { last_read[std::string(id)] = i; });
  std::size_t alive = 0, most = 0;
  std::multiset<std::size_t> ends;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    while (!ends.empty() && *ends.begin() <= i) ends.erase(ends.begin());
    if (std::string name = name_defined(lines[i]); !name.empty() && last_read[name] > i) ends.insert(last_read[name]);
    alive = ends.size();
    most = std::max(most, alive);
  }
  return most;
}

// `chains` independent chains of `levels` products, written level by level as a derivation's
// recursion writes them, each chain's end stored in F at the end: every chain is alive to the end.
std::string level_by_level(std::size_t chains, std::size_t levels) {
  std::string out;
  for (std::size_t k = 0; k < levels; ++k)
    for (std::size_t c = 0; c < chains; ++c)
      out += k == 0 ? fmt::format("  const T a{}_0 = x[{}]*p[0];\n", c, c)
                    : fmt::format("  const T a{}_{} = a{}_{}*x[{}] + T(1)/T(3);\n", c, k, c, k - 1, c);
  for (std::size_t c = 0; c < chains; ++c) out += fmt::format("  F[{}] = a{}_{};\n", c, c, levels - 1);
  return out;
}

TEST(StatementOrder, EachValueIsWrittenJustBeforeItIsNeeded) {
  std::string before = level_by_level(100, 7);
  std::vector<std::string> old_lines = lines_of(before), new_lines = lines_of(in_order_of_use(before));
  EXPECT_EQ(most_alive(old_lines), 100u);
  EXPECT_LE(most_alive(new_lines), 1u);
  std::vector<std::string> a = old_lines, b = new_lines;
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b) << "the same statements";
  std::set<std::string> written;
  for (const std::string& line : new_lines) {
    for_each_identifier(line, line.find(" = ") + 3, line.size(), [&](std::string_view id) {
      if (id.size() > 1 && id[0] == 'a') {
        EXPECT_TRUE(written.count(std::string(id))) << id << " read before written: " << line;
      }
    });
    written.insert(name_defined(line));
  }
  EXPECT_EQ(new_lines[6], "  const T a0_6 = a0_5*x[0] + T(1)/T(3);");
  EXPECT_EQ(new_lines[7], "  F[0] = a0_6;");
}

TEST(StatementOrder, ShortRunsKeepTheirOrder) {
  std::string short_run = level_by_level(10, 7);
  EXPECT_EQ(in_order_of_use(short_run), short_run);
}

// the fused gradient's M and f (BodyWriter::order_every_run) take the order however short their run
TEST(StatementOrder, AShortRunIsOrderedWhenEveryRunIsAsked) {
  std::string short_run = level_by_level(10, 7);
  std::vector<std::string> out = lines_of(in_order_of_use(short_run, 0));
  EXPECT_EQ(most_alive(lines_of(short_run)), 10u);
  EXPECT_LE(most_alive(out), 1u);
  EXPECT_EQ(out[7], "  F[0] = a0_6;");
}

TEST(StatementOrder, ArrayEntriesKeepTheOrderOfTheirWritesAndReads) {
  std::string run = level_by_level(100, 7);
  run += "  M[1] = a3_6;\n  M[21] = M[1];\n  const T b = M[21]*T(2);\n  M[1] = a0_6*b;\n  M[21] = a1_6;\n";
  std::vector<std::string> out = lines_of(in_order_of_use(run));
  auto at = [&](const std::string& line) { return std::find(out.begin(), out.end(), line) - out.begin(); };
  EXPECT_LT(at("  M[1] = a3_6;"), at("  M[21] = M[1];"));
  EXPECT_LT(at("  M[21] = M[1];"), at("  const T b = M[21]*T(2);"));
  EXPECT_LT(at("  const T b = M[21]*T(2);"), at("  M[1] = a0_6*b;"));
  EXPECT_LT(at("  M[21] = M[1];"), at("  M[1] = a0_6*b;"));
  EXPECT_LT(at("  const T b = M[21]*T(2);"), at("  M[21] = a1_6;"));
}

TEST(StatementOrder, OtherLinesBoundTheRunsAndStayInPlace) {
  std::string first = level_by_level(100, 7), second = level_by_level(90, 7);
  for (std::size_t c = 0; c < 90; ++c) {
    std::string from = fmt::format("a{}_", c), to = fmt::format("b{}_", c);
    for (std::size_t at; (at = second.find(from)) != std::string::npos;) second.replace(at, from.size(), to);
  }
  std::string call = "  detail::ldlt_solve(L, D, F);\n", computed = "  const T c = F[i]*T(2);\n";
  std::vector<std::string> out = lines_of(in_order_of_use(first + call + computed + second));
  std::size_t first_lines = lines_of(first).size();
  EXPECT_EQ(out[first_lines] + "\n", call);
  EXPECT_EQ(out[first_lines + 1] + "\n", computed) << "a computed index bounds a run";
  for (std::size_t i = 0; i < first_lines; ++i) EXPECT_EQ(out[i].find("b"), std::string::npos) << out[i];
}

}  // namespace
}  // namespace eomgen::test
