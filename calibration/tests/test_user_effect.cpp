// User-defined effects from a formula in a JSON model file (issue 18): parsing and its errors,
// the effect's power, and the workflow of the README - a log with motor heating (outside the
// candidate list) is "unexplained" until the user's heating effect is added, which is then found
// with its coefficients and brings the residual to the noise.
#include <gtest/gtest.h>

#include "simulated_effects.hpp"
#include "wattswath/calibration/user_effect.hpp"

using namespace wattswath;
using namespace wattswath::energy;
using namespace wattswath::calibration;

namespace {

const char* kHeating = R"J({"effects": [{
  "name": "motor_heating", "meaning": "motors lose efficiency as they warm up",
  "power": "k * hover_power * (1 - exp(-t / tau))",
  "coefficients": [
    {"name": "k", "unit": "-", "value": 0.02, "lower": 0, "upper": 0.5},
    {"name": "tau", "unit": "s", "value": 100, "lower": 5, "upper": 2000}]}]})J";

std::string errorOf(const std::string& text) {
  try {
    const auto specs = parseEffectFile(text, "model.json");
    for (const auto& s : specs) makeFormulaEffect(s, test::iris());
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(UserEffect, FormulaPowerFollowsTheCoefficientsAndTheMotion) {
  const Vehicle v = test::iris();
  const auto specs = parseEffectFile(kHeating, "model.json");
  ASSERT_EQ(specs.size(), 1u);
  auto e = makeFormulaEffect(specs[0], v);
  EXPECT_EQ(e->name(), "motor_heating");
  MotionState s;
  s.t = 60.0;
  EXPECT_NEAR(e->power(s), 0.02 * marinsHoverPowerW(v) * (1.0 - std::exp(-0.6)), 1e-9);
  e->setCoefficientValues({0.1, 60.0});
  const auto copy = e->clone();
  EXPECT_NEAR(copy->power(s), 0.1 * marinsHoverPowerW(v) * (1.0 - std::exp(-1.0)), 1e-9);
  s.airborne = false;
  EXPECT_EQ(copy->power(s), 0.0);
}

TEST(UserEffect, ErrorsNameFileFieldValueAndExpectation) {
  EXPECT_NE(errorOf(R"J({"name": "x", "power": "k *", "coefficients": [{"name": "k", "unit": "W", "value": 1, "lower": 0, "upper": 2}]})J")
                .find("model.json: effect x, power = \"k *\""),
            std::string::npos);
  const auto unknown = errorOf(R"J({"name": "x", "power": "k * altitude", "coefficients": [{"name": "k", "unit": "W", "value": 1, "lower": 0, "upper": 2}]})J");
  EXPECT_NE(unknown.find("altitude"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("hover_power"), std::string::npos) << unknown;  // lists the variables
  EXPECT_NE(errorOf(R"J({"name": "x", "power": "k", "coefficients": [{"name": "k", "unit": "W", "value": 5, "lower": 0, "upper": 2}]})J")
                .find("effect.coefficients[0].value = 5, expected within lower 0 and upper 2"),
            std::string::npos);
  EXPECT_NE(errorOf(R"J({"name": "wind", "power": "1", "coefficients": []})J").find("is a built-in effect"), std::string::npos);
  EXPECT_NE(errorOf(R"J({"name": "x", "power": "t", "coefficients": [{"name": "t", "unit": "s", "value": 1, "lower": 0, "upper": 2}]})J")
                .find("is a variable of the formula"),
            std::string::npos);
  EXPECT_NE(errorOf("{not json").find("model.json: not valid JSON"), std::string::npos);
  EXPECT_NE(errorOf("[1e999]").find("model.json: not valid JSON"), std::string::npos);  // out of range, not a crash
  EXPECT_NE(errorOf(R"J({"name": "x", "power": "k", "name": "y", "coefficients": []})J")
                .find("model.json: field 'name' appears twice in one object, expected each field once"),
            std::string::npos);
  EXPECT_NE(errorOf(R"J({"effects": [{"name": "x", "coefficients": []}]})J").find("effects[0].power is missing"),
            std::string::npos);
}

TEST(UserEffect, MotorHeatingUnexplainedThenFoundOnceTheUserAddsIt) {
  const Vehicle v = test::iris();
  const auto spec = parseEffectFile(kHeating, "model.json").at(0);
  const EnergyModel paper = buildModel(v, {"hover", "kinetic", "parasitic_drag"});
  const auto log = test::simulateLog(paper, 11, {"motor_heating", 0.06});  // tests/simulated_effects.hpp's form
  DiagnoseSettings s;
  const auto before = diagnose(paper, v, {log}, s);
  EXPECT_EQ(before.verdict, "unexplained") << before.conclusion;
  s.extra_candidates.push_back(makeFormulaEffect(spec, v));
  const auto after = diagnose(paper, v, {log}, s);
  ASSERT_EQ(after.verdict, "missing_effect") << after.conclusion;
  ASSERT_EQ(after.found.size(), 1u);
  EXPECT_EQ(after.found[0].effect, "motor_heating");
  EXPECT_NEAR(after.found[0].coefficients.at(0).value, 0.06, 0.01);   // k
  EXPECT_NEAR(after.found[0].coefficients.at(1).value, 60.0, 20.0);   // tau [s]
  EXPECT_LT(after.final_heldout.rmse_w, 0.85 * after.baseline.rmse_w);
  EXPECT_LE(after.final_rmse_w, 1.5 * after.noise_w);
}

TEST(UserEffect, BuildModelWithNamesBuiltInAndUserEffects) {
  const Vehicle v = test::iris();
  const auto specs = parseEffectFile(kHeating, "model.json");
  const auto m = buildModelWith(v, {"hover", "kinetic", "motor_heating"}, specs);
  EXPECT_TRUE(m.has("motor_heating"));
  EXPECT_TRUE(m.has("hover"));
  try {
    buildModelWith(v, {"hover", "heating"}, specs);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("motor_heating (user-defined)"), std::string::npos) << e.what();
  }
}
