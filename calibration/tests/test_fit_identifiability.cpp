// Identifiability in fit (issue 19): a coefficient is fitted only when the training data offer the
// excitation it needs (speed for drag, speed changes for the kinetic term, climbs and descents for
// climb); otherwise it keeps its starting value (the vehicle's physics) and says why, instead of a
// drag area of 12.5 m^2 fitted to hover noise.
#include <gtest/gtest.h>

#include <cmath>

#include "test_util.hpp"
#include "wattswath/calibration/diagnose.hpp"

using namespace wattswath::energy;
using namespace wattswath::logs;
using namespace wattswath::calibration;

namespace {

Vehicle iris() { return loadVehicle(wattswath::test::sourcePath("data/vehicles/iris.json")); }

// A model of `effects` flown through `path` at 5 Hz (60 s hovers at the ends, 10 W power noise).
PreparedLog fly(const std::vector<Eigen::Vector3d>& path, const std::vector<std::string>& effects) {
  SimulationSettings s;
  s.rate_hz = 5.0;
  s.power_noise_w = 10.0;
  s.hover_s = 60.0;
  return prepareLog(simulateFlight(path, buildModel(iris(), effects), s));
}

const FittedCoefficient& find(const FitResult& r, const std::string& effect, const std::string& name) {
  for (const auto& c : r.coefficients)
    if (c.effect == effect && c.name == name) return c;
  throw std::out_of_range(effect + "." + name);
}

bool anyNoteHas(const FitResult& r, const std::string& part) {
  for (const auto& n : r.notes)
    if (n.find(part) != std::string::npos) return true;
  return false;
}

const std::vector<std::string> kPaper = {"hover", "kinetic", "parasitic_drag"};

TEST(FitIdentifiability, HoverOnlyTrainingLeavesDragAreaNotDetermined) {
  const PreparedLog log = fly({{0, 0, 10}, {0.3, 0, 10}}, kPaper);
  const EnergyModel start = buildModel(iris(), kPaper);
  const FitResult r = fitModel(start, {{&log, {}}});
  const auto& drag = find(r, "parasitic_drag", "drag_area");
  EXPECT_FALSE(drag.determined);
  EXPECT_FALSE(drag.fitted);
  EXPECT_DOUBLE_EQ(drag.value, iris().drag_area_m2);  // the vehicle's, not an extrapolation
  EXPECT_DOUBLE_EQ(r.model.effect("parasitic_drag").coefficient("drag_area"), iris().drag_area_m2);
  EXPECT_NE(drag.why_not_determined.find("0 of "), std::string::npos) << drag.why_not_determined;
  EXPECT_NE(drag.why_not_determined.find("faster than 3 m/s"), std::string::npos) << drag.why_not_determined;
  EXPECT_TRUE(anyNoteHas(r, "parasitic_drag.drag_area is not determined by the data"));
  EXPECT_NE(describeEffect("parasitic_drag", r.coefficients).find("NOT DETERMINED"), std::string::npos);
  // Hover power is what these data do determine.
  const auto& hover = find(r, "hover", "hover_power");
  EXPECT_TRUE(hover.determined);
  EXPECT_NEAR(hover.value, marinsHoverPowerW(iris()), 5.0);
  // The kinetic term needs speed changes: a hover has none.
  EXPECT_FALSE(find(r, "kinetic", "effective_mass").determined);
}

TEST(FitIdentifiability, SurveyDeterminesEveryPaperCoefficient) {
  const PreparedLog log = fly({{0, 0, 0}, {0, 0, 15}, {160, 0, 15}, {160, 25, 15}, {0, 25, 15}, {0, 0, 0}}, kPaper);
  const FitResult r = fitModel(buildModel(iris(), kPaper), {{&log, {}}});
  for (const auto& c : r.coefficients) {
    EXPECT_TRUE(c.determined) << c.effect << "." << c.name << ": " << c.why_not_determined;
    EXPECT_TRUE(c.fitted) << c.effect << "." << c.name;
  }
}

TEST(FitIdentifiability, ClimbOnlyDeterminesClimbButNotDescent) {
  const std::vector<std::string> effects = {"hover", "climb"};
  const PreparedLog log = fly({{0, 0, 0}, {0, 0, 40}}, effects);
  const FitResult r = fitModel(buildModel(iris(), effects), {{&log, {}}});
  EXPECT_TRUE(find(r, "climb", "climb_mass").determined);
  const auto& descent = find(r, "climb", "descent_mass");
  EXPECT_FALSE(descent.determined);
  EXPECT_NE(descent.why_not_determined.find("descending at 0.5 m/s or faster"), std::string::npos)
      << descent.why_not_determined;
}

TEST(FitIdentifiability, NothingToFitStillAnswers) {
  const std::vector<std::string> effects = {"parasitic_drag"};
  const PreparedLog log = fly({{0, 0, 10}, {0.3, 0, 10}}, kPaper);
  const FitResult r = fitModel(buildModel(iris(), effects), {{&log, {}}});
  ASSERT_EQ(r.coefficients.size(), 1u);
  EXPECT_FALSE(r.coefficients[0].determined);
  EXPECT_TRUE(std::isfinite(r.train_rmse_w));
}

// A straight cruise in one direction at one speed: drag and hover power (and a wind along the
// track) change the power alike, so the fit can only give their sum. Each used to come back
// "determined" with an uncertainty many times its value (a hover power of 204 +- 1.5e3 W, a wind
// of 15 +- 1e3 m/s ready to paste into replay --wind); now none is.
TEST(FitIdentifiability, AnUncertaintyLargerThanTheValueIsNotDetermined) {
  const std::vector<std::string> effects = {"hover", "wind"};
  SimulationSettings s;
  s.rate_hz = 5.0;
  s.power_noise_w = 10.0;
  s.hover_s = 0.0;
  const auto full = simulateFlight({{0, 0, 10}, {1500, 0, 10}}, buildModel(iris(), kPaper), s);
  FlightLog cruise = full;  // the constant-speed middle only
  cruise.samples.clear();
  for (const auto& x : full.samples)
    if (x.position.x() > 200 && x.position.x() < 1300) cruise.samples.push_back(x);
  cruise.airborne = {{cruise.samples.front().t, cruise.samples.back().t}};
  const PreparedLog log = prepareLog(cruise);
  const FitResult r = fitModel(buildModel(iris(), effects), {{&log, {}}});
  int undetermined = 0;
  for (const auto& c : r.coefficients) {
    if (!c.fitted) continue;
    if (c.determined) {  // what stays determined is known to better than its own size
      EXPECT_LT(c.sigma, std::abs(c.value)) << c.effect << "." << c.name;
    } else {
      ++undetermined;
      EXPECT_FALSE(c.why_not_determined.empty());
    }
  }
  EXPECT_GE(undetermined, 2) << describeEffect("wind", r.coefficients);
  EXPECT_NE(describeEffect("wind", r.coefficients).find("wind not determined"), std::string::npos)
      << describeEffect("wind", r.coefficients);
}

// A coefficient that stops at its physical bound is the bound, not a measurement: no +-, not
// determined (fit printed "effective_mass 0 +- 0.96 kg", determined, where calibrate said "at its
// bound ... not a measurement").
TEST(FitIdentifiability, ACoefficientAtItsBoundIsNotDetermined) {
  const PreparedLog log = fly({{0, 0, 0}, {0, 0, 15}, {160, 0, 15}, {160, 25, 15}, {0, 25, 15}, {0, 0, 0}}, {"hover"});
  // The data have no kinetic power at all, and noise: the effective mass is pushed to 0 or near it.
  const FitResult r = fitModel(buildModel(iris(), kPaper), {{&log, {}}});
  const auto& m = find(r, "kinetic", "effective_mass");
  if (m.at_bound) {
    EXPECT_FALSE(m.determined);
    EXPECT_TRUE(std::isnan(m.sigma));
    EXPECT_NE(m.why_not_determined.find("stopped at its physical bound"), std::string::npos) << m.why_not_determined;
  } else {
    EXPECT_FALSE(m.determined && m.sigma >= m.value) << m.value << " +- " << m.sigma;
  }
  for (const auto& c : r.coefficients) {
    EXPECT_FALSE(c.at_bound && c.determined) << c.effect << "." << c.name;
  }
}

TEST(FitIdentifiability, SettingsAreValidated) {
  FitSettings s;
  s.excitation.min_fraction = 2.0;
  const PreparedLog log = fly({{0, 0, 10}, {0.3, 0, 10}}, kPaper);
  EXPECT_THROW(fitModel(buildModel(iris(), kPaper), {{&log, {}}}, s), std::invalid_argument);
}

}  // namespace
