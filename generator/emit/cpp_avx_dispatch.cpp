#include "emit/cpp_avx_dispatch.hpp"

#include <fmt/format.h>

#include <regex>
#include <stdexcept>
#include <vector>

namespace eomgen {

namespace {

const char* const guard =
    "#if defined(__GNUC__) && defined(__x86_64__) && !defined(__AVX__) && !defined(EOMGEN_NO_AVX_DISPATCH)\n";

// asked once per program and function: whether this processor runs AVX code
const char* const processor_has_avx = "  static const bool avx = (__builtin_cpu_init(), __builtin_cpu_supports(\"avx\") != 0);\n";

struct Parameter {
  std::string declaration, name;  // for double; its name
};

// the parameters of "void NAME(T t, const T* x, const input_t<T>* u, …)" with T = double
std::vector<Parameter> double_parameters(const std::string& list) {
  static const std::regex input(R"(input_t<T>)"), scalar(R"(\bT\b)"), name(R"((\w+)\s*$)");
  std::vector<Parameter> out;
  std::size_t at = 0;
  while (at < list.size()) {
    std::size_t comma = list.find(',', at);
    if (comma == std::string::npos) comma = list.size();
    std::string declaration = list.substr(at, comma - at);
    declaration.erase(0, declaration.find_first_not_of(' '));
    declaration = std::regex_replace(std::regex_replace(declaration, input, "double"), scalar, "double");
    std::smatch m;
    if (!std::regex_search(declaration, m, name)) throw std::logic_error("with_avx_dispatch: a parameter without a name: " + declaration);
    out.push_back({declaration, m[1].str()});
    at = comma + 1;
  }
  return out;
}

}  // namespace

std::string with_avx_dispatch(const std::string& function) {
  static const std::string head = "template <class T>\nvoid ";
  std::size_t at = function.find(head);
  if (at == std::string::npos) throw std::logic_error("with_avx_dispatch: not a function template");
  std::size_t name_begin = at + head.size(), open = function.find('(', name_begin), close = function.find(')', open);
  const std::string name = function.substr(name_begin, open - name_begin);
  std::string declarations, arguments;
  for (const Parameter& p : double_parameters(function.substr(open + 1, close - open - 1))) {
    declarations += (declarations.empty() ? "" : ", ") + p.declaration;
    arguments += (arguments.empty() ? "" : ", ") + p.name;
  }
  return function + guard +
         fmt::format("/// {0} for double also as AVX code (a fifth smaller: more of it stays in the instruction cache;\n"
                     "/// the same results to the last bit), taken where the processor has AVX. EOMGEN_NO_AVX_DISPATCH: not.\n"
                     "__attribute__((target(\"avx\"), flatten)) inline void {0}_avx({1}) {{\n"
                     "  {0}<double>({2});\n"
                     "}}\n"
                     "inline void {0}({1}) {{\n"
                     "{3}"
                     "  if (avx)\n"
                     "    {0}_avx({2});\n"
                     "  else\n"
                     "    {0}<double>({2});\n"
                     "}}\n"
                     "#endif\n\n",
                     name, declarations, arguments, processor_has_avx);
}

std::string solve_rows_avx_dispatch() {
  return std::string(guard) +
         "/// ldlt_solve_rows for double also as AVX code (four columns at a time; the same results to the\n"
         "/// last bit), taken where the processor has AVX. EOMGEN_NO_AVX_DISPATCH: not.\n"
         "template <std::size_t m, bool negated = false>\n"
         "__attribute__((target(\"avx\"), flatten)) inline void ldlt_solve_rows_avx(const double* L, const double* D, double* B) {\n"
         "  ldlt_solve_rows<m, negated, double>(L, D, B);\n"
         "}\n"
         "template <std::size_t m, bool negated = false>\n"
         "inline void ldlt_solve_rows(const double* L, const double* D, double* B) {\n" +
         processor_has_avx +
         "  if (m >= 8 && avx)\n"
         "    ldlt_solve_rows_avx<m, negated>(L, D, B);\n"
         "  else\n"
         "    ldlt_solve_rows<m, negated, double>(L, D, B);\n"
         "}\n"
         "#endif\n\n";
}

}  // namespace eomgen
