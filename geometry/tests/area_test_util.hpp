#pragma once
// Shared by the survey-area reader tests (test_geoio.cpp, test_area_formats.cpp).
#include <string>

#include "wattswath/geometry/survey_area.hpp"

namespace wattswath::test {

/// Message of the SurveyAreaError thrown by reading `path` ("" when none is thrown).
inline std::string errorOf(const std::string& path, const geometry::ReadOptions& o = {}) {
  try {
    geometry::readSurveyArea(path, o);
  } catch (const geometry::SurveyAreaError& e) {
    return e.what();
  }
  return "";
}

}  // namespace wattswath::test
