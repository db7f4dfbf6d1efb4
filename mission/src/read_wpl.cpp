// QGC WPL 110 (`.waypoints`) reader, by the rules of pymavlink's MAVWPLoader, Mission Planner's
// WaypointFile and QGroundControl's MissionItem::load(QTextStream), plus decimal commas.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <system_error>

#include "files_internal.hpp"

namespace wattswath::mission {
namespace {
using detail::fail;

constexpr const char* kHeader = "QGC WPL 110";
constexpr const char* kColumns[12] = {"index",    "current",  "frame",     "command",  "param1",   "param2",
                                      "param3",   "param4",   "latitude",  "longitude", "altitude", "autocontinue"};

/// One data row as written: the 12 columns.
struct Row {
  long index = 0, current = 0, frame = 0, command = 0, autocontinue = 1;
  double p[7] = {0, 0, 0, 0, 0, 0, 0};  // param1..4, lat [deg], lon [deg], alt [m]
};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

/// The whitespace-separated fields of `line`; `tabs_only` is set when every separator is tabs.
std::vector<std::string> splitFields(const std::string& line, bool& tabs_only) {
  std::vector<std::string> out;
  tabs_only = true;
  std::size_t i = 0;
  while (i < line.size()) {
    const std::size_t b = line.find_first_not_of(" \t", i);
    if (b == std::string::npos) break;
    if (!out.empty() && line.find(' ', i) < b) tabs_only = false;
    const std::size_t e = std::min(line.find_first_of(" \t", b), line.size());
    out.push_back(line.substr(b, e - b));
    i = e;
  }
  return out;
}

/// "43,7159500" -> "43.7159500" when decimal commas are allowed here; throws otherwise.
std::string decimalPoint(const std::string& field, bool commas_ok, const std::string& where, const char* column) {
  const std::size_t c = field.find(',');
  if (c == std::string::npos) return field;
  const std::string got = std::string(column) + " = \"" + detail::printable(field) + "\"";
  if (!commas_ok) fail(where, got + ", expected a number with a decimal point (decimal commas are accepted only in tab-separated lines)");
  const bool digitsAround = c > 0 && c + 1 < field.size() && std::isdigit(static_cast<unsigned char>(field[c - 1])) &&
                            std::isdigit(static_cast<unsigned char>(field[c + 1]));
  if (!digitsAround || field.find_first_of(",.", c + 1) != std::string::npos || field.find('.') < c)
    fail(where, got + ", expected a number (one decimal comma or point between digits)");
  std::string s = field;
  s[c] = '.';
  return s;
}

double realField(const std::string& field, bool commas_ok, const std::string& where, const char* column) {
  std::string s = decimalPoint(field, commas_ok, where, column);
  if (s.size() > 1 && s[0] == '+') s.erase(0, 1);
  double v = 0.0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec == std::errc::result_out_of_range || std::isinf(v))
    fail(where, std::string(column) + " = \"" + detail::printable(field) + "\", expected a finite number in the range of a double");
  if (r.ec != std::errc() || r.ptr != s.data() + s.size())
    fail(where, std::string(column) + " = \"" + detail::printable(field) + "\", expected a number");
  return v;
}

long intField(const std::string& field, const std::string& where, const char* column, long lo, long hi) {
  long v = 0;
  const auto r = std::from_chars(field.data(), field.data() + field.size(), v);
  if (r.ec != std::errc() || r.ptr != field.data() + field.size() || v < lo || v > hi)
    fail(where, std::string(column) + " = \"" + detail::printable(field) + "\", expected an integer in [" + std::to_string(lo) + ", " +
                    std::to_string(hi) + "]");
  return v;
}

Row parseRow(const std::string& line, const std::string& where) {
  bool tabs_only = true;
  const auto f = splitFields(line, tabs_only);
  if (f.size() != 12)
    fail(where, std::to_string(f.size()) + " columns, expected 12 (INDEX CURRENT FRAME COMMAND PARAM1..4 LAT LON ALT "
                                           "AUTOCONTINUE, tab separated)");
  Row r;
  r.index = intField(f[0], where, kColumns[0], 0, 65535);
  r.current = intField(f[1], where, kColumns[1], 0, 1);
  r.frame = intField(f[2], where, kColumns[2], 0, 255);
  r.command = intField(f[3], where, kColumns[3], 0, 65535);
  for (int k = 0; k < 7; ++k) r.p[k] = realField(f[4 + k], tabs_only, where, kColumns[4 + k]);
  r.autocontinue = intField(f[11], where, kColumns[11], 0, 1);
  return r;
}

/// The warning for a data row `line` (line end removed) that QGroundControl's MissionItem::load
/// (QTextStream) cannot read: it splits a line on single tabs and needs exactly 12 fields (a space
/// separator, a trailing or doubled tab fail it, and the whole file with it). Mission Planner
/// (WaypointFile) splits on tabs and commas, so a space-separated row fails there too. Empty when
/// QGroundControl reads the line.
std::string unsplitRow(const std::string& line, const std::string& where) {
  const auto tabs = static_cast<std::size_t>(std::count(line.begin(), line.end(), '\t'));
  if (tabs + 1 == 12) return {};
  bool tabs_only = true;
  splitFields(line, tabs_only);
  const std::string read = " (this program reads it; pymavlink splits on any white space), so save the file with one tab "
                           "between columns and none at the end of a line before loading it in a ground station";
  if (!tabs_only) {
    return where + ": columns separated by spaces: QGroundControl and Mission Planner would not read this file "
           "(QGroundControl's MissionItem::load splits a line on tabs only and needs exactly 12 fields; Mission Planner "
           "splits on tabs and commas)" + read;
  }
  return where + ": " + std::to_string(tabs + 1) + " tab-separated fields" +
         (!line.empty() && line.back() == '\t' ? std::string(" (a tab at the end of the line)") : std::string()) +
         ": QGroundControl would not read this file (MissionItem::load splits a line on tabs and needs exactly 12 fields)" + read;
}

void checkHeader(const std::string& first, const std::string& source) {
  std::istringstream in(first);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  if (words.size() == 3 && words[0] == "QGC" && words[1] == "WPL" && words[2] == "110") return;
  if (words.size() == 3 && words[0] == "QGC" && words[1] == "WPL")
    fail(source + ":1", "QGC WPL version " + detail::printable(words[2]) + " is not supported, expected the header \"" + kHeader + "\"");
  fail(source + ":1", "header \"" + detail::printable(first) + "\", expected \"" + kHeader + "\"");
}

void setHome(Mission& m, const Row& r, const std::string& where) {
  if (r.p[4] == 0.0 && r.p[5] == 0.0) {
    m.warnings.push_back(where + ": the home row has no position (0, 0)");
    return;
  }
  m.home = {r.p[4], r.p[5], r.frame == 0 ? r.p[6] : 0.0};
  detail::checkHomePoint(m.home, where);
  m.home_known = true;
  if (r.frame != 0)
    m.warnings.push_back(where + ": home row frame = " + std::to_string(r.frame) +
                         ", so its altitude is not above mean sea level; home altitude taken as 0 m");
}

MissionItem itemOf(const Row& r, int seq, const std::string& where) {
  MissionItem it;
  it.seq = seq;
  it.command = static_cast<int>(r.command);
  it.frame = static_cast<int>(r.frame);
  for (int k = 0; k < 4; ++k) it.param[k] = r.p[k];
  it.lat_deg = r.p[4];
  it.lon_deg = r.p[5];
  it.alt_m = r.p[6];
  it.autocontinue = r.autocontinue == 1;
  it.where = where;
  return it;
}

/// Adds data row number `row` (0 = first after the header) of line `where`.
void addRow(Mission& m, const Row& r, int row, bool& home_row, const std::string& where) {
  if (row == 0) {
    home_row = r.index == 0;  // Mission Planner: a first row numbered other than 0 means "no home row"
    if (home_row) return setHome(m, r, where);
    m.warnings.push_back(where + ": the first row is numbered " + std::to_string(r.index) +
                         ", not 0: no home row; every row is an item, as Mission Planner reads it (QGroundControl takes the first row "
                         "as home whatever its number, and would drop this item)");
  }
  const int seq = home_row ? row : row + 1;
  if (r.index != seq)
    m.warnings.push_back(where + ": index " + std::to_string(r.index) + " but this is item " + std::to_string(seq) +
                         " (items are numbered by their row, as the autopilot does)");
  m.items.push_back(itemOf(r, seq, where));
}

}  // namespace

