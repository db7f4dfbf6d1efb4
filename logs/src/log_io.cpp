#include "wattswath/logs/log_io.hpp"
#include "wattswath/io/text_file.hpp"

#include <GeographicLib/LocalCartesian.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <sstream>
#include <stdexcept>

#include "binary_read.hpp"
#include "wattswath/logs/local_fit.hpp"
#include "wattswath/logs/tolerances.hpp"

namespace wattswath::logs {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string trim(const std::string& s) {
  size_t a = 0, b = s.size();
  while (a < b && (s[a] == ' ' || s[a] == '\t')) ++a;
  while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t')) --b;
  return s.substr(a, b - a);
}

std::vector<std::string> splitCommas(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ',') {
      out.push_back(trim(cur));
      cur.clear();
    } else {
      cur.push_back(c);
    }
  }
  out.push_back(trim(cur));
  return out;
}

[[noreturn]] void fail(const std::string& source, size_t line, const std::string& what) {
  throw std::runtime_error(source + ":" + std::to_string(line) + ": " + what);
}

/// The columns the model uses, in the order of kKnown.
enum Column : int {
  kTime, kX, kY, kZ, kLat, kLon, kAlt, kVx, kVy, kVz, kAx, kAy, kAz,
  kYaw, kVoltage, kCurrent, kPower, kMass, kWindX, kWindY, kColumnCount
};

/// A column the model uses, with whether an empty cell means "not measured".
struct Known {
  const char* name;
  bool empty_ok;
};
constexpr std::array<Known, kColumnCount> kKnown = {{{"time_s", false},    {"x_m", false},       {"y_m", false},
                                                     {"z_m", false},       {"lat_deg", false},   {"lon_deg", false},
                                                     {"alt_m", false},     {"vx_mps", false},    {"vy_mps", false},
                                                     {"vz_mps", false},    {"ax_mps2", false},   {"ay_mps2", false},
                                                     {"az_mps2", false},   {"yaw_rad", true},    {"voltage_v", false},
                                                     {"current_a", false}, {"power_w", false},   {"mass_kg", true},
                                                     {"wind_x_mps", true}, {"wind_y_mps", true}}};

/// The known column named `n`, or -1 (run once per header column, not per cell).
int knownIndex(const std::string& n) {
  for (size_t i = 0; i < kKnown.size(); ++i)
    if (n == kKnown[i].name) return static_cast<int>(i);
  return -1;
}

std::string fmt(double v) {
  std::array<char, 64> buf{};
  auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return std::string(buf.data(), r.ptr);
}

/// "-100000..100000 m": the altitude bound of log samples and origin metadata, in plain digits.
std::string altitudeRange() {
  const std::string b = std::to_string(static_cast<long long>(tol::kLogMaxAltitude));
  return "-" + b + ".." + b + " m";
}

}  // namespace

void deriveKinematics(FlightLog& log, bool velocity, bool acceleration, const DerivativeSettings& d) {
  if (d.half_window < 1 || d.half_window > 50) {
    throw std::invalid_argument("DerivativeSettings.half_window = " + std::to_string(d.half_window) +
                                ", expected 1..50 samples");
  }
  auto& s = log.samples;
  if (s.size() < 2) return;
  const int n = static_cast<int>(s.size());
  if (velocity) {
    std::vector<Eigen::Vector3d> v(s.size());
    for (size_t i = 0; i < s.size(); ++i)
      for (int k = 0; k < 3; ++k)
        v[i][k] = detail::localSlope(
            n, static_cast<int>(i), d.half_window, [&](int j) { return s[j].t; }, [&](int j) { return s[j].position[k]; });
    for (size_t i = 0; i < s.size(); ++i) s[i].velocity = v[i];
    log.velocity_derived = true;
    log.metadata["velocity_derivation"] = "quadratic least-squares (Savitzky-Golay) derivative of position over " +
                                          std::to_string(2 * d.half_window + 1) + " samples";
  }
  if (acceleration) {
    std::vector<Eigen::Vector3d> a(s.size());
    for (size_t i = 0; i < s.size(); ++i)
      for (int k = 0; k < 3; ++k)
        a[i][k] = detail::localSlope(
            n, static_cast<int>(i), d.half_window, [&](int j) { return s[j].t; }, [&](int j) { return s[j].velocity[k]; });
    for (size_t i = 0; i < s.size(); ++i) s[i].acceleration = a[i];
    log.acceleration_derived = true;
    log.metadata["acceleration_derivation"] = "quadratic least-squares (Savitzky-Golay) derivative of velocity over " +
                                              std::to_string(2 * d.half_window + 1) + " samples";
  }
}

