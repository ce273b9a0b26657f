// `eomgen fmu` against an importer written here from the FMI 2.0 specification: the FMU is
// unzipped by Python's zipfile (an independent reader of the archive), its binary loaded with
// dlopen and driven through the fmi2 calls only. Model Exchange: the importer's own RK4 at
// 1e-3 s on fmi2GetDerivatives; Co-Simulation: fmi2DoStep (CVODE inside) at 0.1 s. Both match
// `eomgen simulate --integrator reference` to 1e-8, for the double pendulum and for the cart
// pendulum pushed by its input F; the directional derivatives match differences of the
// derivatives; and modelDescription.xml, valid against the FMI 2.0 schema (xmllint), names what
// the binary computes.
#include <gtest/gtest.h>

#include <dlfcn.h>

#include <cmath>
#include <cstdarg>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>

#include "fmu/fmi2.h"
#include "support/small_models.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

namespace fs = std::filesystem;

// the fmi2 functions of one loaded binary
struct Fmi2 {
  void* library = nullptr;
  decltype(&fmi2Instantiate) instantiate = nullptr;
  decltype(&fmi2FreeInstance) free_instance = nullptr;
  decltype(&fmi2SetupExperiment) setup_experiment = nullptr;
  decltype(&fmi2EnterInitializationMode) enter_initialization = nullptr;
  decltype(&fmi2ExitInitializationMode) exit_initialization = nullptr;
  decltype(&fmi2SetReal) set_real = nullptr;
  decltype(&fmi2GetReal) get_real = nullptr;
  decltype(&fmi2NewDiscreteStates) new_discrete_states = nullptr;
  decltype(&fmi2EnterContinuousTimeMode) enter_continuous_time = nullptr;
  decltype(&fmi2SetTime) set_time = nullptr;
  decltype(&fmi2SetContinuousStates) set_states = nullptr;
  decltype(&fmi2GetContinuousStates) get_states = nullptr;
  decltype(&fmi2GetDerivatives) get_derivatives = nullptr;
  decltype(&fmi2GetDirectionalDerivative) directional_derivative = nullptr;
  decltype(&fmi2GetNominalsOfContinuousStates) nominals = nullptr;
  decltype(&fmi2DoStep) do_step = nullptr;
  decltype(&fmi2Terminate) terminate = nullptr;
  ~Fmi2() {
    if (library) dlclose(library);
  }
};

template <class F>
void bind(void* library, F& f, const char* name) {
  f = reinterpret_cast<F>(dlsym(library, name));
  if (!f) throw std::runtime_error(std::string("the FMU does not export ") + name);
}

void load(Fmi2& f, const std::string& path) {
  f.library = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!f.library) throw std::runtime_error(std::string("dlopen: ") + dlerror());
  bind(f.library, f.instantiate, "fmi2Instantiate"), bind(f.library, f.free_instance, "fmi2FreeInstance");
  bind(f.library, f.setup_experiment, "fmi2SetupExperiment");
  bind(f.library, f.enter_initialization, "fmi2EnterInitializationMode");
  bind(f.library, f.exit_initialization, "fmi2ExitInitializationMode");
  bind(f.library, f.set_real, "fmi2SetReal"), bind(f.library, f.get_real, "fmi2GetReal");
  bind(f.library, f.new_discrete_states, "fmi2NewDiscreteStates");
  bind(f.library, f.enter_continuous_time, "fmi2EnterContinuousTimeMode");
  bind(f.library, f.set_time, "fmi2SetTime"), bind(f.library, f.set_states, "fmi2SetContinuousStates");
  bind(f.library, f.get_states, "fmi2GetContinuousStates"), bind(f.library, f.get_derivatives, "fmi2GetDerivatives");
  bind(f.library, f.directional_derivative, "fmi2GetDirectionalDerivative");
  bind(f.library, f.nominals, "fmi2GetNominalsOfContinuousStates");
  bind(f.library, f.do_step, "fmi2DoStep"), bind(f.library, f.terminate, "fmi2Terminate");
}

