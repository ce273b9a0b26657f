// The generated headers' detail::sin_cos for double (emit/cpp_trig): within 2 ulp of long double's
// sinl and cosl over the angles its reduction covers, with g++ and clang++ (and, by std::sin, under
// g++ -ffast-math); the C library's values, to the bit, where it hands over (0, -0, NaN, infinities,
// |angle| >= 1e6); and the headers' functions computing with it agree with the same headers built
// with EOMGEN_STD_SIN_COS.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "emit/cpp_trig.hpp"
#include "support/test_support.hpp"

namespace eomgen::test {
namespace {

const std::string generated_dir = std::string(EOMGEN_SOURCE_DIR) + "/generated";

// prints the largest error in ulp and where, then the number of special angles whose values differ
// from std::sin and std::cos in any bit (checked unless the argument "fast" is given)
const char* accuracy_program = R"(#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include "double_pendulum.hpp"
namespace d = eomgen::models::double_pendulum::detail;
long double reference_sin(double x);  // sinl and cosl, compiled without the flags under test
long double reference_cos(double x);

// |v - r| in units of the last place of r rounded to double
double ulps(double v, long double r) {
  int e = 0;
  std::frexp(static_cast<double>(r), &e);
  if (static_cast<double>(r) == 0) return v == 0 ? 0 : 1e300;
  return static_cast<double>(std::fabs(static_cast<long double>(v) - r) / std::ldexp(1.0L, e - 53));
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

int main(int argc, char** argv) {
  std::mt19937_64 random(7);
  double worst = 0, worst_at = 0;
  for (double range : {0.5, 4.0, 100.0, 1e4, 9.99e5}) {
    std::uniform_real_distribution<double> uniform(-range, range);
    for (int i = 0; i < 100000; ++i) {
      double angle[5], s[5], c[5];  // an odd count: the last angle goes through alone
      for (double& a : angle) a = uniform(random);
      d::sin_cos(angle, s, c);
      for (int k = 0; k < 5; ++k) {
        double e = std::max(ulps(s[k], reference_sin(angle[k])), ulps(c[k], reference_cos(angle[k])));
        if (e > worst) worst = e, worst_at = angle[k];
      }
    }
  }
  int differ = 0;
  if (argc < 2 || std::string(argv[1]) != "fast") {
    const double inf = std::numeric_limits<double>::infinity();
    double special[8] = {0.0, -0.0, std::nan(""), inf, -inf, 1e6, -3.5e7, 1e300}, s[8], c[8];
    d::sin_cos(special, s, c);
    for (int k = 0; k < 8; ++k)
      if (!same_bits(s[k], std::sin(special[k])) || !same_bits(c[k], std::cos(special[k]))) ++differ;
  }
  std::printf("%.4f %.17g %d\n", worst, worst_at, differ);
}
)";

// (under -ffast-math, cosl(192530.93) came out 3.5e-10 wrong: the x87 instruction, unreduced)
const char* reference_program = R"(#include <cmath>
long double reference_sin(double x) { return sinl(x); }
long double reference_cos(double x) { return cosl(x); }
)";

struct Accuracy {
  double worst_ulps = 1e300, worst_at = 0;
  int special_differ = -1;
};

Accuracy accuracy_with(const std::string& compile, bool fast) {
  std::string dir = temporary_directory();
  std::ofstream(dir + "/accuracy.cpp") << accuracy_program;
  std::ofstream(dir + "/reference.cpp") << reference_program;
  std::string command = "cd '" + dir + "' && " + compile + " -I '" + generated_dir +
                        "' -c accuracy.cpp && g++ -O2 -c reference.cpp && g++ accuracy.o reference.o -o accuracy && ./accuracy " +
                        (fast ? "fast" : "") + " > out.txt";
  Accuracy a;
  if (run_command(command) != 0) return a;
  std::istringstream(read_file(dir + "/out.txt")) >> a.worst_ulps >> a.worst_at >> a.special_differ;
  return a;
}

// the header promises 2 ulp; 1.56 is measured here (2.3 when r was rounded twice, without the two-sum)
constexpr double measured_bound = 1.75;

TEST(SinCos, WithinTwoUlpOfLongDoubleWithGcc) {
  Accuracy a = accuracy_with("g++ -std=c++17 -O2 -Wall -Wextra -Wpedantic -Werror", false);
  EXPECT_LE(a.worst_ulps, measured_bound) << "at " << a.worst_at;
  EXPECT_EQ(a.special_differ, 0) << "0, -0, NaN, infinities and |angle| >= 1e6 take std::sin and std::cos";
}

TEST(SinCos, WithinTwoUlpOfLongDoubleWithClang) {
  if (run_command("command -v clang++ > /dev/null") != 0) GTEST_SKIP() << "no clang++ on this machine";
  Accuracy a = accuracy_with("clang++ -std=c++20 -O2 -Wall -Wextra -Wpedantic -Werror", false);
  EXPECT_LE(a.worst_ulps, measured_bound) << "at " << a.worst_at;
  EXPECT_EQ(a.special_differ, 0);
}

// -ffast-math would reassociate the reduction's sums ((x + 1.5 2^52) - 1.5 2^52 into x, the three
// parts of π/2 into one): errors of 1e11 ulp at 2e5 were measured before the header left it to std::sin
TEST(SinCos, WithinTwoUlpOfLongDoubleUnderFastMath) {
  Accuracy a = accuracy_with("g++ -std=c++17 -O3 -ffast-math", true);
  EXPECT_LE(a.worst_ulps, 2.0) << "at " << a.worst_at;
}

TEST(SinCos, ReductionLimitIsWhereTheProductsStayExact) {
  // k < 2^20 keeps k·C1 and k·C2 (33 significant bits each) exact: |angle| 2/π < 2^20
  EXPECT_LT(sin_cos_reduction_limit * 2 / 3.141592653589793, 1048576.0);
  EXPECT_NE(sin_cos_function().find(fmt::format("std::abs(angle[i]) < {:g})", sin_cos_reduction_limit)), std::string::npos)
      << "the header's own test of the limit";
}

// rhs and jacobian_state of headers that take many sines and cosines (Euler angles, rolling contact,
// a tree by the recursion, rotations through frames), at the default state and three others
const char* agreement_program = R"(#include <cstdio>
#include <random>
#include <vector>
#include "free_rigid_body.hpp"
#include "rolling_disk.hpp"
#include "lumped_rope.hpp"
#include "spatial_double_pendulum.hpp"
template <class Model>
void print(std::mt19937& random) {
  std::vector<double> x(Model::num_states), p(Model::num_parameters), u(Model::num_inputs + 1), xdot(Model::num_states),
      J(Model::num_states * Model::num_states);
  std::uniform_real_distribution<double> uniform(-3, 3);
  for (int point = 0; point < 4; ++point) {
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = point == 0 ? Model::default_state[i] : uniform(random);
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = Model::default_parameters[i];
    Model::rhs(0.0, x.data(), u.data(), p.data(), xdot.data());
    Model::jacobian_state(0.0, x.data(), u.data(), p.data(), J.data());
    for (double v : xdot) std::printf("%.17g\n", v);
    for (double v : J) std::printf("%.17g\n", v);
  }
}
#define MODEL(NAME)                                                                          \
  struct NAME {                                                                              \
    static constexpr std::size_t num_states = eomgen::models::NAME::num_states;              \
    static constexpr std::size_t num_parameters = eomgen::models::NAME::num_parameters;      \
    static constexpr std::size_t num_inputs = eomgen::models::NAME::num_inputs;              \
    static constexpr auto default_state = eomgen::models::NAME::default_state;               \
    static constexpr auto default_parameters = eomgen::models::NAME::default_parameters;     \
    static void rhs(double t, const double* x, const double* u, const double* p, double* y) { \
      eomgen::models::NAME::rhs(t, x, u, p, y);                                              \
    }                                                                                        \
    static void jacobian_state(double t, const double* x, const double* u, const double* p, double* J) { \
      eomgen::models::NAME::jacobian_state(t, x, u, p, J);                                   \
    }                                                                                        \
  };
MODEL(free_rigid_body)
MODEL(rolling_disk)
MODEL(lumped_rope)
MODEL(spatial_double_pendulum)
int main() {
  std::mt19937 random(3);
  print<free_rigid_body>(random);
  print<rolling_disk>(random);
  print<lumped_rope>(random);
  print<spatial_double_pendulum>(random);
}
)";