FlightLog readCsvLog(const std::string& path, const DerivativeSettings& d, long long max_file_bytes) {
  return parseCsvLog(binary::readWholeFile<std::string>(path, max_file_bytes), path, d);
}

namespace {

/// Reads a canonical CSV log into a FlightLog: the header once (names, duplicates and which
/// columns are present), then row by row, converting each row as it is read. Every error names
/// the source, the line and the column.
class CsvLogReader {
 public:
  CsvLogReader(FlightLog& log, const std::string& source) : log_(log), source_(source) {}

  /// Whether the header row has been read.
  bool hasHeader() const { return !header_.empty(); }
  /// The header's line number (1-based).
  size_t headerLine() const { return header_line_; }
  /// Whether positions are local x, y, z [m] (else geodetic, converted to ENU).
  bool local() const { return local_; }
  /// Whether the log gives velocities (else they are derived).
  bool haveVelocity() const { return have_vel_; }
  /// Whether the log gives accelerations (else they are derived).
  bool haveAcceleration() const { return have_acc_; }

  /// Reads the header row at `line_no`: names, duplicates, known and extra columns, then the checks.
  void readHeader(const std::string& line, size_t line_no) {
    header_ = splitCommas(line);
    header_line_ = line_no;
    std::unordered_map<std::string_view, size_t> seen;  // name -> first column: linear in the header's width
    seen.reserve(header_.size());
    for (size_t c = 0; c < header_.size(); ++c) {
      if (header_[c].empty()) fail(source_, line_no, "column " + std::to_string(c + 1) + " has an empty name");
      if (!seen.emplace(header_[c], c).second) {
        fail(source_, line_no, "column '" + header_[c] + "' appears twice (fields " + std::to_string(seen[header_[c]] + 1) +
                                   " and " + std::to_string(c + 1) + ")");
      }
      const int k = knownIndex(header_[c]);
      if (k >= 0) {
        col_of_[k] = static_cast<int>(c);
      } else {
        extra_idx_.push_back(static_cast<int>(c));
        log_.extra_columns.push_back(header_[c]);
      }
    }
    checkColumns();
  }

  /// Converts the row at line `ln` (its comma-separated fields) into a sample.
  void addRow(size_t ln, const std::vector<std::string>& f) {
    if (f.size() != header_.size()) {
      fail(source_, ln, "row has " + std::to_string(f.size()) + " fields, the header has " + std::to_string(header_.size()));
    }
    LogSample s;
    s.t = number(kTime, ln, f);
    s.position = position(ln, f);
    if (have_vel_) s.velocity = {number(kVx, ln, f), number(kVy, ln, f), number(kVz, ln, f)};
    if (have_acc_) s.acceleration = {number(kAx, ln, f), number(kAy, ln, f), number(kAz, ln, f)};
    s.yaw = number(kYaw, ln, f);
    s.voltage = number(kVoltage, ln, f);
    s.current = number(kCurrent, ln, f);
    if (s.current < tol::kLogMinCurrent) {
      fail(source_, ln, "column 'current_a': value " + fmt(s.current) + " A is below " + fmt(tol::kLogMinCurrent) +
                            " A (a multirotor draws current: is the current sensor's sign or offset wrong?)");
    }
    s.power = have_power_ ? number(kPower, ln, f) : s.voltage * s.current;
    if (!have_power_ && !(std::abs(s.power) <= tol::kLogMaxMagnitude)) {
      // Written back as power_w, which is bounded like every value: the log would not read back.
      fail(source_, ln, "columns 'voltage_v' x 'current_a': power " + fmt(s.power) +
                            " W is too large, expected a magnitude of at most " + fmt(tol::kLogMaxMagnitude));
    }
    s.mass = number(kMass, ln, f);
    s.wind = {number(kWindX, ln, f), number(kWindY, ln, f)};
    checkTime(ln, s.t);
    std::vector<std::string> extra;
    extra.reserve(extra_idx_.size());
    for (int c : extra_idx_) extra.push_back(f[c]);
    log_.extra_values.push_back(std::move(extra));
    log_.samples.push_back(s);
  }

 private:
  bool has(Column k) const { return col_of_[k] >= 0; }