extern "C" void log_to_stderr(fmi2ComponentEnvironment, fmi2String instance, fmi2Status, fmi2String category, fmi2String message, ...) {
  va_list args;
  va_start(args, message);
  std::fprintf(stderr, "[%s %s] ", instance, category);
  std::vfprintf(stderr, message, args);
  std::fprintf(stderr, "\n");
  va_end(args);
}

const fmi2CallbackFunctions callbacks{log_to_stderr, std::calloc, std::free, nullptr, nullptr};

// an unzipped FMU: its description's GUID, value references by name and number of states
struct Unpacked {
  std::string directory, description, guid;
  std::map<std::string, unsigned> reference;
  std::size_t states = 0;
};

Unpacked build_and_unpack(const std::string& model_file, const std::string& name) {
  Unpacked u;
  u.directory = temporary_directory();
  CommandOutput built = run_eomgen("fmu '" + model_file + "' -o '" + u.directory + "'");
  EXPECT_EQ(built.status, 0) << built.err;
  std::string fmu = u.directory + "/" + name + ".fmu";
  EXPECT_EQ(run_command("python3 -c 'import sys, zipfile; zipfile.ZipFile(sys.argv[1]).extractall(sys.argv[2])' '" + fmu + "' '" +
                        u.directory + "/unzipped'"),
            0);
  u.description = read_file(u.directory + "/unzipped/modelDescription.xml");
  std::smatch m;
  if (std::regex_search(u.description, m, std::regex("guid=\"([^\"]+)\""))) u.guid = m[1];
  std::regex variable("<ScalarVariable name=\"([^\"]+)\" valueReference=\"([0-9]+)\"");
  for (auto it = std::sregex_iterator(u.description.begin(), u.description.end(), variable); it != std::sregex_iterator(); ++it)
    u.reference[(*it)[1]] = unsigned(std::stoul((*it)[2]));
  std::string derivatives = u.description.substr(u.description.find("<Derivatives>"));
  derivatives = derivatives.substr(0, derivatives.find("</Derivatives>"));
  for (std::size_t at = derivatives.find("<Unknown"); at != std::string::npos; at = derivatives.find("<Unknown", at + 1)) ++u.states;
  return u;
}

// `eomgen simulate` with the wide-scalar reference: the states at t = 0, 0.1, …, 2
std::vector<std::vector<double>> reference_run(const std::string& model, const std::string& sets, std::size_t states) {
  std::string csv = temporary_directory() + "/reference.csv";
  CommandOutput r = run_eomgen("simulate '" + model_path(model) + "' --integrator reference --t-end 2 --dt-out 0.1 " + sets +
                               " -o '" + csv + "'");
  EXPECT_EQ(r.status, 0) << r.err;
  std::vector<std::vector<double>> out;
  for (const auto& row : read_numeric_csv(csv)) out.emplace_back(row.begin() + 1, row.begin() + 1 + long(states));
  return out;
}

double largest_difference(const std::vector<std::vector<double>>& a, const std::vector<std::vector<double>>& b) {
  double worst = a.size() == b.size() ? 0 : INFINITY;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
    for (std::size_t i = 0; i < a[k].size(); ++i) worst = std::max(worst, std::abs(a[k][i] - b[k][i]));
  return worst;
}

fmi2Component instantiate(const Fmi2& f, const Unpacked& u, fmi2Type kind, const std::map<std::string, double>& values) {
  fmi2Component c = f.instantiate("test", kind, u.guid.c_str(), "", &callbacks, fmi2False, fmi2False);
  if (!c) return nullptr;
  f.setup_experiment(c, fmi2True, 1e-13, 0.0, fmi2False, 0.0);  // CVODE's rtol in Co-Simulation
  f.enter_initialization(c);
  for (const auto& [name, value] : values) {
    unsigned r = u.reference.at(name);
    f.set_real(c, &r, 1, &value);
  }
  f.exit_initialization(c);
  return c;
}