Mission parseQgcWpl(const std::string& text, const std::string& source, const ReadOptions& o) {
  Mission m;
  m.source = source;
  m.format = "waypoints";
  std::string body = detail::withoutBom(text);
  detail::checkText(body, source);
  // Lines ended by CR alone (classic Mac OS; .NET's ReadLine, which Mission Planner uses, accepts them).
  if (body.find('\n') == std::string::npos) std::replace(body.begin(), body.end(), '\r', '\n');
  std::istringstream in(body);
  std::string line;
  int number = 0, row = 0;
  bool home_row = false;
  std::string first_comma;  // the first line read with decimal commas
  std::string first_unsplit;  // the first row QGroundControl would not split into 12 fields, and why
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (number == 1) {
      checkHeader(trim(line), source);
      continue;
    }
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const std::string where = source + ":" + std::to_string(number);
    addRow(m, parseRow(t, where), row++, home_row, where);
    if (first_comma.empty() && t.find(',') != std::string::npos) first_comma = where;
    if (first_unsplit.empty()) first_unsplit = unsplitRow(line, where);
  }
  if (!first_unsplit.empty()) m.warnings.push_back(first_unsplit);
  if (!first_comma.empty()) {
    m.warnings.push_back(first_comma + ": decimal commas read as decimal points (an older Mission Planner in a comma "
                         "locale); QGroundControl reads such a number as 0 and a current Mission Planner splits it into two "
                         "columns, so save the file with decimal points before uploading it");
  }
  if (number == 0) fail(source, "empty file, expected the header \"" + std::string(kHeader) + "\"");
  if (m.items.empty()) fail(source, "no mission items after the home row, expected at least one");
  checkMission(m, o);
  return m;
}

}  // namespace wattswath::mission
