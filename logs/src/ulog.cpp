#include "wattswath/logs/ulog.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "binary_read.hpp"

namespace wattswath::logs::ulog {
namespace {

using binary::readLe;

constexpr std::uint8_t kMagic[7] = {'U', 'L', 'o', 'g', 0x01, 0x12, 0x35};
constexpr std::size_t kHeaderSize = 16;
constexpr std::size_t kMaxFormatSize = 65535;  // a message payload cannot be larger
constexpr int kMaxNesting = 16;
constexpr std::size_t kMaxFormatName = 256;  // [B] longest 'name:' prefix a resynchronisation accepts
constexpr std::uint8_t kSync[8] = {0x2F, 0x73, 0x13, 0x20, 0x25, 0x0C, 0xBB, 0x12};  // the 'S' payload

// Message types of the definitions and data sections after the flag bits ('B' only comes first).
bool isDataType(char t) { return t != 0 && std::strchr("FIMPQARDLCSO", t) != nullptr; }

std::string str(const std::uint8_t* p, std::size_t n) { return std::string(reinterpret_cast<const char*>(p), n); }

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r\n");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r\n");
  return s.substr(a, b - a + 1);
}

double decodeBase(const std::string& type, const std::uint8_t* p) {
  if (type == "float") return static_cast<double>(readLe<float>(p));
  if (type == "double") return readLe<double>(p);
  if (type == "uint8_t" || type == "bool" || type == "char") return static_cast<double>(readLe<std::uint8_t>(p));
  if (type == "int8_t") return static_cast<double>(readLe<std::int8_t>(p));
  if (type == "uint16_t") return static_cast<double>(readLe<std::uint16_t>(p));
  if (type == "int16_t") return static_cast<double>(readLe<std::int16_t>(p));
  if (type == "uint32_t") return static_cast<double>(readLe<std::uint32_t>(p));
  if (type == "int32_t") return static_cast<double>(readLe<std::int32_t>(p));
  if (type == "uint64_t") return static_cast<double>(readLe<std::uint64_t>(p));
  if (type == "int64_t") return static_cast<double>(readLe<std::int64_t>(p));
  return 0.0;
}

// Splits "type[N]" into base type and count (-1 when not an array). Returns false when malformed.
bool parseType(const std::string& t, std::string& base, int& array) {
  const auto lb = t.find('[');
  if (lb == std::string::npos) {
    base = t;
    array = -1;
    return !t.empty();
  }
  if (t.back() != ']' || lb == 0) return false;
  base = t.substr(0, lb);
  const std::string digits = t.substr(lb + 1, t.size() - lb - 2);
  if (digits.empty() || digits.size() > 5 || !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) return false;
  array = std::stoi(digits);
  return array <= static_cast<int>(kMaxFormatSize);
}

// Decodes an info/parameter value of ULog type `type` (may be "char[N]").
std::string infoValue(const std::string& type, const std::uint8_t* p, std::size_t n, double* number) {
  std::string base;
  int array = -1;
  if (parseType(type, base, array) && base == "char") {
    std::string s = str(p, n);
    const auto nul = s.find('\0');
    if (nul != std::string::npos) s.resize(nul);
    return s;
  }
  const std::size_t size = baseTypeSize(base);
  if (size == 0 || n < size || array >= 0) return "";
  const double v = decodeBase(base, p);
  if (number) *number = v;
  if (base == "float" || base == "double") return std::to_string(v);
  return std::to_string(static_cast<long long>(v));
}

}  // namespace

std::size_t baseTypeSize(const std::string& type) {
  if (type == "int8_t" || type == "uint8_t" || type == "bool" || type == "char") return 1;
  if (type == "int16_t" || type == "uint16_t") return 2;
  if (type == "int32_t" || type == "uint32_t" || type == "float") return 4;
  if (type == "int64_t" || type == "uint64_t" || type == "double") return 8;
  return 0;
}

Log Log::parse(std::vector<std::uint8_t> bytes, const std::string& source, bool lenient) {
  Log log;
  log.source_ = source;
  log.bytes_ = std::move(bytes);
  const auto& b = log.bytes_;
  const std::size_t n = b.size();
  if (n < kHeaderSize)
    throw std::runtime_error(source + ": " + std::to_string(n) + " bytes, shorter than the 16-byte ULog header");
  if (std::memcmp(b.data(), kMagic, sizeof kMagic) != 0)
    throw std::runtime_error(source + ": byte offset 0: not a ULog file (magic 'ULog' 0x01 0x12 0x35 missing)");
  log.version_ = b[7];
  log.start_us_ = readLe<std::uint64_t>(b.data() + 8);
  std::size_t pos = kHeaderSize;
  while (pos < n) pos = log.step(pos, lenient);
  log.appended_offsets_.clear();
  log.sub_by_msg_id_.clear();
  return log;
}

