#include "fmu/fmu_nominals.hpp"

#include <dlfcn.h>

#include <cstdlib>

#include <fmt/format.h>

#include "fmu/fmi2.h"

namespace eomgen::runtime {

namespace {

template <class F>
F bound(void* library, const char* name, std::string& failure) {
  F f = reinterpret_cast<F>(dlsym(library, name));
  if (!f && failure.empty()) failure = fmt::format("the FMU binary does not export {}", name);
  return f;
}

extern "C" void quiet_fmu_logger(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String, fmi2String, ...) {}

std::vector<double> nominals_of(void* library, const std::string& guid, std::size_t states, std::string& failure) {
  auto instantiate = bound<decltype(&fmi2Instantiate)>(library, "fmi2Instantiate", failure);
  auto setup = bound<decltype(&fmi2SetupExperiment)>(library, "fmi2SetupExperiment", failure);
  auto enter = bound<decltype(&fmi2EnterInitializationMode)>(library, "fmi2EnterInitializationMode", failure);
  auto leave = bound<decltype(&fmi2ExitInitializationMode)>(library, "fmi2ExitInitializationMode", failure);
  auto nominals = bound<decltype(&fmi2GetNominalsOfContinuousStates)>(library, "fmi2GetNominalsOfContinuousStates", failure);
  auto release = bound<decltype(&fmi2FreeInstance)>(library, "fmi2FreeInstance", failure);
  if (!failure.empty()) return {};
  const fmi2CallbackFunctions callbacks{quiet_fmu_logger, std::calloc, std::free, nullptr, nullptr};
  fmi2Component c = instantiate("eomgen", fmi2ModelExchange, guid.c_str(), "", &callbacks, fmi2False, fmi2False);
  if (!c) {
    failure = "the FMU binary refused to be instantiated";
    return {};
  }
  std::vector<double> out(states);
  bool ok = setup(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) == fmi2OK && enter(c) == fmi2OK && leave(c) == fmi2OK &&
            nominals(c, out.data(), states) == fmi2OK;
  release(c);
  if (!ok) failure = "the FMU binary gave no nominals at its default values";
  return ok ? out : std::vector<double>{};
}

}  // namespace

std::vector<double> fmu_state_nominals(const std::string& library_path, const std::string& guid, std::size_t states,
                                       std::string& failure) {
  void* library = dlopen(library_path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!library) {
    failure = fmt::format("cannot load {}: {}", library_path, dlerror());
    return {};
  }
  std::vector<double> out = nominals_of(library, guid, states, failure);
  dlclose(library);
  return out;
}

}  // namespace eomgen::runtime