  void require(Column k, const std::string& why) const {
    if (!has(k)) fail(source_, header_line_, "missing required column '" + std::string(kKnown[k].name) + "' (" + why + ")");
  }

  /// Whether all three columns of `g` are present; one or two of them is an error naming the missing one.
  bool groupAll(std::array<Column, 3> g) const {
    const int n = has(g[0]) + has(g[1]) + has(g[2]);
    if (n != 0 && n != 3) {
      for (Column c : g)
        if (!has(c)) {
          fail(source_, header_line_,
               "missing column '" + std::string(kKnown[c].name) + "': give all of " + kKnown[g[0]].name + ", " +
                   kKnown[g[1]].name + ", " + kKnown[g[2]].name + " or none");
        }
    }
    return n == 3;
  }

  /// The header's checks: time, one kind of position, power, whole groups, both wind columns.
  void checkColumns() {
    require(kTime, "sample time");
    local_ = has(kX) || has(kY) || has(kZ);
    const bool geodetic = !local_ && (has(kLat) || has(kLon) || has(kAlt));
    if (local_) {
      for (Column c : {kX, kY, kZ}) require(c, "local position x_m, y_m, z_m");
    } else if (geodetic) {
      for (Column c : {kLat, kLon, kAlt}) require(c, "geodetic position lat_deg, lon_deg, alt_m");
    } else {
      fail(source_, header_line_, "missing required column 'x_m' (position: x_m, y_m, z_m or lat_deg, lon_deg, alt_m)");
    }
    have_power_ = has(kPower);
    if (!have_power_) {
      require(kVoltage, "battery power: voltage_v and current_a, or power_w");
      require(kCurrent, "battery power: voltage_v and current_a, or power_w");
    }
    have_vel_ = groupAll({kVx, kVy, kVz});
    have_acc_ = groupAll({kAx, kAy, kAz});
    if (has(kWindX) != has(kWindY)) {
      fail(source_, header_line_,
           std::string("missing column '") + (has(kWindX) ? "wind_y_mps" : "wind_x_mps") + "': give both wind columns or none");
    }
    // In a local-frame log the lat/lon/alt columns are not used: keep them verbatim.
    if (local_) {
      for (Column c : {kLat, kLon, kAlt}) {
        if (has(c)) {
          extra_idx_.push_back(col_of_[c]);
          log_.extra_columns.push_back(kKnown[c].name);
          col_of_[c] = -1;
        }
      }
    }
  }

  /// The value of column `k` in the row at line `ln`: NaN when absent (or empty where allowed),
  /// else a finite number within the log's bounds.
  double number(Column k, size_t ln, const std::vector<std::string>& f) const {
    const int c = col_of_[k];
    if (c < 0) return kNaN;
    const std::string& cell = f[c];
    const std::string name = kKnown[k].name;
    if (cell.empty()) {
      if (kKnown[k].empty_ok) return kNaN;
      fail(source_, ln, "column '" + name + "' (field " + std::to_string(c + 1) + "): empty value, expected a finite number");
    }
    double v = 0.0;
    const char* b = cell.data();
    const char* e = b + cell.size();
    if (*b == '+' && e - b > 1 && b[1] != '-') ++b;
    auto r = std::from_chars(b, e, v);
    if (r.ec != std::errc() || r.ptr != e || !std::isfinite(v)) {
      fail(source_, ln, "column '" + name + "' (field " + std::to_string(c + 1) + "): value '" + cell + "' is not a finite number");
    }
    const bool bounded_elsewhere = k == kTime || k == kLat || k == kLon;
    if (!bounded_elsewhere && std::abs(v) > tol::kLogMaxMagnitude) {
      fail(source_, ln, "column '" + name + "' (field " + std::to_string(c + 1) + "): value '" + cell +
                            "' is too large, expected a magnitude of at most " + fmt(tol::kLogMaxMagnitude));
    }
    return v;
  }

