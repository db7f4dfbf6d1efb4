#pragma once
// Builders of small DataFlash and ULog files byte by byte, for the logs library's tests.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace wattswath::test::logbytes {

/// A file's bytes.
using Bytes = std::vector<std::uint8_t>;

/// Appends `v` little-endian (the tests run on little-endian machines).
template <typename T>
void put(Bytes& b, T v) {
  std::uint8_t raw[sizeof(T)];
  std::memcpy(raw, &v, sizeof(T));
  for (std::uint8_t x : raw) b.push_back(x);  // (insert() trips GCC 12's bogus -Wnonnull)
}
/// Appends `s` as a NUL-padded field of `n` bytes.
inline void putText(Bytes& b, const std::string& s, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) b.push_back(k < s.size() ? static_cast<std::uint8_t>(s[k]) : 0);
}

// ------------------------------------------------------------ DataFlash builder
/// A DataFlash file under construction: FMT records, then message headers and payloads.
struct DataFlash {
  Bytes b;  ///< the file so far
  /// Starts with the FMT record of FMT itself, naming its columns `fmt_columns` (ArduCopter <= 3.1
  /// wrote "Type,Length,Name,Format": 4 names for 5 format characters).
  explicit DataFlash(const std::string& fmt_columns = "Type,Length,Name,Format,Columns") {
    fmt(128, 89, "FMT", "BBnNZ", fmt_columns);
  }
  /// Appends an FMT record defining message `name`; `len` [B] includes the 3 header bytes.
  void fmt(std::uint8_t type, std::uint8_t len, const std::string& name, const std::string& format, const std::string& cols) {
    b.insert(b.end(), {0xA3, 0x95, 128, type, len});
    putText(b, name, 4);
    putText(b, format, 16);
    putText(b, cols, 64);
  }
  /// Appends the 3 header bytes of a message of `type`; the caller appends the payload.
  void head(std::uint8_t type) { b.insert(b.end(), {0xA3, 0x95, type}); }
};

// ------------------------------------------------------------ ULog builder
/// A ULog file under construction: header, flag bits, then messages.
struct ULog {
  Bytes b;  ///< the file so far
  /// Header and flag bits; `appended_flag` declares appended data at byte `appended_at`.
  explicit ULog(bool appended_flag = false, std::uint64_t appended_at = 0) {
    b = {'U', 'L', 'o', 'g', 0x01, 0x12, 0x35, 1};
    put<std::uint64_t>(b, 1000);
    Bytes flags(40, 0);
    if (appended_flag) {
      flags[8] = 1;
      std::memcpy(flags.data() + 16, &appended_at, 8);
    }
    msg('B', flags);
  }
  /// Appends a message of `type` with `payload`.
  void msg(char type, const Bytes& payload) {
    put<std::uint16_t>(b, static_cast<std::uint16_t>(payload.size()));
    b.push_back(static_cast<std::uint8_t>(type));
    b.insert(b.end(), payload.begin(), payload.end());
  }
  /// Appends a message of `type` whose payload is the text `s`.
  void text(char type, const std::string& s) { msg(type, Bytes(s.begin(), s.end())); }
  /// Appends an 'A' subscription of topic `name` instance `multi` as msg_id `id`.
  void subscribe(std::uint8_t multi, std::uint16_t id, const std::string& name) {
    Bytes p{multi};
    put<std::uint16_t>(p, id);
    p.insert(p.end(), name.begin(), name.end());
    msg('A', p);
  }
  /// Appends a 'D' data message for msg_id `id`.
  void data(std::uint16_t id, const Bytes& fields) {
    Bytes p;
    put<std::uint16_t>(p, id);
    p.insert(p.end(), fields.begin(), fields.end());
    msg('D', p);
  }
  /// [B] Position of the first appended-data offset in the flag bits message.
  std::size_t appendedOffsetPos() const { return 16 + 3 + 16; }
};

}  // namespace wattswath::test::logbytes
