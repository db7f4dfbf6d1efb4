// User-defined effects from a formula in a JSON model file (issue 18): muparser evaluates the
// formula, private to this file.
#include "wattswath/calibration/user_effect.hpp"
#include "wattswath/io/strict_json.hpp"
#include "wattswath/io/text_file.hpp"

#include <muParser.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "number_text.hpp"
#include "wattswath/energy/candidate_effects.hpp"
#include "wattswath/energy/model.hpp"

namespace wattswath::calibration {
using detail::num;
namespace {

class FormulaEffect final : public energy::Effect {
 public:
  FormulaEffect(FormulaEffectSpec spec, double mass, double g, double hover) : spec_(std::move(spec)) {
    coeffs_ = spec_.coefficients;
    vars_.assign(formulaVariables().size(), 0.0);
    vars_[kMass] = mass;
    vars_[kG] = g;
    vars_[kHover] = hover;
    coeff_vars_.assign(coeffs_.size(), 0.0);
    for (size_t k = 0; k < vars_.size(); ++k) parser_.DefineVar(formulaVariables()[k], &vars_[k]);
    for (size_t k = 0; k < coeffs_.size(); ++k) parser_.DefineVar(coeffs_[k].name, &coeff_vars_[k]);
    parser_.SetExpr(spec_.power);
  }
  FormulaEffect(const FormulaEffect& o) : FormulaEffect(o.spec_, o.vars_[kMass], o.vars_[kG], o.vars_[kHover]) {
    coeffs_ = o.coeffs_;
  }
  std::string name() const override { return spec_.name; }
  std::string meaning() const override { return spec_.meaning; }
  double power(const energy::MotionState& s) const override {
    if (!s.airborne) return 0.0;
    const Eigen::Vector3d& v = s.velocity;
    const Eigen::Vector3d& a = s.acceleration;
    const double values[] = {s.t, v.head<2>().norm(), v.x(), v.y(), v.z(), v.z(), a.norm(), a.x(), a.y(), a.z(),
                             s.yaw_rate, s.heading, 1.0};
    for (size_t k = 0; k < std::size(values); ++k) vars_[k] = values[k];
    for (size_t k = 0; k < coeffs_.size(); ++k) coeff_vars_[k] = coeffs_[k].value;
    return parser_.Eval();
  }
  std::unique_ptr<Effect> clone() const override { return std::make_unique<FormulaEffect>(*this); }

  static constexpr size_t kMass = 13, kG = 14, kHover = 15;  ///< indices in formulaVariables()

