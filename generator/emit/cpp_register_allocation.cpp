#include "emit/cpp_register_allocation.hpp"

namespace eomgen {

std::string with_priority_register_allocation(const std::string& functions) {
  return "#if defined(__GNUC__) && !defined(__clang__)\n"
         "#pragma GCC push_options\n"
         "#pragma GCC optimize(\"ira-algorithm=priority\")\n"
         "#endif\n" +
         functions +
         "#if defined(__GNUC__) && !defined(__clang__)\n"
         "#pragma GCC pop_options\n"
         "#endif\n";
}

}  // namespace eomgen
