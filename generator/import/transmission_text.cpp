#include "import/transmission_text.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <utility>

namespace eomgen {

namespace {

// gear × (gainprm·u + bias0 + bias1·gear·q + bias2·gear·q'), MuJoCo's actuator force along its
// joint (q its angle, or a fixed tendon's length) times the gear, with u clamped to the control range
// and the force to the force range where MuJoCo clamps them (ctrllimited, forcelimited)
std::string actuator_force(const RobotActuator& a, const std::string& u, const std::string& q, const std::string& rate) {
  std::string control = a.limited ? fmt::format("clamp({}, {}, {})", u, format_number(a.range[0]), format_number(a.range[1])) : u;
  auto with_sign = [](double coefficient, const std::string& factor) {
    return fmt::format(" {} {}{}", coefficient < 0 ? "-" : "+", format_number(std::abs(coefficient)), factor.empty() ? "" : "*" + factor);
  };
  std::array<std::pair<double, std::string>, 3> bias{
      {{a.bias[0], std::string()}, {a.gear * a.bias[1], q}, {a.gear * a.bias[2], rate}}};
  if (!a.force_limited) {
    std::string term = a.gain == 1 ? control : fmt::format("{}*{}", format_number(a.gain), control);
    for (const auto& [coefficient, factor] : bias)
      if (coefficient != 0) term += with_sign(a.gear * coefficient, factor);
    return term;
  }
  double gain = a.gear != 0 ? a.gain / a.gear : 0;  // gainprm
  std::string force = gain == 1 ? control : fmt::format("{}*{}", format_number(gain), control);
  for (const auto& [coefficient, factor] : bias)
    if (coefficient != 0) force += with_sign(coefficient, factor);
  std::string clamped = fmt::format("clamp({}, {}, {})", force, format_number(a.force_range[0]), format_number(a.force_range[1]));
  return a.gear == 1 ? clamped : fmt::format("{}*{}", format_number(a.gear), clamped);
}

// Σ cᵢ θᵢ and Σ cᵢ θᵢ' of the joints, in the model's coordinates (a single joint's own angle and rate)
std::pair<std::string, std::string> length_and_rate(const std::vector<TendonJoint>& joints,
                                                    const std::vector<std::vector<JointSymbols>>& joint_symbols) {
  std::string length, rate;
  for (const TendonJoint& j : joints) {
    const JointSymbols& s = joint_symbols[std::size_t(j.body)][std::size_t(j.joint)];
    double size = length.empty() ? j.coefficient : std::abs(j.coefficient);
    std::string sign = length.empty() ? "" : j.coefficient < 0 ? " - " : " + ";
    std::string c = size == 1 ? "" : size == -1 ? "-" : format_number(size) + "*";
    length += sign + c + s.angle();
    rate += sign + c + s.rate();
  }
  if (joints.size() > 1) length = "(" + length + ")", rate = "(" + rate + ")";
  return {length, rate};
}

}  // namespace

// a fixed tendon's spring and damper: ½ k (L − L₀)² and ½ d L'² into [energy]
void add_tendon_springs(const Robot& robot, const std::vector<std::vector<JointSymbols>>& joint_symbols, Sections& out) {
  for (const RobotTendonSpring& t : robot.tendon_springs) {
    auto [length, rate] = length_and_rate(t.joints, joint_symbols);
    if (t.stiffness != 0)
      out.potential.push_back(t.rest_length == 0 ? fmt::format("{}*{}^2", format_number(t.stiffness), length)
                                                 : fmt::format("{}*({} - {})^2", format_number(t.stiffness), length,
                                                               format_number(t.rest_length)));
    if (t.damping != 0) out.dissipation.push_back(fmt::format("{}*{}^2", format_number(t.damping), rate));
  }
}

void add_actuators(const Robot& robot, const std::vector<std::vector<JointSymbols>>& joint_symbols, Names& names, Sections& out) {
  std::map<std::string, std::string> forces;
  std::vector<std::string> order;
  for (const RobotActuator& a : robot.actuators) {
    bool servo = a.bias != std::array<double, 3>{0, 0, 0};
    std::string u = names.take(a.name, servo ? "servo" : "motor");
    out.inputs += u + " = 0" +
                  (a.limited ? fmt::format("  # control range [{}, {}]: clamped, as MuJoCo clamps it", format_number(a.range[0]),
                                           format_number(a.range[1]))
                  : !a.remark.empty() ? "  # " + a.remark
                                      : "") +
                  "\n";
    // the joints it moves: its own, or its fixed tendon's, each with its coefficient
    std::vector<TendonJoint> moved = a.tendon.empty() ? std::vector<TendonJoint>{{a.body, a.joint, 1}} : a.tendon;
    auto [length, rate] = length_and_rate(moved, joint_symbols);
    std::vector<std::pair<std::string, double>> weights;  // generalized force per coordinate: weight × F
    for (const TendonJoint& j : moved) {
      const JointSymbols& s = joint_symbols[std::size_t(j.body)][std::size_t(j.joint)];
      // a joint that follows a coordinate passes m times its force on to it
      std::string coordinate = s.follows() ? s.leader : s.coordinates[0];
      double weight = j.coefficient * (s.follows() ? s.multiplier : 1);
      auto same = [&](const auto& w) { return w.first == coordinate; };
      if (auto found = std::find_if(weights.begin(), weights.end(), same); found != weights.end()) found->second += weight;
      else weights.emplace_back(coordinate, weight);
    }
    std::string force = actuator_force(a, u, length, rate);
    for (const auto& [q, weight] : weights) {
      if (weight == 0) continue;
      if (!forces.count(q)) order.push_back(q);
      forces[q] += (forces[q].empty() ? "" : " + ") + (weight == 1 ? force : fmt::format("{}*({})", format_number(weight), force));
    }
  }
  // MuJoCo 3's actuatorfrcrange: the joint's total clamped (a joint without actuators keeps none)
  for (std::size_t b = 0; b < robot.bodies.size(); ++b)
    for (std::size_t j = 0; j < robot.bodies[b].joints.size(); ++j) {
      const RobotJoint& joint = robot.bodies[b].joints[j];
      const JointSymbols& s = joint_symbols[b][j];
      if (!joint.actuator_force_limited || !forces.count(s.follows() ? s.leader : s.coordinates[0])) continue;
      if (s.follows()) {
        out.warnings.push_back(fmt::format("joint '{}' follows another's coordinate: the clamp of its total actuator force "
                                           "(actuatorfrcrange) is not carried",
                                           joint.name));
        continue;
      }
      std::string& total = forces[s.coordinates[0]];
      total = fmt::format("clamp({}, {}, {})", total, format_number(joint.actuator_force_range[0]),
                          format_number(joint.actuator_force_range[1]));
    }
  std::string generalized;
  for (const std::string& q : order) generalized += (generalized.empty() ? "" : ", ") + fmt::format("{} = \"{}\"", q, forces[q]);
  if (!generalized.empty()) out.forces += "\n[[forces]]\ngeneralized = { " + generalized + " }\n";
}

}  // namespace eomgen
