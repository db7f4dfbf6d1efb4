#pragma once
/// @file dataflash.hpp
/// Low-level reader of ArduPilot DataFlash binary logs (.bin). The format is self-describing:
/// every message is `0xA3 0x95 <type id> <payload>` (little-endian) and FMT messages (type 128)
/// define each type's name, total length, format characters and column labels. Messages are
/// looked up by NAME and column label only; type ids are taken from the file's FMT records.
/// ../shared/data/autopilot-logs/README.md lists the format characters and the per-version units.

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace wattswath::logs::dataflash {

/// One FMT record: how to decode a message type.
struct Format {
  int type = 0;                      ///< [-] message type id (third header byte)
  int length = 0;                    ///< [B] total message length including the 3 header bytes
  std::string name;                  ///< message name, e.g. "CURR" (up to 4 characters)
  std::string format;                ///< one format character per column, e.g. "QfffcHH"
  std::vector<std::string> columns;  ///< column labels, e.g. {"TimeUS", "Volt", ...}
  std::vector<int> offsets;          ///< [B] offset of each column in the payload
  bool decodable = false;            ///< false when a format character is unknown or sizes disagree
  std::string problem;               ///< why the type is not decodable (empty when it is)
};

/// A whole DataFlash file, parsed once; columns are decoded on demand.
class Log {
 public:
  /// Parses `bytes` (the whole file). `source` names the file in messages. With `lenient`
  /// false any framing error (bad header bytes, undefined type id, a message cut off by the end
  /// of the file) throws std::runtime_error naming the byte offset; with `lenient` true the
  /// reader skips to the next header and records each skip in warnings().
  static Log parse(std::vector<std::uint8_t> bytes, const std::string& source, bool lenient);
  /// As parse(), but a record cut off by the end of the file (ArduPilot's logger leaves one in every
  /// log it stops; pymavlink reads such logs) is accepted without `lenient` and kept in warnings();
  /// any other framing error throws, naming the byte offset and the `--lenient` option.
  static Log parseAcceptingCutEnd(std::vector<std::uint8_t> bytes, const std::string& source, bool lenient);

  /// The format of message `name`, or nullptr when the file defines none.
  const Format* format(const std::string& name) const;
  /// Number of messages of type `name` in the file (0 when undefined).
  std::size_t count(const std::string& name) const;
  /// Names of all message types with at least one message, sorted.
  std::vector<std::string> presentMessages() const;
  /// True when message `name` exists with at least one record and has column `column`.
  bool has(const std::string& name, const std::string& column) const;
  /// Format character of `column` in message `name` (0 when absent).
  char columnType(const std::string& name, const std::string& column) const;
  /// Numeric values of `column` for every `name` message, in file order, scaled by the format
  /// character (c, C, e, E: x0.01; L: x1e-7 deg). Throws naming the message and column when the
  /// message or column does not exist, is not decodable or is a text column.
  std::vector<double> column(const std::string& name, const std::string& column) const;
  /// Text values (format characters n, N, Z) of `column`, trailing NULs removed.
  std::vector<std::string> textColumn(const std::string& name, const std::string& column) const;
  /// [s] Boot time of every `name` message: TimeUS / 1e6 if present, else GPS.T / 1e3 (ArduPilot
  /// <= 3.3 GPS, whose TimeMS is GPS time of week), else TimeMS / 1e3. Throws when none exists.
  std::vector<double> times(const std::string& name) const;
  /// True when `name` messages carry a boot timestamp (see times()).
  bool hasTime(const std::string& name) const;
  /// Byte offset of the i-th `name` message (for messages naming a record).
  std::size_t offsetOf(const std::string& name, std::size_t i) const;
  /// Problems skipped in lenient mode, each naming the byte offset.
  const std::vector<std::string>& warnings() const { return warnings_; }
  /// True when, in lenient mode, the file ended inside a message (the cut final record ArduPilot's
  /// logger leaves when it stops); the cut is also listed in warnings().
  bool endsInCutMessage() const { return cut_end_; }
  /// Total number of messages decoded.
  std::size_t messageCount() const { return message_count_; }
  /// Name of the file the log was read from.
  const std::string& source() const { return source_; }

 private:
  const Format& require(const std::string& name, const std::string& column, int* index) const;
  /// "SOURCE: byte offset OFF: ", the start of a message about the bytes at `off`.
  std::string at(std::size_t off) const;
  /// Takes the format an FMT message at byte `pos` defines; one that is malformed, or that would
  /// redefine a type after messages of it were read, throws (or, `lenient`, is ignored with a warning).
  void define(const Format& f, std::size_t pos, bool lenient);

  std::string source_;
  std::vector<std::uint8_t> bytes_;
  std::map<int, Format> formats_;                      // by type id
  std::map<std::string, int> type_by_name_;            // name -> type id
  std::map<int, std::vector<std::size_t>> records_;    // type id -> payload offsets
  std::vector<std::string> warnings_;
  std::string first_problem_;  // the first damaged record, without what lenient reading did about it
  std::size_t message_count_ = 0;
  bool cut_end_ = false;
};

/// Size in bytes of format character `c`, or 0 when it is not a DataFlash format character.
int formatCharSize(char c);

}  // namespace wattswath::logs::dataflash
