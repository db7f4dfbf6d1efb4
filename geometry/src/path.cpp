#include "wattswath/geometry/path.hpp"

#include <cmath>

namespace wattswath::geometry {

double PathLeg::length() const {
  switch (kind) {
    case PrimitiveKind::Line: return (end - start).norm();
    case PrimitiveKind::Arc: return radius * std::abs(turn_angle);
    case PrimitiveKind::TurnInPlace: return 0.0;
  }
  return 0.0;
}

double CoveragePath::length() const {
  double l = 0.0;
  for (const auto& leg : legs) l += leg.length();
  return l;
}

int CoveragePath::turnCount() const {
  int n = 0;
  for (const auto& leg : legs) {
    if (leg.kind == PrimitiveKind::TurnInPlace || (leg.kind == PrimitiveKind::Arc && leg.role == LegRole::Turn)) ++n;
  }
  return n;
}

}  // namespace wattswath::geometry
