// Autopilot logs in: the common assembly of what the DataFlash and ULog readers extract
// (dataflash_log.cpp, ulog_log.cpp) into one FlightLog, airborne windows, time windows, and
// reading any log by its format.
#include "wattswath/logs/autopilot_log.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "autopilot_log_internal.hpp"
#include "wattswath/logs/log_io.hpp"

namespace wattswath::logs {
namespace detail {

/// Between two warnings in metadata `warnings` (one line of the CSV's `# warnings:` comment).
constexpr const char* kWarningSeparator = " | ";

std::string num(double x, int precision) {
  std::ostringstream os;
  os.precision(precision);
  os << x;
  return os.str();
}

bool setOrigin(Raw& raw, double lat, double lon, double alt) {
  if (!std::isfinite(lat) || !std::isfinite(lon) || std::abs(lat) > 90.0 || std::abs(lon) > 180.0 || (lat == 0.0 && lon == 0.0))
    return false;
  raw.has_origin = true;
  raw.origin_lat = lat;
  raw.origin_lon = lon;
  raw.origin_alt = std::isfinite(alt) ? alt : 0.0;
  return true;
}

double median(std::vector<double> x) {
  if (x.empty()) return kNaN;
  const auto mid = x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2);
  std::nth_element(x.begin(), mid, x.end());
  return *mid;
}

namespace {

double rateHz(const std::vector<double>& t) {
  std::vector<double> dt;
  for (std::size_t k = 1; k < t.size(); ++k) dt.push_back(t[k] - t[k - 1]);
  const double m = median(dt);
  return m > 0 ? 1.0 / m : kNaN;
}

// Keeps the longest run of rows whose time strictly increases; returns how many were dropped.
template <typename... Cols>
std::size_t keepIncreasing(std::vector<double>& t, Cols&... cols) {
  // The longest strictly increasing run of finite times (patience sorting, O(n log n)): one corrupt
  // timestamp far ahead costs that sample only, where keeping the increasing prefix dropped every
  // sample after it.
  std::vector<std::size_t> tails, prev(t.size(), SIZE_MAX);
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (!std::isfinite(t[k])) continue;
    const auto at = std::lower_bound(tails.begin(), tails.end(), t[k], [&](std::size_t i, double v) { return t[i] < v; });
    if (at != tails.begin()) prev[k] = *(at - 1);
    if (at == tails.end()) tails.push_back(k);
    else *at = k;
  }
  std::vector<std::size_t> keep(tails.size());
  for (std::size_t n = tails.size(), k = tails.empty() ? 0 : tails.back(); n > 0; k = prev[k]) keep[--n] = k;
  const std::size_t dropped = t.size() - keep.size();
  auto select = [&](auto& v) {
    std::remove_reference_t<decltype(v)> out;
    out.reserve(keep.size());
    for (std::size_t k : keep) out.push_back(v[k]);
    v.swap(out);
  };
  select(t);
  (select(cols), ...);
  return dropped;
}

std::vector<double> unwrap(std::vector<double> a) {
  for (std::size_t k = 1; k < a.size(); ++k) {
    if (!std::isfinite(a[k]) || !std::isfinite(a[k - 1])) continue;
    a[k] = a[k - 1] + std::remainder(a[k] - a[k - 1], 2 * kPi);
  }
  return a;
}

// Acceleration from the position source's velocities at their native rate (log_io's smoothing).
std::vector<Eigen::Vector3d> accelerationFrom(const std::vector<double>& t, const std::vector<Eigen::Vector3d>& v) {
  FlightLog tmp;
  for (std::size_t k = 0; k < t.size(); ++k) {
    LogSample s;
    s.t = t[k];
    s.velocity = v[k];
    tmp.samples.push_back(s);
  }
  deriveKinematics(tmp, false, true);
  std::vector<Eigen::Vector3d> a;
  for (const auto& s : tmp.samples) a.push_back(s.acceleration);
  return a;
}

// The charge the logged current draws over the whole battery series against the battery's capacity
// (a parameter of the log): more than the pack holds is a current sensor reading high (a wrong
// scale, ArduPilot BATT_AMP_PERVLT / PX4 BAT1_A_PER_V) or a capacity parameter that is not this
// pack's. Either way the energies from this log are in doubt, and the reader says so.
void checkChargeAgainstCapacity(const Battery& b, std::map<std::string, std::string>& m, std::vector<std::string>& warnings) {
  double as = 0.0;  // [A s]
  for (std::size_t k = 1; k < b.t.size(); ++k)
    if (std::isfinite(b.i[k]) && std::isfinite(b.i[k - 1])) as += 0.5 * (b.i[k] + b.i[k - 1]) * (b.t[k] - b.t[k - 1]);
  const double drawn_mah = as / 3.6;
  m["charge_drawn_mah"] = std::to_string(std::lround(drawn_mah));
  const auto cap = m.find("battery_capacity_mah");
  if (cap == m.end()) return;
  const double capacity = std::stod(cap->second);
  if (!(capacity > 0.0) || drawn_mah <= capacity) return;
  warnings.push_back("the logged current draws " + std::to_string(std::lround(drawn_mah)) + " mAh, " +
                     std::to_string(std::lround(100.0 * drawn_mah / capacity)) +
                     " % of the battery's capacity (" + m["battery_capacity_source"] + ": " + cap->second +
                     " mAh): either the current sensor reads high (its scale, ArduPilot BATT_AMP_PERVLT or PX4 "
                     "BAT1_A_PER_V, is wrong) or the capacity set is not this pack's; energies from this log rest "
                     "on that current");
}

}  // namespace