std::vector<double> numbers(const std::string& text) {
  std::vector<double> v;
  std::istringstream in(text);
  for (double x; in >> x;) v.push_back(x);
  return v;
}

TEST(SinCos, HeadersAgreeWithTheCLibrarysSineAndCosine) {
  std::string dir = temporary_directory();
  std::ofstream(dir + "/agree.cpp") << agreement_program;
  std::string compile = "g++ -std=c++17 -O1 -I '" + generated_dir + "' agree.cpp";
  ASSERT_EQ(run_command("cd '" + dir + "' && " + compile + " -o fast && " + compile +
                        " -DEOMGEN_STD_SIN_COS -o libm && ./fast > fast.txt && ./libm > libm.txt"),
            0);
  std::vector<double> fast = numbers(read_file(dir + "/fast.txt")), libm = numbers(read_file(dir + "/libm.txt"));
  ASSERT_EQ(fast.size(), libm.size());
  ASSERT_GT(fast.size(), 1000u);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < fast.size(); ++i) {
    EXPECT_NEAR(fast[i], libm[i], 1e-12 * std::max(1.0, std::abs(libm[i]))) << "value " << i;
    differ += fast[i] != libm[i];
  }
  EXPECT_GT(differ, 0u) << "the two builds computed the same bits: the double path was not taken";
}

}  // namespace
}  // namespace eomgen::test
