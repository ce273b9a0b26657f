#include "emit/statement_order.hpp"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace eomgen {

namespace {

// One line of a run: what it writes (a local's name, or "array[k]") and where its right side starts.
struct Statement {
  std::string_view line;
  std::string writes;
  bool is_array_write = false;
  std::size_t right_side = 0;
};

std::size_t identifier_end(std::string_view s, std::size_t from) {
  while (from < s.size() && is_identifier_char(s[from])) ++from;
  return from;
}

// "[k]" at `at`: the index's end past ']', else 0
std::size_t literal_index_end(std::string_view s, std::size_t at) {
  if (at >= s.size() || s[at] != '[') return 0;
  std::size_t end = at + 1;
  while (end < s.size() && s[end] >= '0' && s[end] <= '9') ++end;
  return end > at + 1 && end < s.size() && s[end] == ']' ? end + 1 : 0;
}

// `  const T name = …;` or `  array[k] = …;`, else nothing (the line bounds a run)
bool parse(std::string_view line, Statement& s) {
  static constexpr std::string_view local = "  const T ";
  if (line.size() < 8 || line.substr(0, 2) != "  " || line[2] == ' ' || line.back() != ';') return false;
  s.line = line;
  std::size_t name_begin = line.substr(0, local.size()) == local ? local.size() : 2;
  std::size_t name_end = identifier_end(line, name_begin);
  if (name_end == name_begin) return false;
  s.is_array_write = name_begin == 2;
  std::size_t end = name_end;
  if (s.is_array_write && (end = literal_index_end(line, name_end)) == 0) return false;
  if (line.substr(end, 3) != " = ") return false;
  s.writes = std::string(line.substr(name_begin, end - name_begin));
  s.right_side = end + 3;
  // an entry read by a computed index could be any: such a line bounds a run
  for (std::size_t at = line.find('[', s.right_side); at != std::string_view::npos; at = line.find('[', at + 1))
    if (at == 0 || !is_identifier_char(line[at - 1]) || literal_index_end(line, at) == 0) return false;
  return true;
}

// The locals and array entries `s` reads.
std::vector<std::string> reads(const Statement& s) {
  std::vector<std::string> out;
  std::string_view text = s.line;
  for (std::size_t i = s.right_side; i < text.size();) {
    if (!is_identifier_char(text[i])) {
      ++i;
      continue;
    }
    std::size_t end = identifier_end(text, i), indexed = literal_index_end(text, end);
    if (text[i] < '0' || text[i] > '9') out.emplace_back(text.substr(i, (indexed ? indexed : end) - i));
    i = indexed ? indexed : end;
  }
  return out;
}

// The run's statements in order of use (see in_order_of_use).
std::vector<std::size_t> schedule(const std::vector<Statement>& run) {
  std::size_t n = run.size();
  std::vector<std::vector<std::size_t>> needs(n);
  std::map<std::string, std::size_t, std::less<>> writer;  // the latest statement writing each
  std::map<std::string, std::vector<std::size_t>, std::less<>> readers;  // an array entry's, since written
  for (std::size_t i = 0; i < n; ++i) {
    for (const std::string& r : reads(run[i])) {
      if (auto w = writer.find(r); w != writer.end()) needs[i].push_back(w->second);
      if (r.back() == ']') readers[r].push_back(i);
    }
    if (run[i].is_array_write) {
      // a later write of the same entry stays after the earlier write and its reads
      if (auto w = writer.find(run[i].writes); w != writer.end()) needs[i].push_back(w->second);
      std::vector<std::size_t>& earlier = readers[run[i].writes];
      needs[i].insert(needs[i].end(), earlier.begin(), earlier.end());
      earlier.clear();
    }
    writer[run[i].writes] = i;
    std::sort(needs[i].begin(), needs[i].end());
    needs[i].erase(std::unique(needs[i].begin(), needs[i].end()), needs[i].end());
    needs[i].erase(std::remove(needs[i].begin(), needs[i].end(), i), needs[i].end());
  }
  std::vector<std::pair<std::size_t, std::size_t>> outputs;  // (when its operands are all there, index)
  for (std::size_t i = 0; i < n; ++i)
    if (run[i].is_array_write) outputs.emplace_back(needs[i].empty() ? 0 : needs[i].back() + 1, i);
  std::sort(outputs.begin(), outputs.end());
  std::vector<std::size_t> order;
  std::vector<bool> placed(n, false);
  auto place = [&](std::size_t root) {
    std::vector<std::pair<std::size_t, std::size_t>> stack{{root, 0}};  // (statement, next need)
    while (!stack.empty()) {
      auto& [i, next] = stack.back();
      if (placed[i]) {
        stack.pop_back();
      } else if (next < needs[i].size()) {
        std::size_t need = needs[i][next++];
        if (!placed[need]) stack.emplace_back(need, 0);
      } else {
        placed[i] = true;
        order.push_back(i);
        stack.pop_back();
      }
    }
  };
  for (const auto& output : outputs) place(output.second);
  for (std::size_t i = 0; i < n; ++i) place(i);
  return order;
}

}  // namespace

// A shorter run keeps the order it was written in: the 7-joint arm's M and f (450 statements),
// written level by level, ran 2–5 % slower in order of use (each header timed in both places of
// one process), where the CPU finds fewer independent operations close together; the 21-joint
// tree's (2,800) and the quadruped's ran at least 3 % faster.
constexpr std::size_t reordered_from = 600;

// GCC's register allocation and combiner grow faster than the number of statements when many values
// are alive at once: a 21-joint tree's inverse_dynamics_gradient, its world-frame quantities written
// link after link in dependency levels and its 1,323 entries at the end, took 18.5 s at -O2, and
// 11.4 s in this order (and ran 8 % faster).
std::string in_order_of_use(const std::string& statements) { return in_order_of_use(statements, reordered_from); }

std::string in_order_of_use(const std::string& statements, std::size_t shortest_reordered) {
  std::string out;
  out.reserve(statements.size());
  std::vector<Statement> run;
  auto flush = [&] {
    if (run.size() < shortest_reordered) {
      for (const Statement& s : run) (out += s.line) += '\n';
    } else {
      for (std::size_t i : schedule(run)) (out += run[i].line) += '\n';
    }
    run.clear();
  };
  std::string_view text = statements;
  for (std::size_t at = 0; at < text.size();) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    Statement s;
    if (parse(text.substr(at, end - at), s)) {
      run.push_back(std::move(s));
    } else {
      flush();
      out += text.substr(at, end - at);
      if (end < text.size()) out += '\n';
    }
    at = end + 1;
  }
  flush();
  return out;
}

}  // namespace eomgen
