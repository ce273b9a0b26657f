#include "import/massless_bodies.hpp"

#include "import/xml_text.hpp"

#include <algorithm>
#include <regex>

#include <fmt/format.h>

namespace eomgen {

bool refuses_massless_bodies(const std::string& message, const std::vector<std::string>& texts) {
  if (message.find("mass and inertia of moving bodies must be larger than mjMINVAL") == std::string::npos) return false;
  static const std::regex negative("(?:mass|value|density)\\s*=\\s*[\"']\\s*-");
  return std::none_of(texts.begin(), texts.end(), [](const std::string& text) { return std::regex_search(text, negative); });
}

int line_naming(const std::string& text, const std::string& name) {
  for (const char* quote : {"\"", "'"}) {
    std::size_t at = text.find(std::string("name=") + quote + name + quote);
    if (at != std::string::npos) return int(std::count(text.begin(), text.begin() + long(at), '\n')) + 1;
  }
  return 0;
}

std::string with_mass_bounds(const std::string& text) {
  const std::string bounds = fmt::format(" boundmass=\"{0}\" boundinertia=\"{0}\"", massless_bound);
  std::string out = text;
  std::size_t mujoco = element_start(out, "mujoco");
  if (mujoco == std::string::npos) {  // a URDF without a <mujoco> element
    std::size_t robot = element_start(out, "robot");
    std::size_t inside = robot == std::string::npos ? robot : past_tag(out, robot);
    if (inside == std::string::npos || out[inside - 2] == '/') return text;
    return out.insert(inside, "<mujoco><compiler" + bounds + "/></mujoco>");
  }
  std::size_t compiler = element_start(out.substr(0, out.find("</mujoco", mujoco)), "compiler", mujoco);
  if (compiler != std::string::npos) {
    std::size_t end = past_tag(out, compiler);
    if (attribute(out, compiler, end, "boundmass") || attribute(out, compiler, end, "boundinertia")) return text;
    return out.insert(compiler + 9, bounds);
  }
  std::size_t inside = past_tag(out, mujoco);
  if (inside == std::string::npos || out[inside - 2] == '/') return text;
  return out.insert(inside, "<compiler" + bounds + "/>");
}

std::string joint_moving_no_mass(const mjModel* model) {
  mjData* data = mj_makeData(model);
  mj_forward(model, data);
  std::string name;
  // a joint that moves only bounded bodies has M_jj of a few bounds times its levers squared
  for (int v = 0; v < model->nv && name.empty(); ++v)
    if (data->qM[model->dof_Madr[v]] - model->dof_armature[v] < 1e3 * massless_bound)
      name = model->names + model->name_jntadr[model->dof_jntid[v]];
  mj_deleteData(data);
  return name;
}

std::vector<std::string> without_mass_bounds(std::vector<RobotBody>& bodies) {
  std::vector<std::string> massless;
  for (RobotBody& b : bodies) {
    bool raised = b.mass == massless_bound;
    if (raised) b.mass = 0;
    for (double& moment : b.principal_inertia)
      if (moment == massless_bound) moment = 0, raised = true;
    if (raised && !b.joints.empty()) massless.push_back(b.name);
  }
  return massless;
}

}  // namespace eomgen
