#pragma once
// Helpers shared by the mission readers, checks and writers (not installed).
#include <string>

#include "wattswath/geometry/frame.hpp"
#include "wattswath/mission/files.hpp"

namespace wattswath::mission::detail {

/// Throws MissionError "WHERE: WHAT".
[[noreturn]] void fail(const std::string& where, const std::string& what);

/// Shortest text that reads back to the same double ("nan", "inf", "-inf" for the non-finite).
std::string numberText(double v);

/// Throws MissionError "WHERE: home latitude = ..., expected ..." unless lat/lon are in range and
/// all three are finite.
void checkHomePoint(const geometry::GeoPoint& p, const std::string& where);

/// `text` without a leading UTF-8 byte order mark.
std::string withoutBom(const std::string& text);

/// Throws MissionError naming `source` when `text` is not 8-bit text: UTF-16 or UTF-32 (by its
/// byte order mark or its NUL bytes) or holding a NUL byte (named by line and column).
void checkText(const std::string& text, const std::string& source);

/// `s` for a message: control bytes as \xNN, at most `most` bytes shown ("..." after).
std::string printable(const std::string& s, std::size_t most = 60);

}  // namespace wattswath::mission::detail
