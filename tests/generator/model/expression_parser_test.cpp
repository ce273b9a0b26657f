#include <gtest/gtest.h>

#include "model/expression_parser.hpp"

namespace eomgen {
namespace {

struct Fixture {
  Symbols s;
  Fixture() {
    auto add = [&](const std::string& name, SymbolKind kind) {
      if (kind == SymbolKind::parameter) {
        s.by_name[name] = {kind, s.parameters.size()};
        s.parameter_names.push_back(name);
        s.parameters.emplace_back(name);
        s.parameter_defaults.push_back(1.0);
      } else if (kind == SymbolKind::coordinate) {
        s.by_name[name] = {kind, s.coordinates.size()};
        s.coordinate_names.push_back(name);
        s.coordinates.emplace_back(name);
        s.velocities.emplace_back("der(" + name + ")");
      } else {
        s.by_name[name] = {kind, s.inputs.size()};
        s.input_names.push_back(name);
        s.inputs.emplace_back(name);
      }
    };
    for (const char* p : {"m", "l", "I", "E", "beta", "gamma"}) add(p, SymbolKind::parameter);
    for (const char* q : {"phi", "psi", "zeta"}) add(q, SymbolKind::coordinate);
    add("u", SymbolKind::input);
  }
  std::optional<GiNaC::ex> parse(const std::string& text, Diagnostics& d, unsigned allowed = allow_everything) {
    return parse_expression({text, {"f.toml", 3, 10}, "k"}, s, {allowed, "a test"}, d);
  }
  GiNaC::ex ok(const std::string& text) {
    Diagnostics d;
    auto e = parse(text, d);
    EXPECT_TRUE(d.empty()) << d.format();
    return e.value_or(0);
  }
};

TEST(ExpressionParser, DecimalsAreExactRationals) {
  Fixture f;
  EXPECT_TRUE(f.ok("0.1").is_equal(GiNaC::numeric(1, 10)));
  EXPECT_TRUE(f.ok("2.5e-3").is_equal(GiNaC::numeric(1, 400)));
  EXPECT_TRUE(f.ok("1E2").is_equal(GiNaC::numeric(100)));
}

TEST(ExpressionParser, PrecedenceFollowsMathematics) {
  Fixture f;
  GiNaC::ex m = f.s.parameters[0];
  EXPECT_TRUE(f.ok("-m^2").is_equal(-GiNaC::pow(m, 2)));
  EXPECT_TRUE(f.ok("2^3^2").is_equal(GiNaC::numeric(512)));
  EXPECT_TRUE(f.ok("m**2/2*3").is_equal(GiNaC::pow(m, 2) * GiNaC::numeric(3, 2)));
  EXPECT_TRUE(f.ok("2^-1").is_equal(GiNaC::numeric(1, 2)));
}

TEST(ExpressionParser, GinacConstantNamesCanBeUserSymbols) {
  Fixture f;
  EXPECT_TRUE(f.ok("I*E + beta*gamma + psi*zeta").is_equal(
      f.s.parameters[2] * f.s.parameters[3] + f.s.parameters[4] * f.s.parameters[5] +
      f.s.coordinates[1] * f.s.coordinates[2]));
  EXPECT_TRUE(f.ok("Pi").is_equal(GiNaC::Pi));
}

TEST(ExpressionParser, DerIsTheVelocitySymbol) {
  Fixture f;
  EXPECT_TRUE(f.ok("der(phi)*2").is_equal(2 * f.s.velocities[0]));
  EXPECT_TRUE(f.ok("atan2(l, m)").is_equal(GiNaC::atan2(f.s.parameters[1], f.s.parameters[0])));
}

TEST(ExpressionParser, MistakesPointAtTheirColumn) {
  Fixture f;
  struct Case {
    const char* text;
    int column;
    const char* message;
  } cases[] = {
      {"m*lx", 12, "unknown symbol 'lx'"},
      {"m + sinn(phi)", 14, "unknown function 'sinn'"},
      {"der(m)", 14, "der() of parameter 'm'"},
      {"der(der(phi))", 10, "der(der(...))"},
      {"m +", 13, "ends too early"},
      {"(m", 12, "expected ')'"},
      {"m/0", 11, "division by zero"},
      {"2m", 10, "cannot start with a digit"},
      {"sin(m, l)", 10, "takes 1 argument"},
      {"m )", 12, "unexpected ')'"},
  };
  for (const Case& c : cases) {
    Diagnostics d;
    EXPECT_FALSE(f.parse(c.text, d)) << c.text;
    ASSERT_EQ(d.size(), 1u) << c.text;
    EXPECT_EQ(d.list()[0].where.line, 3) << c.text;
    EXPECT_EQ(d.list()[0].where.column, c.column) << c.text << ": " << d.format();
    EXPECT_NE(d.list()[0].message.find(c.message), std::string::npos) << d.format();
  }
}

TEST(ExpressionParser, ContextRestrictsWhatMayAppear) {
  Fixture f;
  Diagnostics d;
  EXPECT_FALSE(f.parse("l*der(phi)", d, allow_configuration));
  EXPECT_FALSE(f.parse("m*t", d, allow_parameters));
  EXPECT_FALSE(f.parse("u", d, allow_configuration));
  EXPECT_FALSE(f.parse("phi", d, allow_parameters));
  EXPECT_EQ(d.size(), 4u);
}

TEST(ExpressionParser, RotationProductKeepsItsOrder) {
  Fixture f;
  Diagnostics d;
  auto r = parse_rotation_product({"euler313(psi, phi, zeta) * rot_y(m)", {}, "r"}, f.s, {allow_everything, "a rotation"}, d);
  ASSERT_TRUE(r) << d.format();
  ASSERT_EQ(r->size(), 4u);
  int axes[] = {2, 0, 2, 1};
  for (int i = 0; i < 4; ++i) EXPECT_EQ((*r)[i].axis, axes[i]);
  EXPECT_TRUE((*r)[3].angle.is_equal(f.s.parameters[0]));
}

}  // namespace
}  // namespace eomgen
