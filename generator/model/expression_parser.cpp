#include "model/expression_parser.hpp"

#include "model/quaternion.hpp"

#include <cctype>
#include <cfloat>

#include <fmt/format.h>

#include "symbolic/clamp.hpp"
#include "symbolic/magnitude.hpp"
#include "symbolic/rotation_angle.hpp"
#include "symbolic/exact_double.hpp"

namespace eomgen {
namespace {

using GiNaC::ex;

struct ParseFailure {};

// Limits that keep hostile input from exhausting the stack (the parser recurses once per
// level) or the derivation (each nested function multiplies the size of a derivative)
constexpr int max_nesting = 256;
constexpr int max_function_nesting = 32;

// counts one level of recursion for as long as it lives
class Level {
 public:
  explicit Level(int& depth) : depth_(++depth) {}
  ~Level() { --depth_; }
  Level(const Level&) = delete;
  Level& operator=(const Level&) = delete;

 private:
  int& depth_;
};

const std::vector<std::string> function_names = {"sin",  "cos",  "tan",  "asin", "acos",
                                                  "atan", "atan2", "sinh", "cosh", "tanh",
                                                  "exp",  "log",  "sqrt", "abs",  "sign", "clamp", "rotation_angle", "der"};
const std::vector<std::string> rotation_names = {"rot_x", "rot_y", "rot_z", "rot_axis", "quat", "euler313", "cardan123"};

ex apply_function(const std::string& name, const std::vector<ex>& a) {
  if (name == "sin") return GiNaC::sin(a[0]);
  if (name == "cos") return GiNaC::cos(a[0]);
  if (name == "tan") return GiNaC::tan(a[0]);
  if (name == "asin") return GiNaC::asin(a[0]);
  if (name == "acos") return GiNaC::acos(a[0]);
  if (name == "atan") return GiNaC::atan(a[0]);
  if (name == "atan2") return GiNaC::atan2(a[0], a[1]);
  if (name == "sinh") return GiNaC::sinh(a[0]);
  if (name == "cosh") return GiNaC::cosh(a[0]);
  if (name == "tanh") return GiNaC::tanh(a[0]);
  if (name == "exp") return GiNaC::exp(a[0]);
  if (name == "log") return GiNaC::log(a[0]);
  if (name == "sqrt") return GiNaC::sqrt(a[0]);
  if (name == "clamp") return clamp(a[0], a[1], a[2]);
  if (name == "sign") return sign(a[0]);
  if (name == "rotation_angle") return rotation_angle(a[0], a[1], a[2], a[3]);
  return magnitude(a[0]);
}

std::size_t arity(const std::string& name) {
  return name == "atan2" ? 2 : name == "clamp" ? 3 : name == "rotation_angle" ? 4 : 1;
}

class Parser {
 public:
  Parser(const ExpressionText& text, const Symbols& symbols, ExpressionRules rules, Diagnostics& d)
      : s_(text.text), text_(text), symbols_(symbols), rules_(rules), d_(d) {}

  // expression := term (('+' | '-') term)*
  ex expression() {
    ex value = term();
    for (;;) {
      skip_space();
      if (peek() == '+') { ++pos_; value += term(); }
      else if (peek() == '-') { ++pos_; value -= term(); }
      else return value;
    }
  }

  // rotation := factor ('*' factor)* ; factor := name '(' expression {',' expression} ')'
  std::vector<ElementaryRotation> rotation() {
    std::vector<ElementaryRotation> sequence;
    for (;;) {
      skip_space();
      std::size_t start = pos_;
      std::string name = identifier();
      if (name.empty()) fail(start, "expected a rotation such as rot_z(a) or euler313(psi, theta, phi)");
      auto known = std::find(rotation_names.begin(), rotation_names.end(), name);
      if (known == rotation_names.end())
        fail(start, fmt::format("unknown rotation function '{}'", name),
             suggest(name, rotation_names, "rotations"));
      std::vector<ex> args = arguments(start, name, name == "rot_axis" || name == "quat" ? 4 : name.rfind("rot_", 0) == 0 ? 1 : 3);
      if (name == "quat") {
        sequence.push_back(quaternion_turn(start, args));
      } else if (name == "rot_axis") {
        if ((args[0] * args[0] + args[1] * args[1] + args[2] * args[2]).is_zero())
          fail(start, "rot_axis needs a direction that is not zero", "write rot_axis(x, y, z, angle), e.g. rot_axis(1, 1, 0, q)");
        sequence.push_back(turn_about({args[0], args[1], args[2]}, args[3]));
      } else if (name == "rot_x") sequence.push_back({0, args[0]});
      else if (name == "rot_y") sequence.push_back({1, args[0]});
      else if (name == "rot_z") sequence.push_back({2, args[0]});
      else if (name == "euler313") sequence.insert(sequence.end(), {{2, args[0]}, {0, args[1]}, {2, args[2]}});
      else sequence.insert(sequence.end(), {{0, args[0]}, {1, args[1]}, {2, args[2]}});
      skip_space();
      if (peek() == '*') { ++pos_; continue; }
      return sequence;
    }
  }