 private:
  FormulaEffectSpec spec_;
  mutable std::vector<double> vars_, coeff_vars_;  // bound to the parser by address
  mu::Parser parser_;
};

[[noreturn]] void fail(const std::string& source, const std::string& field, const std::string& what) {
  throw std::invalid_argument(source + ": " + field + " " + what);
}

double number(const nlohmann::json& j, const char* key, const std::string& src, const std::string& field) {
  if (!j.contains(key) || !j.at(key).is_number()) {
    fail(src, field + "." + key, (j.contains(key) ? "= " + j.at(key).dump() : std::string("is missing")) + ", expected a number");
  }
  const double x = j.at(key).get<double>();
  if (!std::isfinite(x)) fail(src, field + "." + key, "is not finite, expected a number");
  return x;
}

std::string text(const nlohmann::json& j, const char* key, const std::string& src, const std::string& field, bool required) {
  if (!j.contains(key)) {
    if (required) fail(src, field + "." + key, "is missing, expected a string");
    return "";
  }
  if (!j.at(key).is_string()) fail(src, field + "." + key, "= " + j.at(key).dump() + ", expected a string");
  return j.at(key).get<std::string>();
}

bool identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

energy::Coefficient parseCoefficient(const nlohmann::json& j, const std::string& src, const std::string& field) {
  if (!j.is_object()) fail(src, field, "= " + j.dump() + ", expected an object with name, unit, value, lower, upper");
  energy::Coefficient c;
  c.name = text(j, "name", src, field, true);
  if (!identifier(c.name)) fail(src, field + ".name", "= \"" + c.name + "\", expected an identifier (letters, digits, _)");
  for (const auto& v : formulaVariables()) {
    if (v == c.name) fail(src, field + ".name", "= \"" + c.name + "\" is a variable of the formula, expected another name");
  }
  c.unit = text(j, "unit", src, field, true);
  c.meaning = text(j, "meaning", src, field, false);
  c.value = number(j, "value", src, field);
  c.lower = number(j, "lower", src, field);
  c.upper = number(j, "upper", src, field);
  if (!(c.lower <= c.value && c.value <= c.upper)) {
    fail(src, field + ".value", "= " + num(c.value) + ", expected within lower " + num(c.lower) + " and upper " + num(c.upper));
  }
  return c;
}

FormulaEffectSpec parseSpec(const nlohmann::json& j, const std::string& src, const std::string& field) {
  if (!j.is_object()) fail(src, field, "= " + j.dump() + ", expected an object with name, power, coefficients");
  FormulaEffectSpec s;
  s.source = src;
  s.name = text(j, "name", src, field, true);
  if (!identifier(s.name)) fail(src, field + ".name", "= \"" + s.name + "\", expected an identifier (letters, digits, _)");
  for (const auto& k : energy::knownEffectNames()) {
    if (k == s.name) fail(src, field + ".name", "= \"" + s.name + "\" is a built-in effect, expected another name");
  }
  s.meaning = text(j, "meaning", src, field, false);
  s.power = text(j, "power", src, field, true);
  if (!j.contains("coefficients") || !j.at("coefficients").is_array()) {
    fail(src, field + ".coefficients", "is missing or not an array, expected [{name, unit, value, lower, upper}, ...]");
  }
  const auto& cs = j.at("coefficients");
  for (size_t k = 0; k < cs.size(); ++k) {
    s.coefficients.push_back(parseCoefficient(cs[k], src, field + ".coefficients[" + std::to_string(k) + "]"));
    for (size_t m = 0; m + 1 < s.coefficients.size(); ++m) {
      if (s.coefficients[m].name == s.coefficients.back().name) {
        fail(src, field + ".coefficients[" + std::to_string(k) + "].name", "= \"" + s.coefficients[m].name + "\" twice");
      }
    }
  }
  return s;
}
}  // namespace

const std::vector<std::string>& formulaVariables() {
  static const std::vector<std::string> n = {"t",        "speed", "vx", "vy",       "vz",      "climb_rate", "accel", "ax",
                                             "ay",       "az",    "yaw_rate", "heading", "airborne", "mass",       "g",
                                             "hover_power"};
  return n;
}

std::unique_ptr<energy::Effect> makeFormulaEffect(const FormulaEffectSpec& spec, const energy::Vehicle& v) {
  std::unique_ptr<FormulaEffect> e;
  try {
    e = std::make_unique<FormulaEffect>(spec, v.mass_kg, v.gravity_mps2, energy::marinsHoverPowerW(v));
    energy::MotionState hover;
    const double p = e->power(hover);
    if (!std::isfinite(p)) throw std::invalid_argument("is not finite at hover (t = 0, at rest): " + num(p) + " W");
  } catch (const mu::Parser::exception_type& x) {
    std::string vars;
    for (const auto& n : formulaVariables()) vars += (vars.empty() ? "" : ", ") + n;
    throw std::invalid_argument(spec.source + ": effect " + spec.name + ", power = \"" + spec.power + "\": " + x.GetMsg() +
                                " (position " + std::to_string(x.GetPos()) + ", token \"" + x.GetToken() +
                                "\"); expected a formula of the coefficients and " + vars);
  } catch (const std::invalid_argument& x) {
    throw std::invalid_argument(spec.source + ": effect " + spec.name + ", power = \"" + spec.power + "\" " + x.what());
  }
  return e;
}

std::vector<FormulaEffectSpec> parseEffectFile(const std::string& text, const std::string& source) {
  // Strict JSON: nesting bounded, and a field given twice (which value counts would be a guess) refused.
  constexpr int kMaxDepth = 64;
  nlohmann::json j;
  try {
    j = io::parseStrictJson(text, kMaxDepth);
  } catch (const io::JsonError& e) {
    if (e.problem() == io::JsonProblem::duplicate_key) {
      throw std::invalid_argument(source + ": field '" + e.key() + "' appears twice in one object, expected each field once");
    }
    throw std::invalid_argument(source + ": " + e.what() + ", expected an effect model file");
  }
  std::vector<FormulaEffectSpec> out;
  if (j.is_object() && j.contains("effects")) {
    if (!j.at("effects").is_array() || j.at("effects").empty()) fail(source, "effects", "is not a non-empty array");
    for (size_t k = 0; k < j.at("effects").size(); ++k) {
      out.push_back(parseSpec(j.at("effects")[k], source, "effects[" + std::to_string(k) + "]"));
    }
  } else {
    out.push_back(parseSpec(j, source, "effect"));
  }
  return out;
}

energy::EnergyModel buildModelWith(const energy::Vehicle& v, const std::vector<std::string>& names,
                                   const std::vector<FormulaEffectSpec>& user) {
  std::vector<std::string> builtin;
  std::vector<const FormulaEffectSpec*> mine;
  for (const auto& n : names) {
    const auto u = std::find_if(user.begin(), user.end(), [&](const FormulaEffectSpec& s) { return s.name == n; });
    if (u != user.end()) {
      mine.push_back(&*u);
      continue;
    }
    if (std::find(energy::knownEffectNames().begin(), energy::knownEffectNames().end(), n) ==
        energy::knownEffectNames().end()) {
      std::string known;
      for (const auto& k : energy::knownEffectNames()) known += (known.empty() ? "" : ", ") + k;
      for (const auto& s : user) known += ", " + s.name + " (user-defined)";
      throw std::invalid_argument("effect '" + n + "' is unknown, expected one of " + known);
    }
    builtin.push_back(n);
  }
  energy::EnergyModel m = energy::buildModel(v, builtin);
  for (const auto* s : mine) m.add(makeFormulaEffect(*s, v));
  return m;
}

std::vector<FormulaEffectSpec> readEffectFile(const std::string& path) {
  // io::FileError is a std::runtime_error naming the file.
  return parseEffectFile(io::readTextFile(path, {kMaxEffectFileBytes, "effect files", ""}), path);
}

}  // namespace wattswath::calibration
