#include "emit/operation_count.hpp"

#include <cctype>

namespace eomgen {

namespace {
constexpr long operations_per_function = 10;
}  // namespace

long count_operations(const std::string& header, const std::string& function, std::size_t n) {
  std::size_t start = header.find("void " + function + "(");
  if (start == std::string::npos) return 0;
  std::size_t open = header.find('{', start), end = header.find("\n}\n", open);
  std::string body = header.substr(open, end - open);
  long count = 0;
  long cube = static_cast<long>(n * n * n), square = static_cast<long>(n * n);
  for (std::size_t line = 0; line < body.size();) {
    std::size_t next = body.find('\n', line);
    if (next == std::string::npos) next = body.size();
    std::string text = body.substr(line, next - line);
    line = next + 1;
    if (text.find("using std::") != std::string::npos || text.find("(void)") != std::string::npos) continue;
    if (text.find("ldlt_factor(") != std::string::npos) count += cube / 6 + square;
    if (text.find("ldlt_solve(") != std::string::npos) count += 2 * square;
    std::size_t eq = text.find(" = ");
    if (eq == std::string::npos) continue;
    const std::string value = text.substr(eq + 3);
    // a sine or cosine that detail::sin_cos computed with the function's other angles
    if (value.rfind("trig_sin[", 0) == 0 || value.rfind("trig_cos[", 0) == 0) count += operations_per_function;
    for (std::size_t i = 0; i < value.size(); ++i) {
      char c = value[i];
      bool unary = c == '-' && (i + 1 == value.size() || value[i + 1] != ' ');  // the printer writes binary minus as " - "
      if ((c == '+' || c == '*' || c == '/' || c == '-') && !unary) ++count;
      // sin(, cos(, sqrt(: an elementary function costs about ten multiplications; T(0.5) is a constant
      bool constant = i > 0 && value[i - 1] == 'T' && (i == 1 || !std::isalnum(static_cast<unsigned char>(value[i - 2])));
      if (c == '(' && i > 0 && std::isalpha(static_cast<unsigned char>(value[i - 1])) && !constant) count += operations_per_function;
    }
  }
  return count;
}

}  // namespace eomgen