std::string Log::where(std::size_t at, char type) const {
  std::string s = source_ + ": byte offset " + std::to_string(at) + ": ";
  if (type >= 32 && type < 127) s += std::string("'") + type + "' message: ";
  return s;
}

// Handles a bad message at `at`: with appended data, jumps to the next appended offset (the spec
// lets the logger leave an incomplete message before it); otherwise throws (strict) or, lenient,
// skips to the next valid message header when `resync` (else, or when none follows, stops).
// Returns the position to continue from (the file size to stop).
std::size_t Log::bad(std::size_t at, char type, const std::string& what, bool lenient, bool resync) {
  const std::size_t n = bytes_.size();
  for (std::uint64_t a : appended_offsets_) {
    if (a > at && a < n) {
      warnings_.push_back(where(at, type) + what + "; continuing at appended data offset " + std::to_string(a));
      return static_cast<std::size_t>(a);
    }
  }
  if (!lenient) throw std::runtime_error(where(at, type) + what + " (use --lenient to skip damaged data and read the rest)");
  std::size_t next = n;
  if (resync)
    for (std::size_t q = at + 1; q + 3 <= n && next == n; ++q)
      if (plausibleAt(q, 0)) next = q;
  gaps_.push_back({at, next - at, next == n, what});
  if (next < n) {
    warnings_.push_back(where(at, type) + what + "; skipped " + std::to_string(next - at) +
                        " bytes to the next valid message at byte offset " + std::to_string(next));
  } else {
    warnings_.push_back(where(at, type) + what + "; the rest of the file (" + std::to_string(n - at) +
                        " bytes) is not read");
  }
  return next;
}

// Reads the message at `pos`; returns the position of the next one.
std::size_t Log::step(std::size_t pos, bool lenient) {
  const auto& b = bytes_;
  const std::size_t n = b.size();
  if (n - pos < 3) {
    return bad(pos, 0, "file ends " + std::to_string(n - pos) +
                           " bytes after the last message, too short for a message header (truncated)", lenient, false);
  }
  const std::size_t size = readLe<std::uint16_t>(b.data() + pos);
  const char type = static_cast<char>(b[pos + 2]);
  if (n - pos - 3 < size) {
    return bad(pos, type, "declares " + std::to_string(size) + " payload bytes but only " +
                              std::to_string(n - pos - 3) + " remain (truncated file)", lenient, true);
  }
  const auto crossing = std::find_if(appended_offsets_.begin(), appended_offsets_.end(), [&](std::uint64_t a) {
    return a > pos && a < pos + 3 + size;
  });
  if (crossing != appended_offsets_.end()) {
    return bad(pos, type, "runs into the appended data at offset " + std::to_string(*crossing) + " (incomplete message)",
               lenient, true);
  }
  if (type == 0) {
    return bad(pos, type, (size == 0 ? "zero-length message of type 0" : "message of type 0") +
                              std::string(" (corrupt or zero-filled data)"), lenient, true);
  }
  const std::size_t next = pos + 3 + size;
  if (lenient && !isDataType(type) && type != 'B' && !plausibleAt(next, 1)) {
    return bad(pos, type, "unknown message type " + std::to_string(static_cast<unsigned char>(type)) +
                              " and no valid message after it (corrupt data)", lenient, true);
  }
  const std::string error = readMessage(pos, type, size);
  if (error.empty()) return next;
  if (lenient && plausibleAt(next, 1)) {
    warnings_.push_back(where(pos, type) + error + "; message skipped");
    return next;
  }
  return bad(pos, type, error, lenient, true);
}

// Flag bits ('B'): appended-data offsets; throws for unknown incompatible flags.
std::string Log::readFlagBits(std::size_t pos, const std::uint8_t* p, std::size_t size) {
  if (size < 40) return "flag bits need 40 bytes, got " + std::to_string(size);
  const std::uint8_t* incompat = p + 8;
  bool unknown = (incompat[0] & 0xFE) != 0;
  for (int i = 1; i < 8; ++i) unknown = unknown || incompat[i] != 0;
  if (unknown)  // never safe to read on, lenient or not
    throw std::runtime_error(where(pos, 'B') + "unknown incompatible flag bits set; this reader cannot read the file");
  appended_ = (incompat[0] & 1) != 0;
  if (appended_) {
    for (int i = 0; i < 3; ++i) {
      const std::uint64_t a = readLe<std::uint64_t>(p + 16 + 8 * i);
      if (a) appended_offsets_.push_back(a);
    }
  }
  return {};
}