  // quat(w, x, y, z): the constant turn of the quaternion (MJCF's quat), R(q)/|q|² exact in its numbers
  ElementaryRotation quaternion_turn(std::size_t start, const std::vector<ex>& q) {
    for (const ex& c : q)
      if (!GiNaC::is_a<GiNaC::numeric>(c))
        fail(start, "quat takes four numbers", "write quat(w, x, y, z), e.g. quat(0.7071, 0.7071, 0, 0); a turn that "
                                                "moves is rot_axis(x, y, z, angle) or a joint");
    if ((q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]).is_zero())
      fail(start, "quat needs a quaternion that is not zero", "write quat(w, x, y, z), e.g. quat(1, 0, 0, 0)");
    ElementaryRotation r{ElementaryRotation::constant_matrix, 0};
    r.constant = quaternion_rotation({q[0], q[1], q[2], q[3]});
    return r;
  }

  void expect_end() {
    skip_space();
    if (pos_ < s_.size())
      fail(pos_, fmt::format("unexpected '{}' after the end of the expression", s_[pos_]),
           "check for a missing operator or an unbalanced parenthesis");
  }

  void fail(std::size_t at, const std::string& message, const std::string& hint = {}) {
    d_.error(location(at), text_.key, message, hint);
    throw ParseFailure{};
  }

 private:
  // term := unary (('*' | '/') unary)*
  ex term() {
    ex value = unary();
    for (;;) {
      skip_space();
      if (peek() == '*' && peek(1) != '*') { ++pos_; value *= unary(); }
      else if (peek() == '/') {
        std::size_t at = pos_++;
        ex divisor = unary();
        if (divisor.is_zero()) fail(at, "division by zero");
        value /= divisor;
      } else return value;
    }
  }

  // unary := ('-' | '+') unary | power    (every level of nesting passes through here)
  ex unary() {
    skip_space();
    Level level(depth_);
    if (depth_ > max_nesting)
      fail(pos_, fmt::format("the expression is nested more than {} levels deep (parentheses, signs, powers and "
                             "function calls)", max_nesting),
           "split it into simpler expressions; eomgen limits nesting so that no input can exhaust its stack");
    if (peek() == '-') { ++pos_; return -unary(); }
    if (peek() == '+') { ++pos_; return unary(); }
    return power();
  }

  // power := primary (('^' | '**') unary)?    right-associative, binds tighter than unary minus
  ex power() {
    ex base = primary();
    skip_space();
    if (peek() == '^') { ++pos_; return GiNaC::pow(base, unary()); }
    if (peek() == '*' && peek(1) == '*') { pos_ += 2; return GiNaC::pow(base, unary()); }
    return base;
  }

  // primary := number | identifier | identifier '(' arguments ')' | '(' expression ')'
  ex primary() {
    skip_space();
    std::size_t start = pos_;
    char c = peek();
    if (c == '(') {
      ++pos_;
      ex inner = expression();
      skip_space();
      if (peek() != ')') fail(pos_, "expected ')'", fmt::format("the '(' at column {} is not closed", location(start).column));
      ++pos_;
      return inner;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && std::isdigit(static_cast<unsigned char>(peek(1)))))
      return number();
    std::string name = identifier();
    if (name.empty()) {
      if (pos_ >= s_.size()) fail(pos_, "the expression ends too early", "an operand is missing");
      fail(pos_, fmt::format("unexpected '{}'", s_[pos_]), "expected a number, a name or '('");
    }
    if (peek() == '.' && std::isalpha(static_cast<unsigned char>(peek(1)))) {  // a component, P.x
      ++pos_;
      name += "." + identifier();
    }
    skip_space();
    if (peek() == '(') return call(start, name);
    return symbol(start, name);
  }

