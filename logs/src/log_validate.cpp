// One validation of the values the DataFlash and ULog readers extract, with the canonical CSV
// reader's bounds (tolerances.hpp), and the check of gaps between samples of any assembled log.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "autopilot_log_internal.hpp"
#include "wattswath/logs/tolerances.hpp"

namespace wattswath::logs {
namespace detail {
namespace {

// What is wrong with `v` [unit] as a flight-log value (empty: nothing); NaN allowed when `optional`.
std::string problem(double v, const char* unit, bool optional, double lowest = -tol::kLogMaxMagnitude) {
  if (std::isnan(v) && optional) return {};
  if (!std::isfinite(v)) return num(v) + " " + unit + " is not a finite number";
  if (std::abs(v) > tol::kLogMaxMagnitude)
    return num(v) + " " + unit + " is too large, expected a magnitude of at most " + num(tol::kLogMaxMagnitude) + " " + unit;
  if (v < lowest) {
    return num(v) + " " + unit + " is below " + num(lowest) + " " + unit +
           " (a multirotor draws current; is the current sensor's sign or offset wrong?)";
  }
  return {};
}

// Keeps the rows of `t` (and of the same-length `cols`) whose index is not in `bad` (increasing).
template <typename... Cols>
void dropRows(const std::vector<std::size_t>& bad, std::vector<double>& t, Cols&... cols) {
  auto select = [&](auto& v) {
    std::remove_reference_t<decltype(v)> out;
    std::size_t b = 0;
    for (std::size_t k = 0; k < v.size(); ++k) {
      if (b < bad.size() && bad[b] == k) { ++b; continue; }
      out.push_back(v[k]);
    }
    v.swap(out);
  };
  select(t);
  (select(cols), ...);
}

// The first problem of a series (empty: none) and, lenient, the rows to drop.
struct Findings {
  std::string first;
  std::vector<std::size_t> rows;
};

// Throws (strict) or records (lenient) row `k`'s problem `what`, found in `field` at time `t` [s].
void note(Findings& f, std::size_t k, const std::string& field, double t, const std::string& what,
          const std::string& source, bool lenient) {
  if (what.empty()) return;
  const std::string text = field + " at t = " + num(t, 10) + " s: " + what;
  if (!lenient)
    throw std::runtime_error(source + ": " + text + " (the CSV reader's bound; --lenient drops such samples)");
  if (f.first.empty()) f.first = text;
  if (f.rows.empty() || f.rows.back() != k) f.rows.push_back(k);
}

std::string dropped(const Findings& f, std::size_t n, const std::string& series) {
  return std::to_string(f.rows.size()) + " of " + std::to_string(n) + " " + series + " samples out of bounds dropped (first: " +
         f.first + ")";
}

void validateBattery(Raw& raw, const std::string& source, bool lenient) {
  Battery& b = raw.battery;
  Findings f;
  std::size_t negative = 0;
  double lowest = 0.0;
  for (std::size_t k = 0; k < b.t.size(); ++k) {
    note(f, k, b.voltage_field, b.t[k], problem(b.v[k], "V", false), source, lenient);
    note(f, k, b.current_field, b.t[k], problem(b.i[k], "A", true, tol::kLogMinCurrent), source, lenient);
    const double p = b.v[k] * b.i[k];
    if (std::isfinite(b.v[k]) && std::isfinite(b.i[k]))
      note(f, k, b.voltage_field + " x " + b.current_field, b.t[k], problem(p, "W", false), source, lenient);
    if (b.i[k] < 0.0 && b.i[k] >= tol::kLogMinCurrent) {
      ++negative;
      lowest = std::min(lowest, b.i[k]);
    }
  }
  if (negative) {
    raw.warnings.push_back(std::to_string(negative) + " battery samples with a small negative current (down to " +
                           num(lowest) + " A, the sensor's offset) kept as measured");
  }
  if (f.rows.empty()) return;
  raw.warnings.push_back(dropped(f, b.t.size(), "battery"));
  dropRows(f.rows, b.t, b.v, b.i);
}

void validatePosition(Raw& raw, const std::string& source, bool lenient) {
  Findings f;
  for (std::size_t k = 0; k < raw.pt.size(); ++k) {
    for (int c = 0; c < 3; ++c) {
      note(f, k, raw.position_message + "." + raw.pos_fields[c], raw.pt[k], problem(raw.pos[k][c], "m", false), source, lenient);
      note(f, k, raw.position_message + "." + raw.vel_fields[c], raw.pt[k], problem(raw.vel[k][c], "m/s", false), source,
           lenient);
      if (raw.has_acc) {
        note(f, k, raw.position_message + "." + raw.acc_fields[c], raw.pt[k], problem(raw.acc[k][c], "m/s^2", false),
             source, lenient);
      }
    }
  }
  if (f.rows.empty()) return;
  raw.warnings.push_back(dropped(f, raw.pt.size(), "position"));
  dropRows(f.rows, raw.pt, raw.pos, raw.vel, raw.acc, raw.yaw);
}

}  // namespace

void validateRaw(Raw& raw, const std::string& source, bool lenient) {
  validateBattery(raw, source, lenient);
  validatePosition(raw, source, lenient);
}

void validateDerivedAcceleration(const Raw& raw, const std::string& source) {
  if (raw.has_acc) return;
  for (std::size_t k = 0; k < raw.pt.size(); ++k) {
    for (int c = 0; c < 3; ++c) {
      const std::string what = problem(raw.acc[k][c], "m/s^2", false);
      if (what.empty()) continue;
      throw std::runtime_error(source + ": acceleration derived from " + raw.position_message + "." + raw.vel_fields[c] +
                               " at t = " + num(raw.pt[k], 10) + " s: " + what +
                               " (the CSV reader's bound; check for velocity jumps between close samples)");
    }
  }
}

}  // namespace detail

void checkSampleGaps(const FlightLog& log, double max_gap_s) {
  const auto& s = log.samples;
  // Every step long (1 Hz logged in ms reads 1000 s a step): a unit, not a stopped logger.
  if (s.size() > 2) {
    std::vector<double> steps;
    for (std::size_t k = 1; k < s.size(); ++k) steps.push_back(s[k].t - s[k - 1].t);
    std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2), steps.end());
    const double median = steps[steps.size() / 2];
    if (median > max_gap_s) {
      throw std::runtime_error(log.source + ": the samples are a median " + detail::num(median) +
                               " s apart, more than the " + detail::num(max_gap_s) +
                               " s allowed between two: is time_s logged in milliseconds (or microseconds)? The canonical "
                               "log's time is in seconds (docs: flight-log CSV format)");
    }
  }
  for (std::size_t k = 1; k < s.size(); ++k) {
    const double gap = s[k].t - s[k - 1].t;
    if (gap <= max_gap_s) continue;
    throw std::runtime_error(log.source + ": no sample for " + detail::num(gap) + " s, from t = " + detail::num(s[k - 1].t, 10) +
                             " s to t = " + detail::num(s[k].t, 10) + " s, expected at most " + detail::num(max_gap_s) +
                             " s between samples (the logger stopped, or two flights are in one log: the energy over "
                             "the gap was not measured); read each part with --from / --to, or raise --max-gap");
  }
}

}  // namespace wattswath::logs