// A format definition ('F').
std::string Log::readFormat(const std::uint8_t* p, std::size_t size) {
  const std::string def = str(p, size);
  const auto colon = def.find(':');
  if (colon == std::string::npos || colon == 0) return "format definition without 'name:' prefix";
  const std::string name = def.substr(0, colon);
  std::vector<Field> fields;
  std::size_t start = colon + 1;
  while (start < def.size()) {
    auto semi = def.find(';', start);
    if (semi == std::string::npos) semi = def.size();
    const std::string item = trim(def.substr(start, semi - start));
    start = semi + 1;
    if (item.empty()) continue;
    const auto sp = item.find(' ');
    Field f;
    if (sp == std::string::npos || !parseType(item.substr(0, sp), f.type, f.array)) {
      return "format " + name + ": malformed field '" + item + "'";
    }
    f.name = trim(item.substr(sp + 1));
    fields.push_back(f);
  }
  if (fields.empty()) return "format " + name + " has no fields";
  // Resolved layouts only hold names all defined before, so only a redefinition can change one.
  if (formats_.count(name)) resolved_.clear();
  unresolved_.clear();  // the new definition may be what a failed layout lacked
  formats_[name] = fields;
  return {};
}

// Info, multi-info, parameter or default parameter ('I', 'M', 'P', 'Q').
std::string Log::readKeyValue(char type, const std::uint8_t* p, std::size_t size) {
  const std::size_t skip = (type == 'M' || type == 'Q') ? 1 : 0;
  if (size < skip + 1) return "too short for a key";
  const std::size_t key_len = p[skip];
  if (size < skip + 1 + key_len) return "key length " + std::to_string(key_len) + " exceeds the message";
  const std::string key = str(p + skip + 1, key_len);
  const auto sp = key.find(' ');
  if (sp == std::string::npos) return "key '" + key + "' is not 'type name'";
  const std::string vtype = key.substr(0, sp), name = key.substr(sp + 1);
  const std::uint8_t* v = p + skip + 1 + key_len;
  const std::size_t vn = size - skip - 1 - key_len;
  double number = 0.0;
  const std::string value = infoValue(vtype, v, vn, &number);
  if (type == 'I') info_[name] = value;
  else if (type == 'M' && p[0]) info_[name] += value;  // a continuation: appended in place (linear)
  else if (type == 'M') info_[name] = value;
  else if (type == 'P') params_[name] = number;
  if (type == 'Q' && (p[0] & 1)) defaults_[name] = number;                // system-wide default
  if (type == 'Q' && (p[0] & 2)) configuration_defaults_[name] = number;  // airframe default
  return {};
}

// A subscription ('A').
std::string Log::readSubscription(const std::uint8_t* p, std::size_t size) {
  if (size < 4) return "subscription needs at least 4 bytes, got " + std::to_string(size);
  Subscription s;
  s.multi_id = p[0];
  const int msg_id = readLe<std::uint16_t>(p + 1);
  s.name = str(p + 3, size - 3);
  if (!formats_.count(s.name)) return "subscription to " + s.name + ", which no 'F' message defines";
  sub_by_msg_id_[msg_id] = subs_.size();
  subs_.push_back(s);
  return {};
}

// A data message ('D') at `pos`.
std::string Log::readData(std::size_t pos, const std::uint8_t* p, std::size_t size) {
  if (size < 2) return "data message shorter than its msg_id";
  const int msg_id = readLe<std::uint16_t>(p);
  auto it = sub_by_msg_id_.find(msg_id);
  if (it == sub_by_msg_id_.end()) return "data for msg_id " + std::to_string(msg_id) + " without an earlier 'A' subscription";
  Subscription& s = subs_[it->second];
  try {
    const Resolved& r = resolve(s.name);
    if (size - 2 < r.required) {
      return s.name + " data has " + std::to_string(size - 2) + " bytes, its format needs " +
             std::to_string(r.required) + " (" + std::to_string(r.size) + " with padding)";
    }
    if (size - 2 > r.size) {
      return s.name + " data has " + std::to_string(size - 2) + " bytes, more than its format's " + std::to_string(r.size);
    }
  } catch (const std::exception& e) {
    return e.what();
  }
  s.records.emplace_back(pos + 5, size - 2);
  return {};
}