FlightLog assemble(Raw raw, const std::string& source, const LogReadOptions& opt) {
  const std::string where = source + ": ";
  Battery& b = raw.battery;
  // Drop non-increasing times first: the interpolation below needs two position samples left.
  const std::size_t bd = keepIncreasing(b.t, b.v, b.i);
  const std::size_t pd = keepIncreasing(raw.pt, raw.pos, raw.vel, raw.acc, raw.yaw);
  validateRaw(raw, source, opt.lenient);  // the CSV reader's bounds: the log converts and reads back
  auto dropped = [](std::size_t d) {
    return d ? ", " + std::to_string(d) + " more with non-increasing or non-finite time not used" : std::string();
  };
  if (b.t.size() < 2) {
    throw std::runtime_error(where + "fewer than two battery samples (" + std::to_string(b.t.size()) + dropped(bd) +
                             "; looked for " + raw.meta["battery_candidates"] + ")");
  }
  if (raw.pt.size() < 2) {
    throw std::runtime_error(where + "fewer than two position samples (" + std::to_string(raw.pt.size()) + dropped(pd) +
                             "; looked for " + raw.meta["position_candidates"] + ")");
  }
  if (bd) raw.warnings.push_back(std::to_string(bd) + " battery samples with non-increasing time not used");
  if (pd) raw.warnings.push_back(std::to_string(pd) + " position samples with non-increasing time not used");
  if (!raw.has_acc) raw.acc = accelerationFrom(raw.pt, raw.vel);
  validateDerivedAcceleration(raw, source);
  const std::vector<double> yaw = unwrap(raw.yaw);

  FlightLog log;
  log.source = source;
  log.format = raw.format;
  log.velocity_derived = false;
  log.acceleration_derived = !raw.has_acc;
  log.has_geodetic_origin = raw.has_origin;  // the EKF origin: the ENU positions are measured from it
  log.origin_lat_deg = raw.origin_lat;
  log.origin_lon_deg = raw.origin_lon;
  log.origin_alt_m = raw.origin_alt;
  std::size_t before = 0, after = 0;
  double max_gap = 0.0, gap_from = 0.0;
  std::size_t j = 0;
  for (std::size_t k = 0; k < b.t.size(); ++k) {
    const double t = b.t[k];
    if (t < raw.pt.front()) { ++before; continue; }
    if (t > raw.pt.back()) { ++after; continue; }
    while (j + 2 < raw.pt.size() && raw.pt[j + 1] < t) ++j;
    const double t0 = raw.pt[j], t1 = raw.pt[j + 1];
    const double w = t1 > t0 ? std::clamp((t - t0) / (t1 - t0), 0.0, 1.0) : 0.0;
    if (t1 - t0 > max_gap) {
      max_gap = t1 - t0;
      gap_from = t0;
    }
    LogSample s;
    s.t = t;
    s.position = (1 - w) * raw.pos[j] + w * raw.pos[j + 1];
    s.velocity = (1 - w) * raw.vel[j] + w * raw.vel[j + 1];
    s.acceleration = (1 - w) * raw.acc[j] + w * raw.acc[j + 1];
    s.yaw = std::remainder((1 - w) * yaw[j] + w * yaw[j + 1], 2 * kPi);
    s.voltage = b.v[k];
    s.current = b.i[k];
    s.power = s.voltage * s.current;
    log.samples.push_back(s);
  }
  log.airborne = detectAirborne(b.t, b.i, raw.landed, opt.airborne);
  const auto last_change = std::max_element(raw.landed.begin(), raw.landed.end(),
                                            [](const LandedChange& x, const LandedChange& y) { return x.t < y.t; });
  const bool landed_at_end = last_change != raw.landed.end() && last_change->landed;
  if (!log.airborne.empty() && log.airborne.back().end >= b.t.back() && !landed_at_end) {
    raw.warnings.push_back("the log ends while airborne (at " + num(b.t.back(), 10) + " s, airborne since " +
                           num(log.airborne.back().begin, 10) + " s): the landing is not in the log");
    raw.meta["ends_airborne"] = "yes";
  }
  if (!log.airborne.empty() && log.airborne.front().begin <= b.t.front()) {
    raw.warnings.push_back("the log starts while airborne (at " + num(b.t.front(), 10) + " s, airborne until " +
                           num(log.airborne.front().end, 10) + " s" +
                           (raw.landed.empty() ? ", current above " + num(opt.airborne.current_threshold_a) + " A" : std::string()) +
                           "): the take-off is not in the log");
    raw.meta["starts_airborne"] = "yes";
  }
  // The windows were found on the battery's clock; the samples are where position data exist too.
  if (!log.samples.empty()) {
    std::vector<TimeWindow> clipped;
    for (auto w : log.airborne) {
      w.begin = std::max(w.begin, log.samples.front().t);
      w.end = std::min(w.end, log.samples.back().t);
      if (w.end > w.begin) clipped.push_back(w);
    }
    log.airborne.swap(clipped);
  }
  // Each reader collects its events kind by kind; the log lists them in time order (stable: one
  // time keeps the readers' order).
  std::stable_sort(raw.events.begin(), raw.events.end(), [](const LogEvent& a, const LogEvent& b) { return a.t < b.t; });
  log.events = std::move(raw.events);

  auto& m = log.metadata;
  m = raw.meta;
  m.erase("battery_candidates");
  m.erase("position_candidates");
  m["source_file"] = source;
  m["source_format"] = raw.format;
  m["firmware"] = raw.firmware;
  m["vehicle"] = raw.vehicle;
  m["battery_source"] = b.label;
  if (!raw.battery_others.empty()) {
    std::string o;
    for (const auto& s : raw.battery_others) o += (o.empty() ? "" : "; ") + s;
    m["battery_sources_not_used"] = o;
  }
  m["position_source"] = raw.position_source;
  m["battery_rate_hz"] = num(rateHz(b.t), 4);
  m["position_rate_hz"] = num(rateHz(raw.pt), 4);
  m["data_start_s"] = num(std::min(b.t.front(), raw.pt.front()), 10);
  m["data_end_s"] = num(std::max(b.t.back(), raw.pt.back()), 10);
  m["battery_samples_outside_position"] = std::to_string(before) + " before, " + std::to_string(after) + " after";
  m["position_max_gap_s"] = num(max_gap, 4);
  if (max_gap > tol::kLogPositionGapWarn) {
    raw.warnings.push_back("no position sample for " + num(max_gap, 3) + " s, from " + num(gap_from, 10) + " s to " +
                           num(gap_from + max_gap, 10) + " s: the positions and velocities across it are interpolated "
                           "in a straight line, not measured");
  }
  checkChargeAgainstCapacity(b, m, raw.warnings);
  m["resampling"] = "battery sample times; position, velocity, acceleration, yaw linearly interpolated";
  m["frame"] = "ENU from the EKF origin (x east, y north, z up)";
  m["airborne_source"] = raw.landed.empty()
                             ? "current > " + num(opt.airborne.current_threshold_a) + " A"
                             : raw.landed_source + " (before the first: current > " +
                                   num(opt.airborne.current_threshold_a) + " A)";
  std::string w;
  for (const auto& s : raw.warnings) w += (w.empty() ? "" : kWarningSeparator) + s;
  if (!w.empty()) m["warnings"] = w;
  if (log.samples.size() < 2)
    throw std::runtime_error(where + "battery and position data do not overlap in time (battery " +
                             num(b.t.front()) + "-" + num(b.t.back()) + " s, position " + num(raw.pt.front()) + "-" +
                             num(raw.pt.back()) + " s)");
  applyTimeWindow(log, opt);
  checkSampleGaps(log, opt.max_gap_s);
  return log;
}

}  // namespace detail