  /// The row's position [m]: local as given, or geodetic converted to ENU about the first row.
  Eigen::Vector3d position(size_t ln, const std::vector<std::string>& f) {
    if (local_) return {number(kX, ln, f), number(kY, ln, f), number(kZ, ln, f)};
    const double lat = number(kLat, ln, f), lon = number(kLon, ln, f), alt = number(kAlt, ln, f);
    if (std::abs(lat) > 90.0) fail(source_, ln, "column 'lat_deg': value " + fmt(lat) + " is outside -90..90 degrees");
    if (std::abs(lon) > 180.0) fail(source_, ln, "column 'lon_deg': value " + fmt(lon) + " is outside -180..180 degrees");
    if (std::abs(alt) > tol::kLogMaxAltitude) {
      fail(source_, ln, "column 'alt_m': value " + fmt(alt) + " is outside " + altitudeRange());
    }
    if (!enu_) {
      enu_.emplace(lat, lon, alt);
      log_.has_geodetic_origin = true;
      log_.origin_lat_deg = lat;
      log_.origin_lon_deg = lon;
      log_.origin_alt_m = alt;
    }
    double x = 0, y = 0, z = 0;
    enu_->Forward(lat, lon, alt, x, y, z);
    return {x, y, z};
  }

  /// Times must increase by at least the log's smallest step.
  void checkTime(size_t ln, double t) const {
    if (log_.samples.empty()) return;
    const double previous = log_.samples.back().t;
    if (!(t > previous)) {
      fail(source_, ln, "column 'time_s': time " + fmt(t) + " s does not increase (previous row: " + fmt(previous) + " s)");
    }
    if (t - previous < tol::kLogMinTimeStep) {
      fail(source_, ln, "column 'time_s': time " + fmt(t) + " s is only " + fmt(t - previous) +
                            " s after the previous row, expected steps of at least " + fmt(tol::kLogMinTimeStep) + " s");
    }
  }

  FlightLog& log_;
  const std::string& source_;
  std::vector<std::string> header_;
  std::array<int, kColumnCount> col_of_ = [] {
    std::array<int, kColumnCount> a{};
    a.fill(-1);
    return a;
  }();                          // known column -> index in the row
  std::vector<int> extra_idx_;  // columns kept verbatim
  size_t header_line_ = 0;
  bool local_ = false, have_power_ = false, have_vel_ = false, have_acc_ = false;
  std::optional<GeographicLib::LocalCartesian> enu_;
};

/// A local-frame log written from a geodetic one keeps its origin in the metadata: read it back.
void readGeodeticOrigin(FlightLog& log, const std::string& source, size_t header_line) {
  if (!(log.metadata.count("origin_lat_deg") && log.metadata.count("origin_lon_deg") && log.metadata.count("origin_alt_m"))) {
    return;
  }
  // Whole-text, finite, in range: std::stod would read "43.7abc" as 43.7 and accept "nan".
  auto origin = [&](const char* key, double limit, const std::string& expected) {
    const std::string& text = log.metadata[key];
    double v = 0.0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(v) ||
        std::abs(v) > limit) {
      fail(source, header_line, "metadata '" + std::string(key) + "': value '" + text + "', expected " + expected);
    }
    return v;
  };
  log.origin_lat_deg = origin("origin_lat_deg", 90.0, "a latitude in -90..90 degrees");
  log.origin_lon_deg = origin("origin_lon_deg", 180.0, "a longitude in -180..180 degrees");
  log.origin_alt_m = origin("origin_alt_m", tol::kLogMaxAltitude, "an altitude in " + altitudeRange());
  log.has_geodetic_origin = true;
  for (const char* k : {"origin_lat_deg", "origin_lon_deg", "origin_alt_m"}) log.metadata.erase(k);
}

/// Finite inputs can still give non-finite or huge derivatives (positions near 1e308, time steps of
/// 1e-320 s); every later sum would turn NaN silently, so name the first such row.
void checkDerivatives(const FlightLog& log, const std::string& source, const std::vector<size_t>& row_lines) {
  for (size_t i = 0; i < log.samples.size(); ++i) {
    const auto& x = log.samples[i];
    if (!x.velocity.allFinite() || !x.acceleration.allFinite()) {
      fail(source, row_lines[i],
           std::string("derived ") + (x.velocity.allFinite() ? "acceleration" : "velocity") + " at time " + fmt(x.t) +
               " s is not finite, expected finite derivatives (check for huge positions or near-zero time steps)");
    }
    // A derivative beyond the bound would be written back as vx_mps... and not read back.
    const bool vel_big = x.velocity.cwiseAbs().maxCoeff() > tol::kLogMaxMagnitude;
    if (vel_big || x.acceleration.cwiseAbs().maxCoeff() > tol::kLogMaxMagnitude) {
      const Eigen::Vector3d& v = vel_big ? x.velocity : x.acceleration;
      fail(source, row_lines[i],
           std::string("derived ") + (vel_big ? "velocity " : "acceleration ") + fmt(v.cwiseAbs().maxCoeff()) +
               (vel_big ? " m/s" : " m/s^2") + " at time " + fmt(x.t) + " s is too large, expected a magnitude of at most " +
               fmt(tol::kLogMaxMagnitude) + " (check for position jumps or near-zero time steps)");
    }
  }
}

}  // namespace