  ex call(std::size_t start, const std::string& name) {
    if (name == "der") return derivative(start);
    if (std::find(rotation_names.begin(), rotation_names.end(), name) != rotation_names.end())
      fail(start, fmt::format("'{}' is a rotation, not a scalar", name),
           "rotations go in a rigid body's rotation = \"...\"");
    if (std::find(function_names.begin(), function_names.end(), name) == function_names.end())
      fail(start, fmt::format("unknown function '{}'", name), suggest(name, function_names, "functions"));
    Level level(function_depth_);
    if (function_depth_ > max_function_nesting)
      fail(start, fmt::format("functions are nested more than {} deep", max_function_nesting),
           "each nested function multiplies the size of the derivatives; simplify the expression");
    return apply_function(name, arguments(start, name, arity(name)));
  }

  std::vector<ex> arguments(std::size_t start, const std::string& name, std::size_t count) {
    skip_space();
    if (peek() != '(') fail(pos_, fmt::format("expected '(' after '{}'", name));
    ++pos_;
    std::vector<ex> args;
    for (;;) {
      args.push_back(expression());
      skip_space();
      if (peek() == ',') { ++pos_; continue; }
      if (peek() == ')') { ++pos_; break; }
      if (pos_ >= s_.size())
        fail(start, fmt::format("the '(' of '{}' is not closed", name), "add the missing ')'");
      fail(pos_, "expected ',' or ')' in the argument list");
    }
    if (args.size() != count)
      fail(start, fmt::format("'{}' takes {} argument{}, got {}", name, count, count == 1 ? "" : "s", args.size()));
    return args;
  }

  // der '(' coordinate ')'
  ex derivative(std::size_t start) {
    ++pos_;  // '('
    skip_space();
    std::size_t at = pos_;
    std::string inner = identifier();
    skip_space();
    if (inner == "der" && peek() == '(')
      fail(start, "der(der(...)) is an acceleration, which cannot appear in a model file",
           "write der(q) for the velocity of coordinate q; accelerations follow from the equations");
    if (inner.empty() || peek() != ')')
      fail(at, "der() takes the name of a coordinate", "write der(q) for the velocity of coordinate q");
    ++pos_;
    auto found = symbols_.by_name.find(inner);
    if (inner == "t") fail(at, "der(t) is 1; time is not a coordinate");
    if (found == symbols_.by_name.end())
      fail(at, fmt::format("unknown coordinate '{}' in der()", inner), suggest(inner, symbols_.coordinate_names, "coordinates"));
    if (found->second.kind != SymbolKind::coordinate)
      fail(at, fmt::format("der() of {} '{}': only coordinates have velocities",
                           found->second.kind == SymbolKind::parameter ? "parameter"
                           : found->second.kind == SymbolKind::input   ? "input"
                           : found->second.kind == SymbolKind::vector  ? "vector"
                           : found->second.kind == SymbolKind::matrix  ? "matrix"
                                                                       : "definition",
                           inner),
           found->second.kind == SymbolKind::definition || found->second.kind == SymbolKind::vector ||
                   found->second.kind == SymbolKind::matrix
               ? "write the definition's rate out in der() of its coordinates (the chain rule), or define it too"
               : "parameters are constant; inputs are given functions of time");
    if (!(rules_.allowed & allow_velocities))
      fail(start, fmt::format("velocity der({}) in {}", inner, rules_.context),
           fmt::format("{} may depend on the coordinates and time only", rules_.context));
    return symbols_.velocities[found->second.index];
  }

