// wattswath fit end to end on identifiability (issue 19): a hover-only training log reports the drag
// area as not determined, in words and in JSON, and keeps the vehicle's value.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_util.hpp"

namespace {

using wattswath::test::Outcome;
using wattswath::test::runCli;

TEST(CliFit, HoverOnlyLogReportsDragAreaNotDetermined) {
  const std::vector<std::string> args = {"fit", "--vehicle", "data/vehicles/iris.json", "--log",
                                         "tests/data/good/log_hover_only.csv"};
  Outcome r = runCli(args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("parasitic_drag: drag area 0.0155 m^2; drag_area NOT DETERMINED by the data (not fitted: "
                       "kept at its starting value)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("note: parasitic_drag.drag_area is not determined by the data: 0 of 43 airborne samples faster "
                       "than 3 m/s horizontally (20 needed)"),
            std::string::npos)
      << r.out;
  auto json_args = args;
  json_args.push_back("--json");
  r = runCli(json_args);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_DOUBLE_EQ(j["coefficients"]["parasitic_drag"]["drag_area"].get<double>(), 0.01547);
  EXPECT_TRUE(j["uncertainty"]["parasitic_drag"]["drag_area"].is_null());
  const auto& id = j["identifiability"]["parasitic_drag"]["drag_area"];
  EXPECT_EQ(id["determined"], false);
  EXPECT_EQ(id["fitted"], false);
  EXPECT_NE(id["why_not_determined"].get<std::string>().find("faster than 3 m/s"), std::string::npos) << id;
  EXPECT_EQ(j["identifiability"]["hover"]["hover_power"]["determined"], true);
}

}  // namespace