// Model Exchange: RK4 at 1e-3 s on the FMU's derivatives, the states every 0.1 s
std::vector<std::vector<double>> model_exchange_run(const Fmi2& f, fmi2Component c, std::size_t n) {
  fmi2EventInfo info{};
  f.new_discrete_states(c, &info);
  f.enter_continuous_time(c);
  std::vector<double> x(n), k1(n), k2(n), k3(n), k4(n), y(n);
  f.get_states(c, x.data(), n);
  auto derivative = [&](double t, const std::vector<double>& state, std::vector<double>& out) {
    f.set_time(c, t), f.set_states(c, state.data(), n), f.get_derivatives(c, out.data(), n);
  };
  std::vector<std::vector<double>> out{x};
  const double h = 1e-3;
  for (int step = 1; step <= 2000; ++step) {
    double t = (step - 1) * h;
    derivative(t, x, k1);
    for (std::size_t i = 0; i < n; ++i) y[i] = x[i] + h / 2 * k1[i];
    derivative(t + h / 2, y, k2);
    for (std::size_t i = 0; i < n; ++i) y[i] = x[i] + h / 2 * k2[i];
    derivative(t + h / 2, y, k3);
    for (std::size_t i = 0; i < n; ++i) y[i] = x[i] + h * k3[i];
    derivative(t + h, y, k4);
    for (std::size_t i = 0; i < n; ++i) x[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    if (step % 100 == 0) out.push_back(x);
  }
  return out;
}

// Co-Simulation: fmi2DoStep every 0.1 s, the states read by value reference 0 … n−1
std::vector<std::vector<double>> co_simulation_run(const Fmi2& f, fmi2Component c, std::size_t n) {
  std::vector<unsigned> references(n);
  for (std::size_t i = 0; i < n; ++i) references[i] = unsigned(i);
  std::vector<double> x(n);
  f.get_real(c, references.data(), n, x.data());
  std::vector<std::vector<double>> out{x};
  for (int k = 0; k < 20; ++k) {
    EXPECT_EQ(f.do_step(c, 0.1 * k, 0.1, fmi2True), fmi2OK);
    f.get_real(c, references.data(), n, x.data());
    out.push_back(x);
  }
  return out;
}

// xmllint against the FMI 2.0 schema written out in tests/fmu/
void expect_valid_description(const Unpacked& u) {
  std::string log = u.directory + "/xmllint.txt";
  int status = run_command(std::string(EOMGEN_XMLLINT) + " --noout --schema '" + EOMGEN_SOURCE_DIR +
                           "/tests/fmu/fmi2ModelDescription.xsd' '" + u.directory + "/unzipped/modelDescription.xml' 2> '" + log + "'");
  EXPECT_EQ(status, 0) << read_file(log);
}

void check_fmu(const std::string& model, const std::map<std::string, double>& values, const std::string& sets) {
  Unpacked u = build_and_unpack(model_path(model), model);
  ASSERT_FALSE(u.guid.empty()) << u.description;
  expect_valid_description(u);
  Fmi2 f;
  load(f, u.directory + "/unzipped/binaries/linux64/" + model + ".so");
  auto reference = reference_run(model, sets, u.states);
  fmi2Component me = instantiate(f, u, fmi2ModelExchange, values);
  ASSERT_NE(me, nullptr);
  EXPECT_LT(largest_difference(model_exchange_run(f, me, u.states), reference), 1e-8) << "Model Exchange";
  f.terminate(me), f.free_instance(me);
  fmi2Component cs = instantiate(f, u, fmi2CoSimulation, values);
  ASSERT_NE(cs, nullptr);
  EXPECT_LT(largest_difference(co_simulation_run(f, cs, u.states), reference), 1e-8) << "Co-Simulation";
  f.terminate(cs), f.free_instance(cs);
  EXPECT_EQ(f.instantiate("wrong", fmi2ModelExchange, "{not-this-one}", "", &callbacks, fmi2False, fmi2False), nullptr)
      << "another FMU's GUID is refused";
}

TEST(Fmu, TheDoublePendulumMatchesTheReferenceInBothKinds) { check_fmu("double_pendulum", {}, ""); }

TEST(Fmu, TheCartPendulumPushedByItsInputMatchesTheReference) {
  check_fmu("cart_pendulum", {{"F", 0.5}, {"m", 0.3}}, "--set F=0.5 --set m=0.3");
}

// A MEMS oscillator, m = 1e-9 kg on k = 10 N/m (1e5 rad/s), released from a = 1e-9 m, at the
// importer's tolerance 1e-8: its nominals are its sizes, a and a ω, and Co-Simulation follows
// a cos(ω t) to 1e-6 of a over three periods. With an absolute tolerance of 1e-2 rtol in every
// unit (1e-10 m) and nominals of 1, it had been off by 2e-4 of a.
// Co-Simulation of a free body: its quaternion is unit at every communication point (CVODE's local
// errors had moved it off by 2e-11 at rtol 1e-13 over 100 s) and the motion is the reference
// integrator's; a quaternion set to zero from outside is refused by the step
TEST(Fmu, CoSimulationKeepsAFreeBodysQuaternionUnit) {
  Unpacked u = build_and_unpack(model_path("tumbling_body"), "tumbling_body");
  Fmi2 f;
  load(f, u.directory + "/unzipped/binaries/linux64/tumbling_body.so");
  fmi2Component c = instantiate(f, u, fmi2CoSimulation, {});
  ASSERT_NE(c, nullptr);
  std::vector<unsigned> references(u.states), quaternion;
  for (std::size_t i = 0; i < u.states; ++i) references[i] = unsigned(i);
  for (const char* name : {"qw", "qx", "qy", "qz"}) quaternion.push_back(u.reference.at(name));
  std::vector<double> q(4), x(u.states);
  double worst = 0;
  for (int k = 0; k < 100; ++k) {
    ASSERT_EQ(f.do_step(c, k, 1.0, fmi2True), fmi2OK);
    f.get_real(c, quaternion.data(), 4, q.data());
    worst = std::max(worst, std::abs(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]) - 1));
  }
  EXPECT_LT(worst, 4e-16);
  f.get_real(c, references.data(), u.states, x.data());
  std::string csv = temporary_directory() + "/tumbling.csv";
  ASSERT_EQ(run_eomgen("simulate '" + model_path("tumbling_body") + "' --integrator reference --t-end 100 --dt-out 10 -o '" +
                       csv + "'").status,
            0);
  std::vector<double> last = read_numeric_csv(csv).back();
  for (std::size_t i = 0; i < u.states; ++i) EXPECT_NEAR(x[i], last[i + 1], 1e-8 * (1 + std::abs(last[i + 1]))) << i;
  const double zero[4] = {0, 0, 0, 0};
  f.set_real(c, quaternion.data(), 4, zero);
  EXPECT_EQ(f.do_step(c, 100, 1.0, fmi2True), fmi2Error);
  f.terminate(c), f.free_instance(c);
}