  ex symbol(std::size_t start, const std::string& name) {
    if (name == "Pi") return GiNaC::Pi;
    if (name == "t") {
      if (!(rules_.allowed & allow_time))
        fail(start, fmt::format("time t in {}", rules_.context), fmt::format("{} must be constant", rules_.context));
      return symbols_.time;
    }
    auto found = symbols_.by_name.find(name);
    if (found == symbols_.by_name.end()) {
      if (std::find(function_names.begin(), function_names.end(), name) != function_names.end())
        fail(start, fmt::format("function '{}' needs an argument", name), fmt::format("write {}(x)", name));
      if (rules_.defined_later &&
          std::find(rules_.defined_later->begin(), rules_.defined_later->end(), name) != rules_.defined_later->end())
        fail(start, fmt::format("'{}' is not defined yet: [definitions] are read from the top", name),
             "a definition may use only those above it (so that none depends on itself): move it up");
      if (rules_.angular_velocities && rules_.angular_velocities->count(name))
        fail(start, fmt::format("'{}' is a ball or free joint's angular velocity, which {} cannot name", name, rules_.context),
             "write it in the rates of the joint's quaternion (w, x, y, z), as at unit length ω_x = 2(w der(x) − x der(w) − "
             "y der(z) + z der(y)), and |ω|² = 4(der(w)^2 + der(x)^2 + der(y)^2 + der(z)^2)");
      fail(start, fmt::format("unknown symbol '{}'", name), suggest(name, symbols_.all_names(), "symbols"));
    }
    const SymbolInfo& info = found->second;
    switch (info.kind) {
      case SymbolKind::parameter:
        if (!(rules_.allowed & allow_parameters))
          fail(start, fmt::format("parameter '{}' in {}", name, rules_.context), "only numbers are allowed here");
        return symbols_.parameters[info.index];
      case SymbolKind::coordinate:
        if (!(rules_.allowed & allow_coordinates))
          fail(start, fmt::format("coordinate '{}' in {}", name, rules_.context),
               fmt::format("{} must not depend on the motion", rules_.context));
        return symbols_.coordinates[info.index];
      case SymbolKind::input:
        if (!(rules_.allowed & allow_inputs))
          fail(start, fmt::format("input '{}' in {}", name, rules_.context),
               "inputs may appear in forces, the potential's forces and outputs");
        return symbols_.inputs[info.index];
      case SymbolKind::definition:
        return definition(start, name, symbols_.definitions[info.index]);
      case SymbolKind::vector:
        fail(start, fmt::format("'{}' is a vector, not a scalar", name),
             fmt::format("use its components {0}.x, {0}.y, {0}.z", name));
        break;
      case SymbolKind::matrix:
        fail(start, fmt::format("'{}' is a 3x3 matrix, not a scalar", name),
             fmt::format("use its entries {0}.xx, {0}.xy, ... {0}.zz (row, then column)", name));
    }
    return 0;
  }

  // a definition stands for its expression, which must be allowed where it is used
  ex definition(std::size_t start, const std::string& name, const ex& value) {
    auto refuse = [&](const std::string& what, const char* hint) {
      fail(start, fmt::format("definition '{}' depends on {}, which {} may not", name, what, rules_.context), hint);
    };
    const Symbols& s = symbols_;
    for (std::size_t i = 0; i < s.coordinates.size(); ++i) {
      if (!(rules_.allowed & allow_coordinates) && value.has(s.coordinates[i]))
        refuse("the coordinate " + s.coordinate_names[i], "use it where the motion may appear");
      if (!(rules_.allowed & allow_velocities) && value.has(s.velocities[i]))
        refuse("the velocity der(" + s.coordinate_names[i] + ")", "velocities may appear in energies, forces and outputs");
    }
    if (!(rules_.allowed & allow_time) && value.has(s.time)) refuse("time t", "use it where time may appear");
    for (std::size_t i = 0; i < s.inputs.size(); ++i)
      if (!(rules_.allowed & allow_inputs) && value.has(s.inputs[i]))
        refuse("the input " + s.input_names[i], "inputs may appear in forces and outputs");
    for (std::size_t i = 0; i < s.parameters.size(); ++i)
      if (!(rules_.allowed & allow_parameters) && value.has(s.parameters[i]))
        refuse("the parameter " + s.parameter_names[i], "only numbers are allowed here");
    return value;
  }

  // digits ['.' digits] [('e'|'E') ['+'|'-'] digits], read as an exact rational
  ex number() {
    std::size_t start = pos_;
    std::string digits;
    int scale = 0;
    while (std::isdigit(static_cast<unsigned char>(peek()))) digits += s_[pos_++];
    if (peek() == '.') {
      ++pos_;
      while (std::isdigit(static_cast<unsigned char>(peek()))) { digits += s_[pos_++]; ++scale; }
    }
    if (peek() == 'e' || peek() == 'E') {
      std::size_t mark = pos_++;
      int sign = 1;
      if (peek() == '+' || peek() == '-') sign = s_[pos_++] == '-' ? -1 : 1;
      std::string exponent;
      while (std::isdigit(static_cast<unsigned char>(peek()))) exponent += s_[pos_++];
      if (exponent.empty()) fail(mark, "malformed exponent in a number", "write e.g. 1.5e-3");
      if (exponent.size() > 4) fail(start, "number out of range");
      scale -= sign * std::stoi(exponent);
    }
    if (std::isalpha(static_cast<unsigned char>(peek())) || peek() == '_')
      fail(start, fmt::format("a name cannot start with a digit"), "write the product explicitly, e.g. 2*x");
    GiNaC::numeric value = GiNaC::numeric(digits.c_str()) / GiNaC::pow(GiNaC::numeric(10), GiNaC::numeric(scale));
    // the generated code computes in double at the least: a number past its range would be infinite
    static const GiNaC::numeric largest = exact_rational(DBL_MAX);
    if (value > largest)
      fail(start, "number beyond the range of double (1.8e308)", "give the quantity in other units, or as a product of parameters");
    return value;
  }

