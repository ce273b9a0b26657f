/// @file C++ text of small vector and matrix expressions over a tree's components (x and y of a
/// planar tree, x, y and z of a spatial one), unrolled: the generated loops over a tree's nodes
/// (emit/cpp_articulated_jacobian, emit/cpp_jacobian_readers) write each component out.
#pragma once

#include <functional>
#include <string>

namespace eomgen {

// C++ text of Σ_c term(c) over the tree's components
class ComponentText {
 public:
  explicit ComponentText(std::size_t count) : count_(count) {}
  std::size_t count() const { return count_; }
  std::string sum(const std::function<std::string(std::size_t)>& term) const {
    std::string out;
    for (std::size_t c = 0; c < count_; ++c) out += (c ? " + " : "") + term(c);
    return count_ > 1 ? "(" + out + ")" : out;
  }
  // one statement per component a, or per pair (a, b)
  std::string each(const std::function<std::string(std::size_t)>& statement, const std::string& indent) const {
    std::string out;
    for (std::size_t a = 0; a < count_; ++a) out += indent + statement(a) + "\n";
    return out;
  }
  std::string each_pair(const std::function<std::string(std::size_t, std::size_t)>& statement, const std::string& indent) const {
    return each([&](std::size_t a) {
      std::string row;
      for (std::size_t b = 0; b < count_; ++b) row += (b ? " " : "") + statement(a, b);
      return row;
    }, indent);
  }

 private:
  std::size_t count_;
};

}  // namespace eomgen
