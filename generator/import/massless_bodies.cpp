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
  return with_compiler_attributes(text, fmt::format(" boundmass=\"{0}\" boundinertia=\"{0}\"", massless_bound),
                                  {"boundmass", "boundinertia"});
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
