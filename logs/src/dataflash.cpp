#include "wattswath/logs/dataflash.hpp"

#include <algorithm>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "binary_read.hpp"

namespace wattswath::logs::dataflash {
namespace {

constexpr std::uint8_t kHead1 = 0xA3;
constexpr std::uint8_t kHead2 = 0x95;
constexpr int kFmtType = 128;
constexpr int kFmtLength = 89;  // 3 header + B B n[4] N[16] Z[64]
/// Appended to the warning when a file that ends inside its last record is read anyway.
constexpr const char* kCutEndAccepted =
    "; ArduPilot's logger leaves its last record cut when the file is closed while it writes: that part is "
    "dropped, the rest is read";

std::string hexByte(std::uint8_t b) {
  static const char* digits = "0123456789ABCDEF";
  return std::string("0x") + digits[b >> 4] + digits[b & 15];
}

std::string text(const std::uint8_t* p, std::size_t n) {
  std::string s(reinterpret_cast<const char*>(p), n);
  const auto nul = s.find('\0');
  if (nul != std::string::npos) s.resize(nul);
  return s;
}

std::vector<std::string> splitColumns(const std::string& s) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty() || !out.empty()) out.push_back(cur);
  return out;
}

// Fills offsets/decodable/problem from name, format, columns and length.
void layout(Format& f) {
  f.offsets.clear();
  int off = 0;
  for (char c : f.format) {
    const int size = formatCharSize(c);
    if (size == 0) {
      f.problem = std::string("unknown format character '") + c + "'";
      return;
    }
    f.offsets.push_back(off);
    off += size;
  }
  if (f.columns.size() != f.format.size()) {
    f.problem = std::to_string(f.format.size()) + " format characters but " +
                std::to_string(f.columns.size()) + " column labels";
    return;
  }
  if (off + 3 != f.length) {
    f.problem = "format '" + f.format + "' needs " + std::to_string(off + 3) + " bytes but FMT says " +
                std::to_string(f.length);
    return;
  }
  f.decodable = true;
}

// ArduCopter <= 3.1 (and the ArduPilot of its time) describes FMT itself with 4 column names for
// its 5 format characters, "Type,Length,Name,Format"; the fifth, the columns text, is unnamed.
// pymavlink names it "Columns" the same way.
bool isOldFmtOfFmt(const Format& f) {
  return f.type == kFmtType && f.name == "FMT" && f.format == "BBnNZ" &&
         f.columns == std::vector<std::string>{"Type", "Length", "Name", "Format"};
}

bool isText(char c) { return c == 'n' || c == 'N' || c == 'Z'; }

double decode(char c, const std::uint8_t* p) {
  using namespace binary;
  switch (c) {
    case 'b': return static_cast<double>(readLe<std::int8_t>(p));
    case 'B': case 'M': return static_cast<double>(readLe<std::uint8_t>(p));
    case 'h': return static_cast<double>(readLe<std::int16_t>(p));
    case 'H': return static_cast<double>(readLe<std::uint16_t>(p));
    case 'i': return static_cast<double>(readLe<std::int32_t>(p));
    case 'I': return static_cast<double>(readLe<std::uint32_t>(p));
    case 'q': return static_cast<double>(readLe<std::int64_t>(p));
    case 'Q': return static_cast<double>(readLe<std::uint64_t>(p));
    case 'f': return static_cast<double>(readLe<float>(p));
    case 'd': return readLe<double>(p);
    case 'c': return readLe<std::int16_t>(p) * 0.01;
    case 'C': return readLe<std::uint16_t>(p) * 0.01;
    case 'e': return readLe<std::int32_t>(p) * 0.01;
    case 'E': return readLe<std::uint32_t>(p) * 0.01;
    case 'L': return readLe<std::int32_t>(p) * 1e-7;
    case 'a': return static_cast<double>(readLe<std::int16_t>(p));  // first element of int16[32]
    default: return 0.0;
  }
}

}  // namespace

int formatCharSize(char c) {
  switch (c) {
    case 'b': case 'B': case 'M': return 1;
    case 'h': case 'H': case 'c': case 'C': return 2;
    case 'i': case 'I': case 'f': case 'e': case 'E': case 'L': case 'n': return 4;
    case 'q': case 'Q': case 'd': return 8;
    case 'N': return 16;
    case 'Z': case 'a': return 64;
    default: return 0;
  }
}

