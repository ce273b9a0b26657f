// The loops that a long tree's header holds (its mass matrix and forces from the derivatives'
// pass, the gradient's loops over the links) with other scalar types than double: the awkward
// scalar of tests/support (the four operations and nothing else: no compound assignment) and long
// double, against double. `eomgen simulate` instantiates the rhs with the reference integrator's
// wide scalar, and a `+=` on the mass matrix had kept every such robot from compiling.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ball_ragdoll_imported.hpp"
#include "branched_tree.hpp"
#include "floating_humanoid.hpp"
#include "support/awkward_scalar.hpp"
#include "support/scalar_agreement.hpp"

namespace {

using eomgen::test::largest_difference;
using eomgen::test::to_double;

// rhs, jacobian_state, mass_matrix and forcing at the default state moved by 0.1, in that order
template <class T, class Robot>
std::vector<double> everything(const Robot&) {
  constexpr std::size_t n = Robot::states, v = Robot::velocities;
  std::vector<T> x, u(Robot::inputs + 1, T(0.3)), p;
  for (double value : Robot::state()) x.push_back(T(value + 0.1));
  for (double value : Robot::parameters()) p.push_back(T(value));
  std::vector<T> out(n + n * n + v * v + v);
  Robot::call(x.data(), u.data(), p.data(), out.data(), out.data() + n, out.data() + n + n * n, out.data() + n + n * n + v * v);
  std::vector<double> values;
  for (const T& e : out) values.push_back(to_double(e));
  return values;
}

#define EOMGEN_ROBOT(NAME)                                                                                   \
  struct NAME##_robot {                                                                                      \
    static constexpr std::size_t states = eomgen::models::NAME::num_states;                                 \
    static constexpr std::size_t velocities = eomgen::models::NAME::num_velocities;                         \
    static constexpr std::size_t inputs = eomgen::models::NAME::num_inputs;                                 \
    static const auto& state() { return eomgen::models::NAME::default_state; }                              \
    static const auto& parameters() { return eomgen::models::NAME::default_parameters; }                    \
    template <class T>                                                                                       \
    static void call(const T* x, const T* u, const T* p, T* xdot, T* J, T* M, T* f) {                       \
      namespace m = eomgen::models::NAME;                                                                    \
      m::rhs(T(0), x, u, p, xdot);                                                                           \
      m::jacobian_state(T(0), x, u, p, J);                                                                   \
      m::mass_matrix(T(0), x, p, M);                                                                         \
      m::forcing(T(0), x, u, p, f);                                                                          \
    }                                                                                                        \
  };
EOMGEN_ROBOT(branched_tree)
EOMGEN_ROBOT(floating_humanoid)
EOMGEN_ROBOT(ball_ragdoll_imported)
#undef EOMGEN_ROBOT

template <class Robot>
void expect_scalars_agree(const char* name) {
  SCOPED_TRACE(name);
  std::vector<double> reference = everything<double>(Robot{});
  // double takes the header's batched sines (detail::sin_cos), the others std::sin, an ulp apart,
  // which the solves with M carry into q'' and J, times its condition number
  EXPECT_LT(largest_difference(everything<awkward::Scalar>(Robot{}), reference), 1e-12);
  EXPECT_LT(largest_difference(everything<long double>(Robot{}), reference), 1e-12);
}

TEST(RobotScalars, ALongTreesLoopsTakeAnyScalarType) {
  expect_scalars_agree<branched_tree_robot>("branched_tree");
  expect_scalars_agree<floating_humanoid_robot>("floating_humanoid");
  expect_scalars_agree<ball_ragdoll_imported_robot>("ball_ragdoll_imported");  // links of three columns
}

}  // namespace
