#include "studies/input_signal.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include <fmt/format.h>

#include "studies/exit_status.hpp"
#include "model/expression_parser.hpp"
#include "symbolic/evaluate.hpp"

namespace eomgen::studies {

namespace {

struct Table {
  std::vector<double> times;
  std::vector<std::vector<double>> columns;  // one per input named in the header
  std::vector<int> inputs;                   // the input index of each column
};

double interpolate(const std::vector<double>& t, const std::vector<double>& v, double at) {
  if (at <= t.front()) return v.front();
  if (at >= t.back()) return v.back();
  auto upper = std::upper_bound(t.begin(), t.end(), at);
  std::size_t k = static_cast<std::size_t>(upper - t.begin());
  double w = (at - t[k - 1]) / (t[k] - t[k - 1]);
  return (1 - w) * v[k - 1] + w * v[k];
}

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  for (std::string cell; std::getline(s, cell, ',');) {
    cell.erase(0, cell.find_first_not_of(" \t\r"));
    cell.erase(cell.find_last_not_of(" \t\r") + 1);
    cells.push_back(cell);
  }
  return cells;
}

// header "t,name,...", then rows of numbers with increasing t
std::optional<Table> read_table(const std::string& path, const eomgen_model_abi& m) {
  std::ifstream in(path);
  if (!in) {
    std::cerr << fmt::format("eomgen: error: --input-file {}: cannot be read\n", path);
    return std::nullopt;
  }
  Table table;
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header = split_csv(line);
  std::vector<std::string> names(m.input_names, m.input_names + m.num_inputs);
  if (header.size() < 2 || header[0] != "t") {
    std::cerr << fmt::format("eomgen: error: {}:1: the header must be t followed by input names, e.g. t,{}\n", path,
                             names.empty() ? "tau" : names[0]);
    return std::nullopt;
  }
  for (std::size_t c = 1; c < header.size(); ++c) {
    int i = index_of(m.input_names, m.num_inputs, header[c]);
    if (i < 0) {
      std::cerr << fmt::format("eomgen: error: {}:1: column {} '{}' is not an input of the model; {}\n", path, c + 1,
                               header[c], suggest(header[c], names, "inputs"));
      return std::nullopt;
    }
    table.inputs.push_back(i);
  }
  table.columns.resize(table.inputs.size());
  for (int row = 2; std::getline(in, line); ++row) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::vector<std::string> cells = split_csv(line);
    std::vector<double> values;
    for (const std::string& cell : cells) {
      char* end = nullptr;
      double v = std::strtod(cell.c_str(), &end);
      if (cell.empty() || *end != '\0' || !std::isfinite(v)) break;
      values.push_back(v);
    }
    if (values.size() != header.size() || cells.size() != header.size() ||
        (!table.times.empty() && !(values[0] > table.times.back()))) {
      std::cerr << fmt::format("eomgen: error: {}:{}: expected {} finite numbers with t increasing from row to row\n",
                               path, row, header.size());
      return std::nullopt;
    }
    table.times.push_back(values[0]);
    for (std::size_t c = 1; c < values.size(); ++c) table.columns[c - 1].push_back(values[c]);
  }
  if (table.times.empty()) {
    std::cerr << fmt::format("eomgen: error: {}: no rows after the header\n", path);
    return std::nullopt;
  }
  return table;
}

struct Signal {
  int input;
  GiNaC::ex expression;
};

}  // namespace

std::optional<int> set_input_signal(LoadedProblem& loaded, const std::vector<std::string>& expressions,
                                    const std::string& table_file, double& table_end) {
  if (expressions.empty() && table_file.empty()) return std::nullopt;
  const eomgen_model_abi& m = *loaded.compiled->abi();
  const Symbols& symbols = loaded.equations.symbols;
  std::vector<std::string> names(m.input_names, m.input_names + m.num_inputs);
  auto signals = std::make_shared<std::vector<Signal>>();
  for (const std::string& text : expressions) {
    std::size_t eq = text.find('=');
    std::string name = eq == std::string::npos ? text : text.substr(0, eq);
    int i = index_of(m.input_names, m.num_inputs, name);
    if (eq == std::string::npos || i < 0) {
      std::cerr << fmt::format("eomgen: error: --input '{}': expected INPUT=EXPRESSION in t and the parameters, e.g. "
                               "--input '{}=0.5*sin(2*t)'; {}\n", text, names.empty() ? "tau" : names[0],
                               names.empty() ? "this model has no inputs" : suggest(name, names, "inputs"));
      return exit_user_error;
    }
    Diagnostics d;
    ExpressionText expression;
    expression.text = text.substr(eq + 1);
    expression.where.file = "--input";
    expression.where.line = 1;
    expression.where.column = static_cast<int>(eq) + 2;
    expression.key = "--input " + name;
    auto e = parse_expression(expression, symbols, {allow_parameters | allow_time, "an input signal"}, d);
    if (!e) {
      std::cerr << d.format();
      return exit_user_error;
    }
    signals->push_back({i, *e});
  }
  std::shared_ptr<Table> table;
  if (!table_file.empty()) {
    auto read = read_table(table_file, m);
    if (!read) return exit_user_error;
    table = std::make_shared<Table>(std::move(*read));
    table_end = table->times.back();
  }
  auto values = std::make_shared<std::map<std::string, double>>();
  for (std::size_t i = 0; i < symbols.parameter_names.size(); ++i) (*values)[symbols.parameter_names[i]] = loaded.problem.parameters[i];
  loaded.problem.input_signal = [signals, table, values](double t, double* u) {
    if (table)
      for (std::size_t c = 0; c < table->inputs.size(); ++c) u[table->inputs[c]] = interpolate(table->times, table->columns[c], t);
    (*values)["t"] = t;
    for (const Signal& s : *signals)
      u[s.input] = evaluate(s.expression, [&](const GiNaC::symbol& x) { return values->at(x.get_name()); });
  };
  return std::nullopt;
}

}  // namespace eomgen::studies