TEST(Fmu, ASmallOscillatorHasItsOwnNominalsAndTolerances) {
  const double a = 1e-9, omega = 1e5;
  Unpacked u = build_and_unpack(write_model("small_oscillator", spring_mass_model("small_oscillator", 1e-9, 10.0, a)),
                                "small_oscillator");
  // the same nominals in modelDescription.xml, for importers that read them there (without, 1 m)
  std::smatch x, v;
  ASSERT_TRUE(std::regex_search(u.description, x, std::regex("name=\"x\"[^>]*>\\s*<Real [^>]*nominal=\"([^\"]+)\""))) << u.description;
  ASSERT_TRUE(std::regex_search(u.description, v, std::regex("name=\"der\\(x\\)\"[^>]*>\\s*<Real [^>]*nominal=\"([^\"]+)\"")))
      << u.description;
  EXPECT_NEAR(std::stod(x[1]) / a, 1, 1e-3);
  EXPECT_NEAR(std::stod(v[1]) / (a * omega), 1, 1e-3);
  Fmi2 f;
  load(f, u.directory + "/unzipped/binaries/linux64/small_oscillator.so");
  for (fmi2Type kind : {fmi2ModelExchange, fmi2CoSimulation}) {
    fmi2Component c = f.instantiate("test", kind, u.guid.c_str(), "", &callbacks, fmi2False, fmi2False);
    ASSERT_NE(c, nullptr);
    f.setup_experiment(c, fmi2True, 1e-8, 0.0, fmi2False, 0.0);
    f.enter_initialization(c), f.exit_initialization(c);
    double nominal[2];
    ASSERT_EQ(f.nominals(c, nominal, 2), fmi2OK);
    EXPECT_NEAR(nominal[0] / a, 1, 1e-12);
    EXPECT_NEAR(nominal[1] / (a * omega), 1, 1e-9);
    if (kind == fmi2CoSimulation) {
      double worst = 0, h = 2 * M_PI / omega / 50;
      unsigned x = 0;
      for (int k = 0; k < 150; ++k) {
        ASSERT_EQ(f.do_step(c, k * h, h, fmi2True), fmi2OK);
        double value = 0;
        f.get_real(c, &x, 1, &value);
        worst = std::max(worst, std::abs(value - a * std::cos(omega * (k + 1) * h)));
      }
      EXPECT_LT(worst, 1e-6 * a);
    }
    f.terminate(c), f.free_instance(c);
  }
}