// A logged string ('L' or tagged 'C').
std::string Log::readString(char type, const std::uint8_t* p, std::size_t size) {
  const std::size_t head = type == 'L' ? 9 : 11;
  if (size < head) return "logged string shorter than its " + std::to_string(head) + "-byte header";
  LoggedString ls;
  ls.level = p[0] >= '0' && p[0] <= '7' ? p[0] - '0' : p[0];
  ls.t = static_cast<double>(readLe<std::uint64_t>(p + head - 8)) * 1e-6;
  ls.text = str(p + head, size - head);
  strings_.push_back(ls);
  return {};
}

// Decodes the message of `type` and `size` at `pos` into the log; returns what is wrong with it
// (empty: nothing). Throws for unknown incompatible flag bits, which no mode may read past.
std::string Log::readMessage(std::size_t pos, char type, std::size_t size) {
  const std::uint8_t* p = bytes_.data() + pos + 3;
  switch (type) {
    case 'B': return readFlagBits(pos, p, size);
    case 'F': return readFormat(p, size);
    case 'I': case 'P': case 'M': case 'Q': return readKeyValue(type, p, size);
    case 'A': return readSubscription(p, size);
    case 'D': return readData(pos, p, size);
    case 'L': case 'C': return readString(type, p, size);
    case 'R':
      if (size >= 2) sub_by_msg_id_.erase(readLe<std::uint16_t>(p));
      return {};
    case 'O':
      if (size >= 2) {
        ++dropout_count_;
        dropout_s_ += readLe<std::uint16_t>(p) * 1e-3;
      }
      return {};
    default:
      return {};  // 'S' sync and message types this reader does not know are skipped, per the spec
  }
}

// True when a message that fits the definitions read so far starts at `q`, and (depth 0) the
// message after it does too, or the file ends (or is cut) there.
bool Log::plausibleAt(std::size_t q, int depth) const {
  const std::size_t n = bytes_.size();
  if (depth > 0 && (q >= n || n - q < 3)) return true;
  if (q >= n || n - q < 3) return false;
  const std::size_t size = readLe<std::uint16_t>(bytes_.data() + q);
  const char type = static_cast<char>(bytes_[q + 2]);
  if (size == 0 || !isDataType(type)) return false;
  if (n - q - 3 < size) return depth > 0;  // a cut final message
  if (!plausiblePayload(type, bytes_.data() + q + 3, size)) return false;
  return depth > 0 || plausibleAt(q + 3 + size, depth + 1);
}

bool Log::plausiblePayload(char type, const std::uint8_t* p, std::size_t size) const {
  auto printable = [](const std::uint8_t* s, std::size_t k) {
    return std::all_of(s, s + k, [](std::uint8_t c) { return c >= 32 && c < 127; });
  };
  switch (type) {
    case 'D': {
      if (size < 2) return false;
      const auto it = sub_by_msg_id_.find(readLe<std::uint16_t>(p));
      if (it == sub_by_msg_id_.end()) return false;
      try {
        const Resolved& r = resolve(subs_[it->second].name);
        return size - 2 >= r.required && size - 2 <= r.size;
      } catch (const std::exception&) {
        return false;
      }
    }
    case 'A': return size >= 4 && formats_.count(str(p + 3, size - 3)) > 0;
    case 'F': {
      // The 'name:' prefix comes first: looking only there keeps a resynchronisation scan over
      // printable garbage linear (a whole-payload check at every byte was 18 KB per byte).
      const std::size_t head = std::min(size, kMaxFormatName);
      const void* colon = std::memchr(p, ':', head);
      return colon != nullptr && printable(p, static_cast<const std::uint8_t*>(colon) - p + 1);
    }
    case 'I': case 'P': case 'M': case 'Q': {
      const std::size_t skip = (type == 'M' || type == 'Q') ? 1 : 0;
      if (size < skip + 1) return false;
      const std::size_t k = p[skip];
      return k > 2 && skip + 1 + k <= size && printable(p + skip + 1, k) && str(p + skip + 1, k).find(' ') != std::string::npos;
    }
    case 'S': return size == 8 && std::memcmp(p, kSync, 8) == 0;
    case 'O': case 'R': return size == 2 || size == 3;
    case 'L': return size >= 9;
    case 'C': return size >= 11;
    default: return false;
  }
}

