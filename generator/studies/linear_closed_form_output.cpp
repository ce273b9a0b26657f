#include "studies/linear_closed_form_output.hpp"

#include <algorithm>
#include <iostream>

#include <fmt/format.h>

#include "studies/exit_status.hpp"
#include "studies/report_text.hpp"
#include "emit/formats.hpp"
#include "symbolic/canonical_print.hpp"

namespace eomgen::studies {

namespace {

std::string joined(const std::vector<std::string>& items, const char* separator) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

// x_i(t) = Σ_j Φ_ij(t) x_j(0), the zero entries left out
std::string solution_row(const LinearReport& r, unsigned i) {
  const GiNaC::matrix& Phi = r.closed_form->solution.fundamental;
  std::string terms;
  for (unsigned j = 0; j < Phi.cols(); ++j) {
    if (Phi(i, j).is_zero()) continue;
    std::string start = r.state_names[j] + "(0)";
    std::string entry = Phi(i, j).is_equal(1) ? start : "(" + canonical_text(Phi(i, j)) + ")*" + start;
    terms += (terms.empty() ? "" : " + ") + entry;
  }
  return fmt::format("{}(t) = {}", r.state_names[i], terms.empty() ? "0" : terms);
}

// G(s) of each --transfer pair, from the closed form's rows (outputs) and columns (inputs)
std::vector<std::pair<const LinearReport::Pair*, std::string>> transfer_texts(const LinearReport& r) {
  std::vector<std::pair<const LinearReport::Pair*, std::string>> out;
  const LinearClosedForm& c = *r.closed_form;
  for (const LinearReport::Pair& p : r.transfer) {
    auto row = std::find(r.closed_form_outputs.begin(), r.closed_form_outputs.end(), p.output) - r.closed_form_outputs.begin();
    auto column = std::find(r.input_names.begin(), r.input_names.end(), p.input) - r.input_names.begin();
    out.push_back({&p, canonical_text(c.solution.transfer(unsigned(row), unsigned(column)))});
  }
  return out;
}

std::string basis_text(const LinearClosedForm& c) {
  if (c.in_parameters())
    return c.system.assumptions.empty() ? "in the parameters" : "in the parameters, for " + joined(c.system.assumptions, ", ");
  return "at the parameter values (not in the parameters: " + c.parameter_refusal + ")";
}

}  // namespace

void print_closed_form_text(const LinearReport& r) {
  if (!r.closed_form) return;
  const LinearClosedForm& c = *r.closed_form;
  if (!c.refusal.empty()) {
    std::cout << "  closed form: none, " << c.refusal << "\n";
    return;
  }
  std::cout << fmt::format("  closed form x(t) = Phi(t) x(0), Phi(t) = L^-1{{(sI - A)^-1}} (Hiller §6.2), {}{}:\n", basis_text(c),
                           c.solution.conditions.empty() ? "" : "; valid where " + joined(c.solution.conditions, ", "));
  for (unsigned i = 0; i < c.solution.fundamental.rows(); ++i) std::cout << "    " << solution_row(r, i) << "\n";
  for (const auto& [pair, g] : transfer_texts(r))
    std::cout << fmt::format("  transfer function {} -> {} in closed form: G(s) = {}\n", pair->input, pair->output, g);
}

std::string closed_form_json(const LinearReport& r) {
  if (!r.closed_form) return "";
  const LinearClosedForm& c = *r.closed_form;
  if (!c.refusal.empty()) return fmt::format(", \"symbolic\": {{\"refusal\": {}}}", json_quoted(c.refusal));
  std::vector<std::string> rows, solution, transfers;
  const GiNaC::matrix& Phi = c.solution.fundamental;
  for (unsigned i = 0; i < Phi.rows(); ++i) {
    std::vector<std::string> row;
    for (unsigned j = 0; j < Phi.cols(); ++j) row.push_back(canonical_text(Phi(i, j)));
    rows.push_back(json_strings(row));
    solution.push_back(solution_row(r, i));
  }
  for (const auto& [pair, g] : transfer_texts(r))
    transfers.push_back(fmt::format("{{\"input\": {}, \"output\": {}, \"G\": {}}}", json_quoted(pair->input),
                                    json_quoted(pair->output), json_quoted(g)));
  return fmt::format(", \"symbolic\": {{\"in_parameters\": {}, \"parameter_refusal\": {}, \"assumptions\": {}, \"conditions\": {}, "
                     "\"time\": \"t\", \"fundamental_matrix\": [{}], \"solution\": {}, \"transfer_functions\": [{}]}}",
                     c.in_parameters() ? "true" : "false",
                     c.parameter_refusal.empty() ? "null" : json_quoted(c.parameter_refusal),
                     json_strings(c.system.assumptions), json_strings(c.solution.conditions), joined(rows, ", "),
                     json_strings(solution), joined(transfers, ", "));
}

}  // namespace eomgen::studies
