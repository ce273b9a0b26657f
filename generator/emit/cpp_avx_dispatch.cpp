#include "emit/cpp_avx_dispatch.hpp"

#include <fmt/format.h>

#include <regex>
#include <stdexcept>
#include <vector>

namespace eomgen {

namespace {

const char* const guard =
    "#if defined(__GNUC__) && defined(__x86_64__) && !defined(__AVX__) && !defined(EOMGEN_NO_AVX_DISPATCH)\n";

// A copy's instruction set: the target attribute, the suffix of its name, and the question asked
// once per program and function, whether this processor runs it (its answer named `fast`)
struct InstructionSet {
  const char* target;
  const char* suffix;
  const char* processor_runs_it;
};

const InstructionSet avx{"avx", "_avx", "  static const bool fast = (__builtin_cpu_init(), __builtin_cpu_supports(\"avx\") != 0);\n"};
const InstructionSet avx2_fma{"avx2,fma", "_fma",
                              "  static const bool fast = (__builtin_cpu_init(), __builtin_cpu_supports(\"avx2\") != 0 &&\n"
                              "                            __builtin_cpu_supports(\"fma\") != 0);\n"};

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

// The AVX copy of a function's double instance and the overload for double that takes it, under
// `guard`; the one text for gradients and the solve.
struct Dispatch {
  std::string comment;             // the two lines saying what the copy is
  std::string head;                // the template line the copy and the overload need, or ""
  std::string name;                // NAME: the copy is NAME_avx, the overload NAME
  std::string parameters;          // for double
  std::string arguments;
  std::string instance;            // the template's double instance the copy inlines
  std::string template_arguments;  // in the overload's call of the copy
  std::string when;                // a condition the overload asks first, "" or "... && "
  InstructionSet set;
};

std::string copy_and_overload(const Dispatch& d) {
  return fmt::format("{0}{1}{2}__attribute__((target(\"{10}\"), flatten)) inline void {3}{11}({4}) {{\n"
                     "  {6}({5});\n"
                     "}}\n"
                     "{2}inline void {3}({4}) {{\n"
                     "{7}"
                     "  if ({8}fast)\n"
                     "    {3}{11}{9}({5});\n"
                     "  else\n"
                     "    {6}({5});\n"
                     "}}\n"
                     "#endif\n\n",
                     guard, d.comment, d.head, d.name, d.parameters, d.arguments, d.instance, d.set.processor_runs_it, d.when,
                     d.template_arguments, d.set.target, d.set.suffix);
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
  return function + copy_and_overload({fmt::format("/// {} for double also as AVX2 code with fused multiply-adds (a fifth smaller, and a tenth of its\n"
                                                   "/// time less), taken where the processor has AVX2 and FMA; results within rounding of the\n"
                                                   "/// template's (the same bits with -ffp-contract=off). EOMGEN_NO_AVX_DISPATCH: not.\n",
                                                   name),
                                       "", name, declarations, arguments, name + "<double>", "", "", avx2_fma});
}

std::string solve_rows_avx_dispatch() {
  return copy_and_overload({"/// ldlt_solve_rows for double also as AVX code (four columns at a time; the same results to the\n"
                            "/// last bit), taken where the processor has AVX. EOMGEN_NO_AVX_DISPATCH: not.\n",
                            "template <std::size_t m, bool negated = false>\n", "ldlt_solve_rows",
                            "const double* L, const double* D, double* B", "L, D, B", "ldlt_solve_rows<m, negated, double>",
                            "<m, negated>", "m >= 8 && ", avx});
}

}  // namespace eomgen