std::size_t Log::resolveInto(const std::string& name, const std::string& prefix, std::size_t base,
                             Resolved& out, int depth) const {
  if (depth > kMaxNesting)
    throw std::runtime_error(source_ + ": format " + name + " nests deeper than " + std::to_string(kMaxNesting) +
                             " levels (recursive definition?)");
  auto it = formats_.find(name);
  if (it == formats_.end()) throw std::runtime_error(source_ + ": no 'F' message defines type " + name);
  std::size_t off = 0;
  for (const Field& f : it->second) {
    const std::size_t count = f.array < 0 ? 1 : static_cast<std::size_t>(f.array);
    const std::size_t s = baseTypeSize(f.type);
    const bool padding = f.name.rfind("_padding", 0) == 0;
    for (std::size_t k = 0; k < count; ++k) {
      const std::string leaf = prefix + f.name + (f.array < 0 ? "" : "[" + std::to_string(k) + "]");
      if (s > 0) {
        if (!padding) {
          out.leaves.push_back({leaf, f.type, base + off});
          out.required = std::max(out.required, base + off + s);
        }
        off += s;
      } else {
        const std::size_t element = resolveInto(f.type, leaf + ".", base + off, out, depth + 1);
        // Every element must take at least one byte, so the work is bounded by the 65535-byte size.
        if (element == 0)
          throw std::runtime_error(source_ + ": format " + name + " field " + f.name + ": type " + f.type +
                                   " takes 0 bytes (only zero-size fields); a nested type needs at least 1 byte");
        off += element;
      }
      if (base + off > kMaxFormatSize)
        throw std::runtime_error(source_ + ": format " + name + " is larger than a ULog message can be (" +
                                 std::to_string(kMaxFormatSize) + " bytes)");
    }
  }
  return off;
}

const Log::Resolved& Log::resolve(const std::string& name) const {
  auto it = resolved_.find(name);
  if (it != resolved_.end()) return it->second;
  // A failure is remembered too: lenient resynchronisation may ask for the same layout at every byte.
  auto failed = unresolved_.find(name);
  if (failed != unresolved_.end()) throw std::runtime_error(failed->second);
  Resolved r;
  try {
    r.size = resolveInto(name, "", 0, r, 0);
  } catch (const std::exception& e) {
    unresolved_[name] = e.what();
    throw;
  }
  return resolved_.emplace(name, std::move(r)).first->second;
}

const Log::Subscription* Log::find(const std::string& name, int multi_id) const {
  for (const auto& s : subs_)
    if (s.name == name && s.multi_id == multi_id && !s.records.empty()) return &s;
  for (const auto& s : subs_)
    if (s.name == name && s.multi_id == multi_id) return &s;
  return nullptr;
}

std::vector<int> Log::instances(const std::string& name) const {
  std::vector<int> out;
  for (const auto& s : subs_)
    if (s.name == name && !s.records.empty() && std::find(out.begin(), out.end(), s.multi_id) == out.end())
      out.push_back(s.multi_id);
  std::sort(out.begin(), out.end());
  return out;
}

std::size_t Log::count(const std::string& name, int multi_id) const {
  std::size_t c = 0;
  for (const auto& s : subs_)
    if (s.name == name && s.multi_id == multi_id) c += s.records.size();
  return c;
}

bool Log::hasField(const std::string& name, const std::string& field) const {
  if (!formats_.count(name)) return false;
  try {
    const auto& l = resolve(name).leaves;
    return std::any_of(l.begin(), l.end(), [&](const Leaf& x) { return x.name == field; });
  } catch (const std::exception&) {
    return false;
  }
}

const std::vector<Leaf>& Log::leaves(const std::string& name) const { return resolve(name).leaves; }

std::vector<double> Log::column(const std::string& name, int multi_id, const std::string& field) const {
  const auto& l = resolve(name).leaves;
  auto leaf = std::find_if(l.begin(), l.end(), [&](const Leaf& x) { return x.name == field; });
  if (leaf == l.end()) throw std::runtime_error(source_ + ": topic " + name + " has no field " + field);
  const std::size_t s = baseTypeSize(leaf->type);
  std::vector<double> out;
  for (const auto& sub : subs_) {
    if (sub.name != name || sub.multi_id != multi_id) continue;
    for (const auto& [off, size] : sub.records)
      out.push_back(leaf->offset + s <= size ? decodeBase(leaf->type, bytes_.data() + off + leaf->offset) : 0.0);
  }
  return out;
}

std::vector<double> Log::times(const std::string& name, int multi_id) const {
  auto t = column(name, multi_id, "timestamp");
  for (double& x : t) x *= 1e-6;
  return t;
}

}  // namespace wattswath::logs::ulog