using namespace detail;

std::vector<TimeWindow> detectAirborne(const std::vector<double>& t, const std::vector<double>& current,
                                       const std::vector<LandedChange>& changes, const AirborneSettings& s) {
  std::vector<TimeWindow> raw;
  if (t.size() < 2 || current.size() != t.size()) return raw;
  const double t_end = t.back();
  std::vector<LandedChange> ch = changes;
  std::stable_sort(ch.begin(), ch.end(), [](const LandedChange& a, const LandedChange& b) { return a.t < b.t; });
  // Before the first change the current decides, unless that change is a take-off (then the
  // vehicle was on the ground before it).
  const double first_change = ch.empty() ? std::numeric_limits<double>::infinity()
                              : ch.front().landed ? ch.front().t : -std::numeric_limits<double>::infinity();
  // Current-based part, up to the first landed-state change.
  auto flying = [&](std::size_t k) { return std::isfinite(current[k]) && current[k] > s.current_threshold_a; };
  auto crossing = [&](std::size_t k) {  // time between samples k-1 and k where current crosses the threshold
    const double a = current[k - 1], b = current[k];
    if (!std::isfinite(a) || !std::isfinite(b) || a == b) return t[k];
    return t[k - 1] + (s.current_threshold_a - a) / (b - a) * (t[k] - t[k - 1]);
  };
  bool in = false;
  double start = 0.0;
  for (std::size_t k = 0; k < t.size() && t[k] < first_change; ++k) {
    const bool f = flying(k);
    if (f && !in) { in = true; start = k == 0 ? t[0] : crossing(k); }
    if (!f && in) { in = false; raw.push_back({start, crossing(k)}); }
  }
  if (in) raw.push_back({start, std::min(first_change, t_end)});
  // A first change that is a landing says the vehicle flew until then: the current-based window
  // that ended shortly before it (low current in the last metres of a descent) runs up to it.
  if (!ch.empty() && ch.front().landed && !raw.empty() && raw.back().end < first_change &&
      first_change - raw.back().end <= s.landing_extend_s)
    raw.back().end = first_change;
  // Event-based part.
  for (std::size_t k = 0; k < ch.size(); ++k) {
    if (ch[k].landed) continue;
    std::size_t m = k + 1;
    while (m < ch.size() && !ch[m].landed) ++m;
    const double end = m < ch.size() ? ch[m].t : t_end;
    raw.push_back({std::max(ch[k].t, t.front()), std::min(end, t_end)});
    k = m == ch.size() ? m : m - 1;
  }
  // A landing event ends a window the current opened before it.
  std::sort(raw.begin(), raw.end(), [](const TimeWindow& a, const TimeWindow& b) { return a.begin < b.begin; });
  std::vector<TimeWindow> merged;
  for (const auto& w : raw) {
    if (w.end <= w.begin) continue;
    if (!merged.empty() && w.begin - merged.back().end < s.merge_gap_s) merged.back().end = std::max(merged.back().end, w.end);
    else merged.push_back(w);
  }
  std::vector<TimeWindow> out;
  for (const auto& w : merged)
    if (w.end - w.begin >= s.min_duration_s) out.push_back(w);
  return out;
}

