#pragma once
/// @file ulog.hpp
/// Low-level reader of PX4 ULog files (.ulg), following the PX4 "ULog File Format" specification:
/// a 16-byte header (magic `ULog` 0x01 0x12 0x35, version, start time), a definitions section
/// (flag bits 'B', formats 'F', info 'I', multi-info 'M', parameters 'P', default parameters 'Q')
/// and a data section (subscriptions 'A', data 'D', logged strings 'L'/'C', sync 'S', dropouts 'O',
/// unsubscriptions 'R', and parameter changes). Topics and fields are resolved by name from the
/// 'F' definitions, never by fixed offsets; nested types and arrays are flattened to names like
/// `esc_report[2].esc_rpm` and `voltage_cell_v[3]`.

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace wattswath::logs::ulog {

/// One flattened scalar field of a topic.
struct Leaf {
  std::string name;     ///< flattened name, e.g. "voltage_v" or "esc_report[0].esc_rpm"
  std::string type;     ///< ULog base type, e.g. "float", "uint8_t", "char"
  std::size_t offset;   ///< [B] offset in the data payload (after the 2-byte msg_id)
};

/// One logged string ('L' or tagged 'C' message).
struct LoggedString {
  double t = 0.0;       ///< [s] boot time
  int level = 0;        ///< syslog level as logged ('0'..'7' as a number)
  std::string text;     ///< the message
};

/// A stretch of a ULog file the lenient reader skipped (zero-filled, corrupt or cut off).
struct Gap {
  std::size_t offset = 0;  ///< [B] byte offset of the first byte skipped
  std::size_t length = 0;  ///< [B] bytes skipped (to the next valid message, or to the end of the file)
  bool to_end = false;     ///< true when no valid message follows: the rest of the file is not read
  std::string reason;      ///< what was found at `offset`
};

/// A whole ULog file, parsed once; topic columns are decoded on demand.
class Log {
 public:
  /// Parses `bytes` (the whole file). `source` names the file in messages. With `lenient` false
  /// any malformed or truncated message throws std::runtime_error naming the byte offset and the
  /// message type (and --lenient); with `lenient` true a bad message is skipped: with appended
  /// data to the next appended offset, else, as pyulog does, to the next byte offset where a
  /// valid message header starts (its type, size and payload consistent with the definitions,
  /// and the message after it too), each skip recorded in gaps() and warnings().
  static Log parse(std::vector<std::uint8_t> bytes, const std::string& source, bool lenient);

  /// [us] start time from the file header.
  std::uint64_t startTimeUs() const { return start_us_; }
  /// ULog file format version from the header.
  int version() const { return version_; }
  /// True when the flag bits declare appended data (ULOG_INCOMPAT_FLAG0_DATA_APPENDED).
  bool appendedData() const { return appended_; }
  /// Info ('I') and multi-info ('M', concatenated) values by key, numbers printed in decimal.
  const std::map<std::string, std::string>& info() const { return info_; }
  /// Parameters ('P'; later values replace earlier ones) by name.
  const std::map<std::string, double>& parameters() const { return params_; }
  /// System-wide default parameter values ('Q' with default_types bit 0) by name; PX4 logs them
  /// only for parameters whose value differs from the default.
  const std::map<std::string, double>& defaultParameters() const { return defaults_; }
  /// Defaults for the current airframe configuration ('Q' with default_types bit 1) by name.
  const std::map<std::string, double>& configurationDefaults() const { return configuration_defaults_; }
  /// Logged strings in file order.
  const std::vector<LoggedString>& strings() const { return strings_; }
  /// Number of dropout ('O') messages and their total duration [s].
  std::pair<int, double> dropouts() const { return {dropout_count_, dropout_s_}; }
  /// Problems skipped in lenient mode, each naming the byte offset.
  const std::vector<std::string>& warnings() const { return warnings_; }
  /// Stretches skipped in lenient mode, in file order.
  const std::vector<Gap>& gaps() const { return gaps_; }

  /// Instances (multi_id) of topic `name` with at least one data message, ascending.
  std::vector<int> instances(const std::string& name) const;
  /// Number of data messages of `name` instance `multi_id`.
  std::size_t count(const std::string& name, int multi_id) const;
  /// True when topic `name` defines field `field` (flattened name).
  bool hasField(const std::string& name, const std::string& field) const;
  /// Flattened scalar fields of topic format `name` (throws if undefined or malformed).
  const std::vector<Leaf>& leaves(const std::string& name) const;
  /// Values of `field` for every data message of `name` instance `multi_id`, as doubles. Bytes
  /// missing from a shorter payload (trailing `_padding` dropped by the logger) read as 0.
  std::vector<double> column(const std::string& name, int multi_id, const std::string& field) const;
  /// [s] `timestamp` / 1e6 of every data message of `name` instance `multi_id`.
  std::vector<double> times(const std::string& name, int multi_id) const;
  /// Name of the file the log was read from.
  const std::string& source() const { return source_; }

 private:
  struct Field {
    std::string type;  // base type or nested format name
    int array = -1;    // -1 scalar, else element count
    std::string name;
  };
  struct Resolved {
    std::vector<Leaf> leaves;
    std::size_t size = 0;      // declared size
    std::size_t required = 0;  // end of the last non-padding field
  };
  struct Subscription {
    std::string name;
    int multi_id = 0;
    std::vector<std::pair<std::size_t, std::size_t>> records;  // payload offset, payload size
  };

  std::size_t step(std::size_t pos, bool lenient);
  std::string readMessage(std::size_t pos, char type, std::size_t size);
  std::string readFlagBits(std::size_t pos, const std::uint8_t* p, std::size_t size);
  std::string readFormat(const std::uint8_t* p, std::size_t size);
  std::string readKeyValue(char type, const std::uint8_t* p, std::size_t size);
  std::string readSubscription(const std::uint8_t* p, std::size_t size);
  std::string readData(std::size_t pos, const std::uint8_t* p, std::size_t size);
  std::string readString(char type, const std::uint8_t* p, std::size_t size);
  std::size_t bad(std::size_t at, char type, const std::string& what, bool lenient, bool resync);
  std::string where(std::size_t at, char type) const;
  bool plausibleAt(std::size_t q, int depth) const;
  bool plausiblePayload(char type, const std::uint8_t* p, std::size_t size) const;
  const Resolved& resolve(const std::string& name) const;
  std::size_t resolveInto(const std::string& name, const std::string& prefix, std::size_t base,
                          Resolved& out, int depth) const;
  const Subscription* find(const std::string& name, int multi_id) const;

  std::string source_;
  std::vector<std::uint8_t> bytes_;
  std::uint64_t start_us_ = 0;
  int version_ = 0;
  bool appended_ = false;
  std::map<std::string, std::vector<Field>> formats_;
  mutable std::map<std::string, Resolved> resolved_;
  mutable std::map<std::string, std::string> unresolved_;  // names whose layout failed: why (until the next 'F')
  std::map<std::string, std::string> info_;
  std::map<std::string, double> params_;
  std::map<std::string, double> defaults_;
  std::map<std::string, double> configuration_defaults_;
  std::vector<LoggedString> strings_;
  std::vector<Subscription> subs_;
  int dropout_count_ = 0;
  double dropout_s_ = 0.0;
  std::vector<std::string> warnings_;
  std::vector<Gap> gaps_;
  std::vector<std::uint64_t> appended_offsets_;   // parse state: appended-data offsets
  std::map<int, std::size_t> sub_by_msg_id_;      // parse state: msg_id -> index in subs_
};

/// Size in bytes of ULog base type `type`, or 0 when it is not a base type (a nested format).
std::size_t baseTypeSize(const std::string& type);

}  // namespace wattswath::logs::ulog
