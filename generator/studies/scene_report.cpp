#include "studies/scene_report.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <fmt/format.h>

#include "studies/exit_status.hpp"
#include "studies/report_text.hpp"
#include "common/output_file.hpp"
#include "emit/formats.hpp"
#include "report/gnuplot.hpp"

namespace eomgen::studies {

namespace {

std::string run_line(const SceneAnalysis& a, const SceneRun& r) {
  return fmt::format("{} model, {} ({}): error {:.3g}, work {:.4g} operations ({} rhs, {} Jacobians), {:.3g} ms",
                     a.candidates[r.candidate].model, r.integrator, r.setting, r.error, r.work, r.rhs_evaluations,
                     r.jacobian_evaluations, 1e3 * r.cpu_seconds);
}

// the cheapest run of each candidate that meets the accuracy, or its closest
std::vector<const SceneRun*> best_per_candidate(const SceneAnalysis& a) {
  std::vector<const SceneRun*> best(a.candidates.size(), nullptr);
  for (const SceneRun& r : a.runs) {
    if (r.stopped) continue;
    const SceneRun*& b = best[r.candidate];
    bool better = !b || (r.meets_accuracy && (!b->meets_accuracy || r.work < b->work)) ||
                  (!r.meets_accuracy && !b->meets_accuracy && r.error < b->error);
    if (better) b = &r;
  }
  // a candidate whose runs were stopped may have met the accuracy at more work: its failures are not its best
  for (const SceneRun& r : a.runs)
    if (r.stopped && best[r.candidate] && !best[r.candidate]->meets_accuracy) best[r.candidate] = nullptr;
  return best;
}

std::string run_json(const SceneAnalysis& a, const SceneRun& r) {
  return fmt::format("{{\"model\": {}, \"integrator\": \"{}\", \"setting\": \"{}\", \"error\": {}, \"cpu_s\": {}, "
                     "\"rhs_evaluations\": {}, \"rhs_operations\": {}, \"work\": {}, \"meets_accuracy\": {}, "
                     "\"rejected_because\": {}}}",
                     json_quoted(a.candidates[r.candidate].model), r.integrator, r.setting, json_number(r.error),
                     json_number(r.cpu_seconds), r.rhs_evaluations, a.candidates[r.candidate].rhs_operations, json_number(r.work),
                     r.meets_accuracy ? "true" : "false",
                     r.rejected_because.empty() ? "null" : json_quoted(r.rejected_because));
}

// a candidate the interruption came before
bool never_ran(const SceneAnalysis& a, std::size_t c) {
  return a.interrupted && std::none_of(a.runs.begin(), a.runs.end(), [c](const SceneRun& r) { return r.candidate == c; });
}

std::string verdict(const SceneAnalysis& a) {
  if (a.interrupted)
    return fmt::format("interrupted (SIGINT or SIGTERM) after {} runs: a partial scene; {}", a.runs.size(),
                       a.chosen ? "cheapest so far: " + run_line(a, a.runs[*a.chosen]) : "no run so far meets the accuracy");
  if (a.chosen) return "chosen: " + run_line(a, a.runs[*a.chosen]);
  return a.closest ? "no candidate reaches the accuracy; closest: " + run_line(a, a.runs[*a.closest])
                   : "no candidate ran";
}

}  // namespace

void print_scene_text(const SceneAnalysis& a) {
  std::string outputs;
  for (const std::string& y : a.scene.outputs) outputs += (outputs.empty() ? "" : ", ") + y;
  std::cout << fmt::format("{}, scene {}: {} to t = {:g}, accuracy {:g} of each output's range{}\n", a.model_name, a.scene.name,
                           outputs, a.scene.t_end, a.scene.accuracy,
                           a.scene.absolute > 0 ? fmt::format(" + {:g}", a.scene.absolute) : "");
  std::cout << fmt::format("  reference: the full model with {}\n", a.reference_integrator);
  std::vector<const SceneRun*> best = best_per_candidate(a);
  for (std::size_t c = 0; c < a.candidates.size(); ++c) {
    const SceneCandidate& k = a.candidates[c];
    if (!k.refusal.empty()) std::cout << fmt::format("  {}: not run: {}\n", k.model, k.refusal);
    else if (never_ran(a, c)) std::cout << fmt::format("  {} ({}): not run: the scene was interrupted first\n", k.model, k.description);
    else if (best[c])
      std::cout << fmt::format("  {} ({}): best run {} ({}), error {:.3g}, work {:.4g}{}\n", k.model, k.description,
                               best[c]->integrator, best[c]->setting, best[c]->error, best[c]->work,
                               best[c]->meets_accuracy ? "" : fmt::format("; never meets the accuracy ({})", best[c]->rejected_because));
    else
      std::cout << fmt::format("  {} ({}): no run met the accuracy within ten times the work of a cheaper run that did\n",
                               k.model, k.description);
  }
  std::cout << "  " << verdict(a) << "\n";
  if (!a.noise_note.empty()) std::cout << "  note: " << a.noise_note << "; the choice between them is within measurement noise\n";
}

void print_scene_json(const SceneAnalysis& a) {
  std::string runs, outputs;
  for (const SceneRun& r : a.runs) runs += (runs.empty() ? "" : ", ") + run_json(a, r);
  for (const std::string& y : a.scene.outputs) outputs += fmt::format("{}{}", outputs.empty() ? "" : ", ", json_quoted(y));
  std::cout << fmt::format("{{\"scene\": {}, \"model\": {}, \"outputs\": [{}], \"accuracy\": {}, \"absolute\": {}, "
                           "\"reference\": {{\"integrator\": \"{}\", \"error_estimate\": {}}}, \"candidates\": [{}], "
                           "\"chosen\": {}, \"closest\": {}, \"noise_note\": {}, \"partial\": {}}}\n",
                           json_quoted(a.scene.name), json_quoted(a.model_name), outputs, json_number(a.scene.accuracy),
                           json_number(a.scene.absolute), a.reference_integrator, json_number(a.reference_error_estimate), runs,
                           a.chosen ? run_json(a, a.runs[*a.chosen]) : "null", a.closest ? run_json(a, a.runs[*a.closest]) : "null",
                           a.noise_note.empty() ? "null" : json_quoted(a.noise_note), a.interrupted ? "true" : "false");
}

std::string write_scene_files(const SceneAnalysis& a, const std::string& directory) {
  if (std::string failure = make_output_directory(directory); !failure.empty()) return failure;
  std::string csv = "model,integrator,setting,error,work,cpu_s,rhs_evaluations,jacobian_evaluations,meets_accuracy\n";
  for (const SceneRun& r : a.runs)
    csv += fmt::format("{},{},{},{:.6g},{:.6g},{:.6g},{},{},{}\n", a.candidates[r.candidate].model, r.integrator, r.setting,
                       r.error, r.work, r.cpu_seconds, r.rhs_evaluations, r.jacobian_evaluations, r.meets_accuracy ? 1 : 0);
  std::string md = fmt::format("# Scene {} of {}\n\n{}\n\n| model | what | best run | error | work |\n|---|---|---|---|---|\n",
                               a.scene.name, a.model_name, verdict(a));
  std::vector<const SceneRun*> best = best_per_candidate(a);
  for (std::size_t c = 0; c < a.candidates.size(); ++c)
    md += never_ran(a, c) ? fmt::format("| {} | {} | not run: the scene was interrupted first | | |\n", a.candidates[c].model,
                                        a.candidates[c].description)
          : best[c] ? fmt::format("| {} | {} | {} {} | {:.3g} | {:.4g} |\n", a.candidates[c].model, a.candidates[c].description,
                                best[c]->integrator, best[c]->setting, best[c]->error, best[c]->work)
                  : a.candidates[c].refusal.empty()
                      ? fmt::format("| {} | {} | no run met the accuracy within ten times the work of a cheaper run | | |\n", a.candidates[c].model,
                                    a.candidates[c].description)
                      : fmt::format("| {} | not run: {} | | | |\n", a.candidates[c].model, a.candidates[c].refusal);
  std::vector<std::pair<std::string, std::string>> files{{"candidates.csv", csv}, {"report.md", md}};
  if (a.chosen) {
    const SceneCandidate& c = a.candidates[a.runs[*a.chosen].candidate];
    files.push_back({c.equations.model_name + ".hpp", c.header});
    std::string rows = "t";
    for (const std::string& y : a.scene.outputs) rows += "," + y;
    rows += "\n";
    for (std::size_t i = 0; i < a.times.size(); ++i) {
      rows += fmt::format("{:.17g}", a.times[i]);
      for (const auto& column : a.chosen_outputs) rows += fmt::format(",{:.17g}", column[i]);
      rows += "\n";
    }
    files.push_back({"chosen.csv", rows});
  }
  for (const auto& [name, text] : files)
    if (std::string failure = write_file_atomically(directory + "/" + name, text); !failure.empty()) return failure;
  // error against work, one mark per run, one series per model, the accuracy as a line
  std::string data = directory + "/error_vs_work.data.tmp", png = directory + "/error_vs_work.png";
  std::ofstream(data) << csv;
  std::string plot = fmt::format("set terminal pngcairo size 1000,620 noenhanced\nset output {}\nset title {}\nset datafile separator ','\n"
                                 "set logscale xy\nset grid\nset xlabel 'work [operations of the generated code]'\n"
                                 "set ylabel 'error / output range'\nset key outside right\nset arrow from graph 0, first {} to graph 1, first {} nohead dt 2 lw 2\nplot ",
                                 runtime::gnuplot_quoted(png),
                                 runtime::gnuplot_quoted(fmt::format("{}, scene {}: error against work (dashed: the accuracy)", a.model_name, a.scene.name)),
                                 a.scene.accuracy, a.scene.accuracy);
  for (std::size_t c = 0; c < a.candidates.size(); ++c)
    if (a.candidates[c].refusal.empty())
      plot += fmt::format("{}{} using (strcol(1) eq '{}' && $5 > 0 && $4 > 0 ? $5 : NaN):4 skip 1 with points pt 7 ps 1.2 title '{}'",
                          plot.back() == ' ' ? "" : ", ", runtime::gnuplot_quoted(data), a.candidates[c].model, a.candidates[c].model);
  std::string failure = runtime::run_gnuplot(plot + "\n", png);
  std::remove(data.c_str());
  if (!failure.empty()) std::cerr << "eomgen: warning: no chart " << png << ": " << failure << "\n";
  return "";
}

}  // namespace eomgen::studies
