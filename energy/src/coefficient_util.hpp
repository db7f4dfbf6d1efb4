#pragma once
// Private helper of energy/src: builds a Coefficient in one expression (effect constructors).
#include "wattswath/energy/effect.hpp"

namespace wattswath::energy::detail {

/// A coefficient `name` = `value` [`unit`] bounded to [lo, hi], with its plain-language meaning.
inline Coefficient coef(const char* name, double value, const char* unit, double lo, double hi, const char* meaning) {
  Coefficient c;
  c.name = name;
  c.value = value;
  c.unit = unit;
  c.lower = lo;
  c.upper = hi;
  c.meaning = meaning;
  return c;
}

}  // namespace wattswath::energy::detail