namespace {

// The format an FMT message's payload `p` (after the 3 header bytes) defines, laid out.
Format decodeFmt(const std::uint8_t* p) {
  Format f;
  f.type = p[0];
  f.length = p[1];
  f.name = text(p + 2, 4);
  f.format = text(p + 6, 16);
  f.columns = splitColumns(text(p + 22, 64));
  if (isOldFmtOfFmt(f)) f.columns.push_back("Columns");
  layout(f);
  return f;
}

// What is wrong with a format an FMT message defines (empty name, length under 3, FMT itself
// redefined), empty when nothing is.
std::string fmtProblem(const Format& f) {
  if (f.name.empty()) return "FMT defines type " + std::to_string(f.type) + " with an empty name";
  if (f.length < 3) return "FMT for " + f.name + " declares length " + std::to_string(f.length) + " (< 3)";
  if (f.type == kFmtType && (f.length != kFmtLength || !f.decodable))
    return "FMT redefines FMT itself as length " + std::to_string(f.length) + " format '" + f.format + "'";
  return "";
}

}  // namespace

std::string Log::at(std::size_t off) const { return source_ + ": byte offset " + std::to_string(off) + ": "; }

void Log::define(const Format& f, std::size_t pos, bool lenient) {
  const std::string bad = fmtProblem(f);
  if (!bad.empty()) {
    if (!lenient) throw std::runtime_error(at(pos) + bad);
    if (first_problem_.empty()) first_problem_ = at(pos) + bad;
    warnings_.push_back(at(pos) + bad + "; FMT ignored");
    return;
  }
  auto old = formats_.find(f.type);
  const bool differs = old != formats_.end() &&
                       (old->second.length != f.length || old->second.format != f.format || old->second.name != f.name);
  if (differs && records_.count(f.type)) {
    const std::string what = "FMT redefines type " + std::to_string(f.type) + " (" + old->second.name + ") as " + f.name +
                             " after messages of it were read";
    if (!lenient) throw std::runtime_error(at(pos) + what);
    if (first_problem_.empty()) first_problem_ = at(pos) + what;
    warnings_.push_back(at(pos) + what + "; FMT ignored");
    return;
  }
  if (old != formats_.end()) type_by_name_.erase(old->second.name);
  type_by_name_[f.name] = f.type;
  formats_[f.type] = f;
}

Log Log::parse(std::vector<std::uint8_t> bytes, const std::string& source, bool lenient) {
  Log log;
  log.source_ = source;
  log.bytes_ = std::move(bytes);
  const auto& b = log.bytes_;
  const std::size_t n = b.size();
  auto fail = [&](std::size_t off, const std::string& what) { throw std::runtime_error(log.at(off) + what); };
  // Skips from `pos` to the next header in lenient mode; returns the new position.
  auto resync = [&](std::size_t pos, const std::string& what) {
    std::size_t next = pos + 1;
    while (next + 1 < n && !(b[next] == kHead1 && b[next + 1] == kHead2)) ++next;
    if (next + 1 >= n) next = n;
    if (log.first_problem_.empty()) log.first_problem_ = log.at(pos) + what;
    log.warnings_.push_back(log.at(pos) + what + "; skipped " + std::to_string(next - pos) + " bytes");
    return next;
  };

  std::size_t pos = 0;
  while (pos < n) {
    if (n - pos < 3) {
      const std::string what = "file ends " + std::to_string(n - pos) +
                               " bytes after the last message, too short for a message header (truncated)";
      if (!lenient) fail(pos, what);
      log.warnings_.push_back(log.at(pos) + what + kCutEndAccepted);
      log.cut_end_ = true;
      break;
    }
    if (b[pos] != kHead1 || b[pos + 1] != kHead2) {
      const std::string what = "expected message header 0xA3 0x95, found " + hexByte(b[pos]) + " " +
                               hexByte(b[pos + 1]);
      if (!lenient) fail(pos, what);
      pos = resync(pos, what);
      continue;
    }
    const int type = b[pos + 2];
    auto it = log.formats_.find(type);
    int length = 0;
    std::string name;
    if (it != log.formats_.end()) {
      length = it->second.length;
      name = it->second.name;
    } else if (type == kFmtType) {
      length = kFmtLength;
      name = "FMT";
    } else {
      const std::string what = "message type " + std::to_string(type) +
                               " is not defined by an earlier FMT message";
      if (!lenient) fail(pos, what);
      pos = resync(pos, what);
      continue;
    }
    if (n - pos < static_cast<std::size_t>(length)) {
      const std::string what = name + " message (type " + std::to_string(type) + ") needs " +
                               std::to_string(length) + " bytes but only " + std::to_string(n - pos) +
                               " remain: the file is truncated";
      if (!lenient) fail(pos, what);
      log.warnings_.push_back(log.at(pos) + what + kCutEndAccepted);
      log.cut_end_ = true;
      break;
    }
    if (type == kFmtType) {
      if (length < kFmtLength) fail(pos, "FMT messages are " + std::to_string(length) + " bytes, expected 89");
      log.define(decodeFmt(b.data() + pos + 3), pos, lenient);
    }
    log.records_[type].push_back(pos + 3);
    ++log.message_count_;
    pos += static_cast<std::size_t>(length);
  }
  if (!log.formats_.count(kFmtType) && log.message_count_ == 0) {
    throw std::runtime_error(source + ": not an ArduPilot DataFlash log (no message found)");
  }
  return log;
}