FlightLog parseCsvLog(const std::string& text_in, const std::string& source, const DerivativeSettings& d) {
  FlightLog log;
  log.source = source;
  log.format = "csv";
  std::string_view text(text_in);
  if (text.size() >= 3 && static_cast<unsigned char>(text[0]) == 0xEF && static_cast<unsigned char>(text[1]) == 0xBB &&
      static_cast<unsigned char>(text[2]) == 0xBF) {
    text.remove_prefix(3);
  }
  CsvLogReader reader(log, source);
  std::vector<size_t> row_lines;  // each sample's line, for the messages about derivatives
  size_t line_no = 0;
  size_t pos = 0;
  while (pos <= text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string line(text.substr(pos, end - pos));
    pos = end + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (trim(line).empty()) {
      if (pos > text.size()) break;
      continue;  // blank line: not a row
    }
    if (!reader.hasHeader()) {
      if (line[0] == '#') {  // "# key: value" metadata before the header
        const std::string body = trim(line.substr(1));
        const size_t colon = body.find(':');
        if (colon != std::string::npos) log.metadata[trim(body.substr(0, colon))] = trim(body.substr(colon + 1));
        continue;
      }
      reader.readHeader(line, line_no);
      continue;
    }
    if (line[0] == '#') {
      fail(source, line_no, "comment line after the header; comments ('# key: value') must come before the header");
    }
    row_lines.push_back(line_no);
    reader.addRow(line_no, splitCommas(line));
  }
  if (!reader.hasHeader()) throw std::runtime_error(source + ":" + std::to_string(line_no) + ": no header row found");
  if (reader.local()) readGeodeticOrigin(log, source, reader.headerLine());
  if (log.samples.size() < 2) {
    throw std::runtime_error(source + ":" + std::to_string(line_no) + ": the log has " +
                             std::to_string(log.samples.size()) + " sample(s), at least 2 are needed");
  }
  deriveKinematics(log, !reader.haveVelocity(), !reader.haveAcceleration(), d);
  checkDerivatives(log, source, row_lines);
  return log;
}

std::string writeCsvLog(const FlightLog& log) {
  const auto& s = log.samples;
  auto anyFinite = [&](auto get) {
    return std::any_of(s.begin(), s.end(), [&](const LogSample& x) { return std::isfinite(get(x)); });
  };
  auto allFinite = [&](auto get) {
    return std::all_of(s.begin(), s.end(), [&](const LogSample& x) { return std::isfinite(get(x)); });
  };
  const bool yaw = anyFinite([](const LogSample& x) { return x.yaw; });
  const bool vi = allFinite([](const LogSample& x) { return x.voltage; }) &&
                  allFinite([](const LogSample& x) { return x.current; });
  const bool mass = anyFinite([](const LogSample& x) { return x.mass; });
  const bool wind = anyFinite([](const LogSample& x) { return x.wind.x(); }) ||
                    anyFinite([](const LogSample& x) { return x.wind.y(); });
  if (log.extra_values.size() != 0 && log.extra_values.size() != s.size()) {
    throw std::invalid_argument("writeCsvLog: " + std::to_string(log.extra_values.size()) + " rows of extra values for " +
                                std::to_string(s.size()) + " samples");
  }

  std::string out;
  out.reserve(s.size() * 160 + 512);
  for (const auto& [k, v] : log.metadata) {
    if (log.has_geodetic_origin && k.rfind("origin_", 0) == 0) continue;  // written below
    out += "# " + k + ": " + v + "\n";
  }
  if (log.has_geodetic_origin) {
    out += "# origin_lat_deg: " + fmt(log.origin_lat_deg) + "\n# origin_lon_deg: " + fmt(log.origin_lon_deg) +
           "\n# origin_alt_m: " + fmt(log.origin_alt_m) + "\n";
  }
  out += "time_s,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,ax_mps2,ay_mps2,az_mps2";
  if (yaw) out += ",yaw_rad";
  if (vi) out += ",voltage_v,current_a";
  out += ",power_w";
  if (mass) out += ",mass_kg";
  if (wind) out += ",wind_x_mps,wind_y_mps";
  for (const auto& c : log.extra_columns) out += "," + c;
  out += "\n";
  auto cell = [&](double v, size_t i, const char* what, bool optional) {
    if (!std::isfinite(v)) {
      if (optional) return std::string();
      throw std::invalid_argument("writeCsvLog: sample " + std::to_string(i) + " (t = " + fmt(s[i].t) + " s): " + what +
                                  " is not finite");
    }
    return fmt(v);
  };
  for (size_t i = 0; i < s.size(); ++i) {
    const auto& x = s[i];
    const double p = std::isfinite(x.power) ? x.power : x.voltage * x.current;
    out += cell(x.t, i, "time", false);
    for (int k = 0; k < 3; ++k) out += "," + cell(x.position[k], i, "position", false);
    for (int k = 0; k < 3; ++k) out += "," + cell(x.velocity[k], i, "velocity", false);
    for (int k = 0; k < 3; ++k) out += "," + cell(x.acceleration[k], i, "acceleration", false);
    if (yaw) out += "," + cell(x.yaw, i, "yaw", true);
    if (vi) out += "," + cell(x.voltage, i, "voltage", false) + "," + cell(x.current, i, "current", false);
    out += "," + cell(p, i, "power (and voltage * current)", false);
    if (mass) out += "," + cell(x.mass, i, "mass", true);
    if (wind) out += "," + cell(x.wind.x(), i, "wind", true) + "," + cell(x.wind.y(), i, "wind", true);
    if (!log.extra_values.empty()) {
      for (const auto& v : log.extra_values[i]) out += "," + v;
    }
    out += "\n";
  }
  return out;
}