TEST(Fmu, DirectionalDerivativesMatchDifferencesOfTheDerivatives) {
  Unpacked u = build_and_unpack(model_path("cart_pendulum"), "cart_pendulum");
  Fmi2 f;
  load(f, u.directory + "/unzipped/binaries/linux64/cart_pendulum.so");
  fmi2Component c = instantiate(f, u, fmi2ModelExchange, {{"F", 0.2}});
  ASSERT_NE(c, nullptr);
  std::size_t n = u.states;
  std::vector<double> x{0.1, 2.5, 0.3, -0.4}, direction{0.3, -0.7, 0.2, 0.5}, dx(n), plus(n), minus(n), shifted(n);
  f.set_time(c, 0.0), f.set_states(c, x.data(), n);
  std::vector<unsigned> knowns{0, 1, 2, 3}, unknowns;
  for (std::size_t i = 0; i < n; ++i) unknowns.push_back(unsigned(n + i));
  ASSERT_EQ(f.directional_derivative(c, unknowns.data(), n, knowns.data(), n, direction.data(), dx.data()), fmi2OK);
  const double h = 1e-6;
  for (std::size_t i = 0; i < n; ++i) shifted[i] = x[i] + h * direction[i];
  f.set_states(c, shifted.data(), n), f.get_derivatives(c, plus.data(), n);
  for (std::size_t i = 0; i < n; ++i) shifted[i] = x[i] - h * direction[i];
  f.set_states(c, shifted.data(), n), f.get_derivatives(c, minus.data(), n);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(dx[i], (plus[i] - minus[i]) / (2 * h), 1e-7) << i;
  // along the input F: the state derivatives through jacobian_input
  unsigned input = u.reference.at("F");
  double one = 1, along_input[4];
  f.set_states(c, x.data(), n);
  ASSERT_EQ(f.directional_derivative(c, unknowns.data(), n, &input, 1, &one, along_input), fmi2OK);
  double pushed = 0.2 + h, pulled = 0.2 - h;
  f.set_real(c, &input, 1, &pushed), f.get_derivatives(c, plus.data(), n);
  f.set_real(c, &input, 1, &pulled), f.get_derivatives(c, minus.data(), n);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(along_input[i], (plus[i] - minus[i]) / (2 * h), 1e-7) << i;
  f.free_instance(c);
}

TEST(Fmu, AModelWithoutOutputsIsWarnedAbout) {
  std::string directory = temporary_directory();
  CommandOutput built = run_eomgen("fmu '" + model_path("damped_two_mass_oscillator") + "' --kind me -o '" + directory + "'");
  ASSERT_EQ(built.status, 0) << built.err;
  EXPECT_NE(built.err.find("warning: the model has no [outputs]"), std::string::npos) << built.err;
}