namespace {
// Why no airborne window was found, when the battery current explains it (a log without working
// current sensing and without logged take-offs has none): " (...)" or empty.
std::string noAirborneReason(const FlightLog& log, const LogReadOptions& opt) {
  double largest = -std::numeric_limits<double>::infinity();
  bool any = false;
  for (const auto& s : log.samples) {
    if (!std::isfinite(s.current)) continue;
    any = true;
    largest = std::max(largest, s.current);
  }
  if (!any) return " (the log has no battery current and no logged take-off; give the window with --from / --to)";
  if (largest <= opt.airborne.current_threshold_a) {
    return " (the battery current never exceeds " + num(opt.airborne.current_threshold_a) + " A, largest " + num(largest) +
           " A, and no take-off is logged: is the current measured? --airborne-current sets the threshold)";
  }
  return "";
}
}  // namespace

void applyTimeWindow(FlightLog& log, const LogReadOptions& opt) {
  double from = opt.from_s, to = opt.to_s;
  if (std::isnan(from) || std::isnan(to) || from > to)
    throw std::invalid_argument(log.source + ": time window from " + num(from) + " s to " + num(to) + " s is empty or invalid");
  if (opt.airborne_only) {
    if (log.airborne.empty()) throw std::runtime_error(log.source + ": --airborne: no airborne window found" + noAirborneReason(log, opt));
    from = std::max(from, log.airborne.front().begin);
    to = std::min(to, log.airborne.back().end);
  }
  if (std::isinf(from) && std::isinf(to) && !opt.airborne_only) return;
  const double span0 = log.samples.empty() ? kNaN : log.samples.front().t, span1 = log.samples.empty() ? kNaN : log.samples.back().t;
  std::vector<LogSample> kept;
  std::vector<std::vector<std::string>> extra;
  for (std::size_t k = 0; k < log.samples.size(); ++k) {
    if (log.samples[k].t < from || log.samples[k].t > to) continue;
    kept.push_back(log.samples[k]);
    if (k < log.extra_values.size()) extra.push_back(log.extra_values[k]);
  }
  if (kept.size() < 2)
    throw std::runtime_error(log.source + ": " + std::to_string(kept.size()) + " samples in the window " + num(from) + " s to " +
                             num(to) + " s (data span " + num(span0) + " s to " + num(span1) + " s); need at least 2");
  log.samples.swap(kept);
  if (!log.extra_values.empty()) log.extra_values.swap(extra);
  std::vector<TimeWindow> air;
  for (auto w : log.airborne) {
    w.begin = std::max(w.begin, from);
    w.end = std::min(w.end, to);
    if (w.end > w.begin) air.push_back(w);
  }
  log.airborne.swap(air);
  std::vector<LogEvent> ev;
  for (const auto& e : log.events)
    if (e.t >= from && e.t <= to) ev.push_back(e);
  log.events.swap(ev);
  log.metadata["window"] = num(log.samples.front().t, 10) + " s to " + num(log.samples.back().t, 10) + " s" +
                           (opt.airborne_only ? " (airborne part)" : "");
}