  std::string identifier() {
    std::size_t start = pos_;
    if (pos_ < s_.size() && (std::isalpha(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_'))
      while (pos_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_')) ++pos_;
    return s_.substr(start, pos_ - start);
  }

  void skip_space() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  char peek(std::size_t ahead = 0) const { return pos_ + ahead < s_.size() ? s_[pos_ + ahead] : '\0'; }

  SourceLocation location(std::size_t offset) const {
    SourceLocation where = text_.where;
    for (std::size_t i = 0; i < offset && i < s_.size(); ++i) {
      if (s_[i] == '\n') { ++where.line; where.column = 1; }
      else if ((static_cast<unsigned char>(s_[i]) & 0xC0) != 0x80) ++where.column;
    }
    return where;
  }

  const std::string& s_;
  const ExpressionText& text_;
  const Symbols& symbols_;
  ExpressionRules rules_;
  Diagnostics& d_;
  std::size_t pos_ = 0;
  int depth_ = 0, function_depth_ = 0;
};

}  // namespace

std::optional<GiNaC::ex> parse_expression(const ExpressionText& text, const Symbols& symbols,
                                          ExpressionRules rules, Diagnostics& diagnostics) {
  Parser parser(text, symbols, rules, diagnostics);
  try {
    ex value = parser.expression();
    parser.expect_end();
    return value;
  } catch (const ParseFailure&) {
    return std::nullopt;
  } catch (const std::exception& e) {  // GiNaC refuses e.g. 0^(-1) or log(0)
    try {
      parser.fail(0, fmt::format("the expression cannot be evaluated: {}", e.what()));
    } catch (const ParseFailure&) {
    }
    return std::nullopt;
  }
}

namespace {

// the coordinate axis (0, 1, 2) a direction lies along and its sign, or -1
std::pair<int, int> coordinate_axis(const std::array<ex, 3>& direction) {
  int nonzero = 0, along = 0;
  for (int a = 0; a < 3; ++a)
    if (!direction[std::size_t(a)].is_zero()) ++nonzero, along = a;
  const ex& d = direction[std::size_t(along)];
  if (nonzero != 1 || !GiNaC::is_a<GiNaC::numeric>(d)) return {-1, 0};
  return {along, GiNaC::ex_to<GiNaC::numeric>(d).is_positive() ? 1 : -1};
}

}  // namespace

std::array<ex, 3> unit_direction(const std::array<ex, 3>& direction) {
  std::array<ex, 3> e{0, 0, 0};
  auto [along, sign] = coordinate_axis(direction);
  if (along >= 0) {
    e[std::size_t(along)] = sign;
    return e;
  }
  ex length = GiNaC::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  for (std::size_t a = 0; a < 3; ++a) e[a] = direction[a] / length;
  return e;
}

ElementaryRotation turn_about(const std::array<ex, 3>& direction, const ex& angle) {
  auto [along, sign] = coordinate_axis(direction);
  if (along >= 0) return {along, sign * angle};
  ElementaryRotation r{ElementaryRotation::about_direction, angle};
  r.direction = unit_direction(direction);
  return r;
}

std::optional<std::vector<ElementaryRotation>> parse_rotation_product(
    const ExpressionText& text, const Symbols& symbols, ExpressionRules rules,
    Diagnostics& diagnostics) {
  Parser parser(text, symbols, rules, diagnostics);
  try {
    auto sequence = parser.rotation();
    parser.expect_end();
    return sequence;
  } catch (const ParseFailure&) {
    return std::nullopt;
  }
}

}  // namespace eomgen