TEST(Fmu, AModelExchangeBinaryNeedsNoSundials) {
  // Model Exchange hands x' to the importer's integrator: its binary carries no CVODE, and
  // refuses to be instantiated for Co-Simulation; the binary of both links CVODE
  std::string directory = temporary_directory();
  CommandOutput built = run_eomgen("fmu '" + model_path("damped_two_mass_oscillator") + "' --kind me -o '" + directory + "'");
  ASSERT_EQ(built.status, 0) << built.err;
  std::string unzip = "python3 -c 'import sys, zipfile; zipfile.ZipFile(sys.argv[1]).extractall(sys.argv[2])' '";
  ASSERT_EQ(run_command(unzip + directory + "/damped_two_mass_oscillator.fmu' '" + directory + "/me'"), 0);
  std::string binary = directory + "/me/binaries/linux64/damped_two_mass_oscillator.so";
  ASSERT_EQ(run_command("readelf -d '" + binary + "' > '" + directory + "/needed.txt'"), 0);
  std::string needed = read_file(directory + "/needed.txt");
  EXPECT_NE(needed.find("NEEDED"), std::string::npos) << needed;
  EXPECT_EQ(needed.find("sundials"), std::string::npos) << needed;
  Fmi2 f;
  load(f, binary);
  Unpacked u;
  u.guid = read_file(directory + "/me/modelDescription.xml");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(u.guid, m, std::regex("guid=\"([^\"]+)\"")));
  u.guid = m[1];
  EXPECT_EQ(f.instantiate("test", fmi2CoSimulation, u.guid.c_str(), "", &callbacks, fmi2False, fmi2False), nullptr);
  fmi2Component me = f.instantiate("test", fmi2ModelExchange, u.guid.c_str(), "", &callbacks, fmi2False, fmi2False);
  ASSERT_NE(me, nullptr);
  f.free_instance(me);
  Unpacked both = build_and_unpack(model_path("damped_two_mass_oscillator"), "damped_two_mass_oscillator");
  ASSERT_EQ(run_command("readelf -d '" + both.directory + "/unzipped/binaries/linux64/damped_two_mass_oscillator.so' > '" +
                        directory + "/needed_both.txt'"),
            0);
  EXPECT_NE(read_file(directory + "/needed_both.txt").find("libsundials_cvode"), std::string::npos);
}

TEST(Fmu, TheDescriptionNamesWhatTheBinaryComputes) {
  Unpacked u = build_and_unpack(model_path("cart_pendulum"), "cart_pendulum");
  const std::string& d = u.description;
  EXPECT_NE(d.find("<fmiModelDescription fmiVersion=\"2.0\" modelName=\"cart_pendulum\""), std::string::npos) << d;
  EXPECT_NE(d.find("<ModelExchange modelIdentifier=\"cart_pendulum\""), std::string::npos);
  EXPECT_NE(d.find("<CoSimulation modelIdentifier=\"cart_pendulum\""), std::string::npos);
  // the states x, theta, der(x), der(theta): der(x) is both a state and the derivative of x
  EXPECT_NE(d.find("<ScalarVariable name=\"der(x)\" valueReference=\"2\" causality=\"local\" variability=\"continuous\" "
                   "initial=\"exact\">\n      <Real start=\"0\" derivative=\"1\" nominal=\"1\"/>"),
            std::string::npos)
      << d;
  EXPECT_NE(d.find("<ScalarVariable name=\"der(der(x))\" valueReference=\"6\""), std::string::npos) << d;
  EXPECT_NE(d.find("<ScalarVariable name=\"F\" valueReference=\"12\" causality=\"input\""), std::string::npos) << d;
  EXPECT_EQ(u.states, 4u);
  // the schema check can fail: a causality FMI does not know
  std::string broken = u.directory + "/broken.xml";
  std::string text = d;
  text.replace(text.find("causality=\"input\""), 17, "causality=\"push\"");
  std::ofstream(broken) << text;
  EXPECT_NE(run_command(std::string(EOMGEN_XMLLINT) + " --noout --schema '" + EOMGEN_SOURCE_DIR +
                        "/tests/fmu/fmi2ModelDescription.xsd' '" + broken + "' 2> /dev/null"),
            0);
  // the second FMU of the same model is the same bytes
  std::string again = temporary_directory();
  ASSERT_EQ(run_eomgen("fmu '" + model_path("cart_pendulum") + "' -o '" + again + "'").status, 0);
  EXPECT_TRUE(read_file(again + "/cart_pendulum.fmu") == read_file(u.directory + "/cart_pendulum.fmu"));
  CommandOutput constrained = run_eomgen("fmu '" + model_path("slider_crank") + "' -o '" + again + "'");
  EXPECT_EQ(constrained.status, 2);
  EXPECT_NE(constrained.err.find("is a Lagrange I model"), std::string::npos) << constrained.err;
}

}  // namespace
}  // namespace eomgen::test
