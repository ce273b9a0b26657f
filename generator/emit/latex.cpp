#include <cctype>

#include <fmt/format.h>

#include "emit/formats.hpp"
#include "symbolic/canonical_print.hpp"

namespace eomgen {

namespace {

const std::vector<std::string> greek = {
    "alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta", "theta", "vartheta",
    "iota", "kappa", "lambda", "mu", "nu", "xi", "pi", "varpi", "rho", "sigma", "tau", "upsilon",
    "phi", "varphi", "chi", "psi", "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma",
    "Upsilon", "Phi", "Psi", "Omega"};

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '_' ? std::string("\\_") : std::string(1, c);
  return out;
}

// phi1 → \phi_{1}, m_cart → m_{\mathrm{cart}}, mass → \mathrm{mass}
std::string tex_base(const std::string& name, std::string& subscript) {
  std::size_t split = name.find('_');
  std::string head = name.substr(0, split), tail = split == std::string::npos ? "" : name.substr(split + 1);
  if (tail.empty()) {
    std::size_t d = head.size();
    while (d > 0 && std::isdigit(static_cast<unsigned char>(head[d - 1]))) --d;
    if (d > 0 && d < head.size()) {
      tail = head.substr(d);
      head = head.substr(0, d);
    }
  }
  bool is_number = !tail.empty() && std::all_of(tail.begin(), tail.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
  subscript = tail.empty() ? "" : (is_number || tail.size() == 1 ? tail : "\\mathrm{" + escape(tail) + "}");
  if (std::find(greek.begin(), greek.end(), head) != greek.end()) return "\\" + head;
  return head.size() == 1 ? head : "\\mathrm{" + escape(head) + "}";
}

std::string tex_name(const std::string& name) {
  std::string sub;
  std::string base = tex_base(name, sub);
  return sub.empty() ? base : base + "_{" + sub + "}";
}

std::string tex_symbol(const GiNaC::symbol& s) {
  std::string name = s.get_name();
  // der(x) → \dot{x}; der(der(x)), a pseudo-acceleration of an independent velocity → \ddot{x}
  const char* accent = name.rfind("der(der(", 0) == 0 ? "\\ddot{" : name.rfind("der(", 0) == 0 ? "\\dot{" : nullptr;
  if (accent) {
    std::size_t depth = accent[2] == 'd' ? 2 : 1;
    std::string sub;
    std::string base = tex_base(name.substr(4 * depth, name.size() - 5 * depth), sub);
    return accent + base + "}" + (sub.empty() ? "" : "_{" + sub + "}");
  }
  return tex_name(name);
}

std::string tex(const GiNaC::ex& e) { return latex_text(e, tex_symbol); }

}  // namespace

std::string emit_latex(const Equations& e) {
  std::size_t n = e.forcing.size();
  std::string out = fmt::format("%% {}: {} (method {})\n%% M(q,t) \\ddot q = f(q, \\dot q, u, t)\n", e.model_name,
                                e.title, e.method);
  out += "\\begin{align*}\n";
  // recursive kinematics: the frames' and bodies' quantities, in order of computation
  for (const Intermediate& i : e.intermediates)
    out += fmt::format("{} &= {} \\\\\n", tex(i.symbol), tex(i.definition));
  for (unsigned j = 0; j < n; ++j)
    for (unsigned k = j; k < n; ++k)
      out += fmt::format("M_{{{}{}}} &= {} \\\\\n", j + 1, k + 1, tex(e.mass_matrix(j, k)));
  for (unsigned j = 0; j < n; ++j) out += fmt::format("f_{{{}}} &= {} \\\\\n", j + 1, tex(e.forcing[j]));
  out += fmt::format("T &= {} \\\\\nV &= {} \\\\\nR &= {}", tex(e.kinetic_energy), tex(e.potential_energy),
                     tex(e.dissipation));
  for (const NamedSymbolic& o : e.outputs) out += fmt::format(" \\\\\n{} &= {}", tex_name(o.name), tex(o.expression));
  for (unsigned i = 0; i < e.constraints.size(); ++i) {
    const ConstraintSet& c = e.constraints;
    std::string velocity;
    for (unsigned j = 0; j < c.jacobian.cols(); ++j)
      if (!c.jacobian(i, j).is_zero())
        velocity += fmt::format("{}\\left({}\\right) \\dot {{{}}}", velocity.empty() ? "" : " + ", tex(c.jacobian(i, j)),
                                tex_name(e.symbols.coordinate_names[j]));
    if (!c.bias[i].is_zero()) velocity += " + " + tex(c.bias[i]);
    out += fmt::format(" \\\\\n0 &= {} & \\text{{({})}}", c.holonomic[i] ? tex(c.position[i]) : velocity,
                       tex_name(c.names[i]));
  }
  if (e.uses_pseudo_velocities()) {
    for (std::size_t j = 0; j < e.coordinate_rates.size(); ++j)
      out += fmt::format(" \\\\\n\\dot {{{}}} &= {}", tex_name(e.symbols.coordinate_names[j]), tex(e.coordinate_rates[j]));
    if (e.method == "hamilton") out += fmt::format(" \\\\\nH &= {}", tex(e.hamiltonian));
    else if (e.acceleration_energy_formed()) out += fmt::format(" \\\\\nS &= {}", tex(e.acceleration_energy));
  }
  for (const FirstIntegral& f : e.first_integrals)
    out += fmt::format(" \\\\\n{} &= {} & \\text{{(first integral)}}", tex_name(f.name == "jacobi_integral" ? "h" : f.name == "energy" ? "E" : f.name),
                       tex(f.expression));
  if (e.has_linearization) {
    out += " \\\\\n% linearization M q'' + P q' + Q q = B u about a state with q'' = 0";
    for (unsigned j = 0; j < n; ++j)
      for (unsigned k = 0; k < n; ++k)
        out += fmt::format(" \\\\\nP_{{{}{}}} &= {}", j + 1, k + 1, tex(e.linear_damping_gyroscopic(j, k)));
    for (unsigned j = 0; j < n; ++j)
      for (unsigned k = 0; k < e.linear_stiffness_circulatory.cols(); ++k)
        out += fmt::format(" \\\\\nQ_{{{}{}}} &= {}", j + 1, k + 1, tex(e.linear_stiffness_circulatory(j, k)));
    for (unsigned j = 0; j < n; ++j)
      for (unsigned k = 0; k < e.symbols.inputs.size(); ++k)
        out += fmt::format(" \\\\\nB_{{{}{}}} &= {}", j + 1, k + 1, tex(e.linear_input(j, k)));
  }
  out += "\n\\end{align*}\n";
  return out;
}

}  // namespace eomgen
