#include "emit/cpp_register_allocation.hpp"

namespace eomgen {

std::string with_priority_register_allocation(const std::string& functions) {
  const std::string gcc_only = "#if defined(__GNUC__) && !defined(__clang__)\n";
  return gcc_only + "#pragma GCC push_options\n#pragma GCC optimize(\"ira-algorithm=priority\")\n#endif\n" + functions + gcc_only +
         "#pragma GCC pop_options\n#endif\n";
}

}  // namespace eomgen
