/// @file The equilibrium a stability analysis is about: one named by --at (checked), or one
/// searched for from the model's initial state; and the models the analyses refuse.
#include <iostream>

#include <fmt/format.h>

#include "analyse/equilibrium.hpp"
#include "analyse/first_order_form.hpp"
#include "analyse/state_check.hpp"
#include "analyse/unbalanced_rate.hpp"
#include "studies/equilibrium_choice.hpp"
#include "studies/exit_status.hpp"
#include "studies/loaded_problem.hpp"

namespace eomgen::studies {

namespace {

// the state an --at list names: given values, other coordinates as in the model, other velocities
// zero; `named` marks the given ones
std::optional<std::vector<double>> state_from_at(const eomgen_model_abi& m, const std::vector<double>& initial,
                                                 const std::vector<std::string>& at, std::vector<bool>& named) {
  std::vector<double> x = initial;
  for (std::size_t i = m.num_coordinates; i < m.num_states; ++i) x[i] = 0;
  if (!assign_states(m, at, "--at", x, &named)) return std::nullopt;
  return x;
}

// "name = value" of each state in `which`, or the names alone without x
std::string states_text(const eomgen_model_abi& m, const std::vector<std::size_t>& which, const std::vector<double>* x) {
  std::string text;
  for (std::size_t i : which)
    text += (text.empty() ? "" : ", ") + (x ? fmt::format("{} = {:.6g}", m.state_names[i], (*x)[i]) : std::string(m.state_names[i]));
  return text;
}

// Where --at names some states and the rest as given do not balance: the equilibrium or steady
// motion with the named ones held, the unnamed cyclic velocities started from the model's values
// (a spherical pendulum held at θ = 0.8 has its φ' = 3.75 for a conical motion; from φ' = 0 no
// Newton step leads there), said in a note; not converged where Newton found none (a Lagrange I
// model's state then on its constraints, closed around the named coordinates); none where nothing
// is free
std::optional<runtime::Equilibrium> completed_at(const runtime::Problem& problem, std::vector<double> x,
                                                 const std::vector<double>& initial, const std::vector<bool>& named) {
  const eomgen_model_abi& m = *problem.model;
  std::vector<std::size_t> free = runtime::unheld_unknowns(m, named);
  if (free.empty()) return std::nullopt;
  // (an Appell model's pseudo-velocities are not der(q): those not named stay zero)
  if (!runtime::has_pseudo_velocities(m))
    for (std::size_t i = 0; i < m.num_coordinates; ++i)
      if (m.is_cyclic[i] && !named[m.num_coordinates + i]) x[m.num_coordinates + i] = initial[m.num_coordinates + i];
  runtime::Equilibrium completed = runtime::complete_equilibrium(problem, std::move(x), named);
  if (completed.converged && !runtime::unfit_state(problem, 0.0, completed.state).empty()) completed.converged = false;
  completed.note = fmt::format("the state given by --at does not balance with the other values as given; with the "
                               "named ones held, {} does", states_text(m, free, &completed.state));
  return completed;
}

// a state where M or f is not finite, or M is singular, has no meaningful linearization
std::optional<int> refuse_unfit(const runtime::Problem& problem, const std::vector<double>& x, const char* which) {
  std::string why = runtime::unfit_state(problem, 0.0, x);
  if (why.empty()) return std::nullopt;
  std::cerr << fmt::format("eomgen: error: no stability analysis at {}: {}\n", which, why);
  return exit_numerical_failure;
}

// says that no equilibrium exists, and returns true, when at rest a velocity's rate, or its row's
// generalized force, is one number in every configuration, where Newton could only report that it
// found none
bool say_unbalanced_rate(const runtime::Problem& problem, const std::vector<double>& initial) {
  std::optional<runtime::UnbalancedRate> unbalanced = runtime::unbalanced_rate(problem, initial);
  if (!unbalanced) return false;
  const eomgen_model_abi& m = *problem.model;
  std::cerr << fmt::format("eomgen: error: no equilibrium exists: at rest, {}{} {} {:.6g} in every configuration tried "
                           "({} about the initial one), so nothing balances what drives it\n  hint: {}\n",
                           unbalanced->force ? "the generalized force of the row of " : "",
                           m.state_names[m.num_coordinates + unbalanced->velocity],
                           unbalanced->force ? "is" : "changes at the rate", unbalanced->rate, unbalanced->configurations,
                           m.num_quaternions ? "a floating base falls unless something holds it: hold it (a robot imported "
                                               "without --free-base stands on a fixed base) to analyse its joints, or add "
                                               "the force that holds it"
                                             : "an equilibrium needs a force that balances this one (a spring, a support, "
                                               "an input)");
  return true;
}

}  // namespace

std::optional<int> stability_refusal(const LoadedProblem& loaded, const std::string& model, bool symbolic,
                                      bool on_manifold) {
  // stability and sweep analyse a Lagrange I model on its constraint manifold; the symbolic
  // conditions and `linear` need independent coordinates
  if (loaded.equations.has_multipliers && (symbolic || !on_manifold)) {
    std::cerr << fmt::format("eomgen: error: {} is a Lagrange I model: its coordinates are not independent{}\n  hint: "
                             "derive it with method = \"appell\" (independent pseudo-velocities){}\n", model,
                             symbolic ? ", and symbolic conditions need them" : "",
                             symbolic ? ", or leave out --symbolic (the numeric analysis works on the constraint manifold)" : "");
    return exit_user_error;
  }
  if (symbolic && !loaded.equations.intermediates.empty()) {
    std::cerr << fmt::format("eomgen: error: {}: symbolic stability conditions differentiate equations written out in q; "
                             "those of ball and free joints hold the frames' quantities\n  hint: leave out --symbolic (the numeric analysis "
                             "works from the generated code)\n",
                             model);
    return exit_user_error;
  }
  if (symbolic && loaded.equations.uses_pseudo_velocities()) {
    std::cerr << "eomgen: error: symbolic stability conditions need the second-order form M q'' + P q' + Q q; Appell "
                 "models are analysed numerically (leave out --symbolic)\n";
    return exit_user_error;
  }
  return std::nullopt;
}

std::optional<int> equilibrium_of(const runtime::Problem& problem, const std::vector<std::string>& at_texts,
                                  const std::vector<double>& initial, runtime::Equilibrium& out) {
  const eomgen_model_abi& m = *problem.model;
  if (!at_texts.empty()) {
    std::vector<bool> named;
    auto x = state_from_at(m, initial, at_texts, named);
    if (!x) return exit_user_error;
    if (auto status = refuse_unfit(problem, *x, "the state given by --at")) return status;
    out = runtime::check_equilibrium(problem, *x);
    std::optional<runtime::Equilibrium> completed;
    if (!out.converged && out.moving.empty()) completed = completed_at(problem, *x, initial, named);
    if (completed && completed->converged) {
      out = *completed;
      std::cerr << "eomgen: note: " << out.note << "\n";
      return std::nullopt;
    }
    if (!out.unmet.empty() && completed && completed->unmet.empty()) {
      std::cerr << fmt::format("eomgen: error: the state given by --at is not an equilibrium: with the named values "
                               "held, the constraints close at {}, where the largest residual of the equations of motion is "
                               "{:.3g} (tolerance {:.3g})\n  hint: leave out --at to search for an equilibrium on the "
                               "constraints\n", states_text(m, runtime::unheld_unknowns(m, named), &completed->state),
                               completed->residual, completed->tolerance);
      return exit_user_error;
    }
    if (!out.unmet.empty()) {
      std::cerr << fmt::format("eomgen: error: the state given by --at is not an equilibrium: its configuration does not "
                               "meet the constraints: {}\n  hint: name coordinates that meet them (the other coordinates "
                               "are as in the model), or leave out --at to search for an equilibrium on them\n", out.unmet);
      return exit_user_error;
    }
    if (!out.moving.empty()) {
      std::cerr << fmt::format("eomgen: error: the state given by --at is not an equilibrium: {} moves a coordinate that "
                               "is not cyclic, so the configuration and with it the forces change\n  hint: only cyclic "
                               "coordinates (ones no equation depends on) may move in a steady motion; leave out --at "
                               "to search for an equilibrium\n", out.moving);
      return exit_user_error;
    }
    if (!out.converged) {
      std::vector<std::size_t> free = runtime::unheld_unknowns(m, named);
      std::cerr << fmt::format("eomgen: error: the state given by --at is not an equilibrium: the largest residual of "
                               "the equations of motion is {:.3g} (tolerance {:.3g}){}\n  hint: leave out --at to search "
                               "for one from the model's initial values\n", out.residual, out.tolerance,
                               free.empty() ? "" : "; with the named values held, Newton on " + states_text(m, free, nullptr) + " found none either");
      return exit_user_error;
    }
    return std::nullopt;
  }
  if (auto status = refuse_unfit(problem, initial, "the model's initial state (where the search starts)")) return status;
  out = runtime::find_equilibrium(problem, initial);
  if (!out.converged && say_unbalanced_rate(problem, initial)) return exit_user_error;
  if (!out.converged) {
    std::cerr << fmt::format("eomgen: no equilibrium found near the model's initial values after {} Newton steps "
                             "({})\n  hint: name one with --at q=VALUE (and --at 'der(q)=VALUE' for a "
                             "steady motion)\n", out.iterations, runtime::search_end_text(problem, out));
    return exit_numerical_failure;
  }
  if (!out.note.empty()) std::cerr << "eomgen: note: " << out.note << "\n";
  return refuse_unfit(problem, out.state, "the equilibrium found");
}

}  // namespace eomgen::studies