std::vector<std::string> readerWarnings(const FlightLog& log) {
  std::vector<std::string> out;
  const auto w = log.metadata.find("warnings");
  if (w == log.metadata.end()) return out;
  const std::string sep = kWarningSeparator;
  for (std::size_t b = 0; b < w->second.size();) {
    const std::size_t e = std::min(w->second.find(sep, b), w->second.size());
    out.push_back(w->second.substr(b, e - b));
    b = e + sep.size();
  }
  return out;
}

LogFormat detectLogFormat(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  char head[7] = {};
  in.read(head, sizeof head);
  const auto n = in.gcount();
  if (n >= 7 && std::string(head, 4) == "ULog" && static_cast<unsigned char>(head[4]) == 0x01 &&
      static_cast<unsigned char>(head[5]) == 0x12 && static_cast<unsigned char>(head[6]) == 0x35)
    return LogFormat::Ulog;
  if (n >= 2 && static_cast<unsigned char>(head[0]) == 0xA3 && static_cast<unsigned char>(head[1]) == 0x95)
    return LogFormat::DataFlash;
  if (n == 0) throw std::runtime_error(path + ": empty file (0 bytes), expected a flight log (canonical CSV, ArduPilot .bin or PX4 .ulg)");
  // A binary log's name with neither binary header: say so, rather than read it as a CSV.
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  if (ext == ".bin" || ext == ".ulg") {
    char hex[8];
    std::string first;
    for (std::streamsize k = 0; k < std::min<std::streamsize>(n, 4); ++k) {
      std::snprintf(hex, sizeof hex, "%s0x%02X", k ? " " : "", static_cast<unsigned char>(head[k]));
      first += hex;
    }
    throw std::runtime_error(path + ": not an ArduPilot DataFlash (.bin) or PX4 ULog (.ulg) log: it begins with bytes " + first +
                             ", expected 0xA3 0x95 (DataFlash) or \"ULog\" 0x01 0x12 0x35 (ULog)");
  }
  return LogFormat::Csv;
}

FlightLog readFlightLog(const std::string& path, const LogReadOptions& options) {
  switch (detectLogFormat(path)) {
    case LogFormat::Ulog: return readUlogLog(path, options);
    case LogFormat::DataFlash: return readDataFlashLog(path, options);
    case LogFormat::Csv: break;
  }
  FlightLog log = readCsvLog(path, {}, options.max_file_bytes);
  if (log.airborne.empty()) {
    std::vector<double> t, i;
    for (const auto& s : log.samples) {
      t.push_back(s.t);
      i.push_back(s.current);
    }
    log.airborne = detectAirborne(t, i, {}, options.airborne);
    log.metadata["airborne_source"] = "current > " + num(options.airborne.current_threshold_a) + " A";
  }
  applyTimeWindow(log, options);
  checkSampleGaps(log, options.max_gap_s);
  return log;
}

}  // namespace wattswath::logs