/// [m] shortest leg of a waypoint path: the vehicle stops and turns at each waypoint, so 1 mm legs
/// (200,000 of them made a 985 MB log) are mistakes, not a path.
constexpr double kMinPathLeg = 0.01;

std::vector<Eigen::Vector3d> parseWaypointPath(const std::string& text, const std::string& source) {
  std::istringstream in(text);
  std::vector<Eigen::Vector3d> w;
  std::string line;
  int ln = 0;
  auto number = [](double x) {
    std::ostringstream os;
    os << x;
    return os.str();
  };
  while (std::getline(in, line)) {
    ++ln;
    for (char& c : line)
      if (c == ',' || c == '\r' || c == '\t') c = ' ';
    if (line.find_first_not_of(' ') == std::string::npos || line[line.find_first_not_of(' ')] == '#') continue;
    std::istringstream is(line);
    double x, y, z;
    std::string rest;
    if (!(is >> x >> y >> z) || (is >> rest)) {
      std::istringstream first(line);
      double probe = 0.0;
      if (w.empty() && ln == 1 && !(first >> probe)) continue;  // a header (not a row of numbers)
      throw std::runtime_error(source + ":" + std::to_string(ln) + ": expected three numbers x y z [m], got '" + line + "'");
    }
    if (!(std::abs(x) <= tol::kLogMaxMagnitude && std::abs(y) <= tol::kLogMaxMagnitude &&
          std::abs(z) <= tol::kLogMaxMagnitude)) {
      throw std::runtime_error(source + ":" + std::to_string(ln) + ": expected three numbers x y z [m] of magnitude at most " +
                               number(tol::kLogMaxMagnitude) + ", got '" + line + "'");
    }
    if (!w.empty() && (Eigen::Vector3d(x, y, z) - w.back()).norm() < kMinPathLeg) {
      throw std::runtime_error(source + ":" + std::to_string(ln) + ": waypoint '" + line + "' is " +
                               number((Eigen::Vector3d(x, y, z) - w.back()).norm()) +
                               " m from the previous one, expected legs of at least " + number(kMinPathLeg) +
                               " m (each waypoint is a stop and a turn: remove the repeat)");
    }
    w.emplace_back(x, y, z);
  }
  if (w.size() < 2) throw std::runtime_error(source + ": a path needs at least 2 waypoints");
  return w;
}

std::vector<Eigen::Vector3d> readWaypointPath(const std::string& path) {
  // io::FileError is a std::runtime_error naming the file.
  return parseWaypointPath(io::readTextFile(path, {kMaxPathFileBytes, "path files", ""}), path);
}

}  // namespace wattswath::logs