const Format* Log::format(const std::string& name) const {
  auto it = type_by_name_.find(name);
  return it == type_by_name_.end() ? nullptr : &formats_.at(it->second);
}

std::size_t Log::count(const std::string& name) const {
  const Format* f = format(name);
  if (!f) return 0;
  auto it = records_.find(f->type);
  return it == records_.end() ? 0 : it->second.size();
}

std::vector<std::string> Log::presentMessages() const {
  std::vector<std::string> out;
  for (const auto& [name, type] : type_by_name_)
    if (records_.count(type)) out.push_back(name);
  return out;
}

bool Log::has(const std::string& name, const std::string& column) const {
  const Format* f = format(name);
  if (!f || !f->decodable || count(name) == 0) return false;
  return std::find(f->columns.begin(), f->columns.end(), column) != f->columns.end();
}

char Log::columnType(const std::string& name, const std::string& column) const {
  const Format* f = format(name);
  if (!f || !f->decodable) return 0;
  auto it = std::find(f->columns.begin(), f->columns.end(), column);
  return it == f->columns.end() ? 0 : f->format[static_cast<std::size_t>(it - f->columns.begin())];
}

const Format& Log::require(const std::string& name, const std::string& column, int* index) const {
  const Format* f = format(name);
  if (!f) throw std::runtime_error(source_ + ": no FMT defines message " + name);
  if (!f->decodable) throw std::runtime_error(source_ + ": message " + name + " cannot be decoded: " + f->problem);
  auto it = std::find(f->columns.begin(), f->columns.end(), column);
  if (it == f->columns.end())
    throw std::runtime_error(source_ + ": message " + name + " has no column " + column + " (format '" +
                             f->format + "')");
  *index = static_cast<int>(it - f->columns.begin());
  return *f;
}

std::vector<double> Log::column(const std::string& name, const std::string& col) const {
  int i = 0;
  const Format& f = require(name, col, &i);
  const char c = f.format[static_cast<std::size_t>(i)];
  if (isText(c)) throw std::runtime_error(source_ + ": " + name + "." + col + " is text, not a number");
  std::vector<double> out;
  auto it = records_.find(f.type);
  if (it == records_.end()) return out;
  out.reserve(it->second.size());
  for (std::size_t off : it->second) out.push_back(decode(c, bytes_.data() + off + f.offsets[static_cast<std::size_t>(i)]));
  return out;
}

std::vector<std::string> Log::textColumn(const std::string& name, const std::string& col) const {
  int i = 0;
  const Format& f = require(name, col, &i);
  const char c = f.format[static_cast<std::size_t>(i)];
  if (!isText(c)) throw std::runtime_error(source_ + ": " + name + "." + col + " is a number, not text");
  std::vector<std::string> out;
  auto it = records_.find(f.type);
  if (it == records_.end()) return out;
  for (std::size_t off : it->second)
    out.push_back(text(bytes_.data() + off + f.offsets[static_cast<std::size_t>(i)],
                       static_cast<std::size_t>(formatCharSize(c))));
  return out;
}

bool Log::hasTime(const std::string& name) const {
  return has(name, "TimeUS") || (name == "GPS" && has(name, "T")) || has(name, "TimeMS");
}

std::vector<double> Log::times(const std::string& name) const {
  std::vector<double> t;
  double scale = 1e-3;
  if (has(name, "TimeUS")) {
    t = column(name, "TimeUS");
    scale = 1e-6;
  } else if (name == "GPS" && has(name, "T")) {
    t = column(name, "T");
  } else if (has(name, "TimeMS")) {
    t = column(name, "TimeMS");
  } else {
    throw std::runtime_error(source_ + ": message " + name + " has no boot timestamp (TimeUS, TimeMS)");
  }
  for (double& x : t) x *= scale;
  return t;
}

std::size_t Log::offsetOf(const std::string& name, std::size_t i) const {
  const Format* f = format(name);
  if (!f) return 0;
  const auto& r = records_.at(f->type);
  return i < r.size() ? r[i] - 3 : 0;
}

Log Log::parseAcceptingCutEnd(std::vector<std::uint8_t> bytes, const std::string& source, bool lenient) {
  Log log = parse(std::move(bytes), source, true);
  const auto& w = log.warnings();
  const bool only_cut_end = w.size() == 1 && log.endsInCutMessage();
  if (!lenient && !w.empty() && !only_cut_end) {
    // The first damaged record as a strict reader meets it (nothing was skipped: the read is refused).
    const std::string first = log.first_problem_.empty() ? w.front() : log.first_problem_;
    throw std::runtime_error(first + " (use --lenient to skip damaged records and read the rest)");
  }
  return log;
}

}  // namespace wattswath::logs::dataflash
