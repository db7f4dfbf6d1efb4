#pragma once
// Private helpers of the binary log readers: whole-file reads, little-endian reads from a byte buffer.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "wattswath/logs/tolerances.hpp"

namespace wattswath::logs::binary {

/// Reads a little-endian value of type T at `p` (the caller checks the bounds).
template <typename T>
T readLe(const std::uint8_t* p) {
  static_assert(std::is_trivially_copyable<T>::value, "readLe needs a plain type");
  std::uint8_t buf[sizeof(T)];
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
  for (std::size_t i = 0; i < sizeof(T); ++i) buf[i] = p[sizeof(T) - 1 - i];
#else
  std::memcpy(buf, p, sizeof(T));
#endif
  T v;
  std::memcpy(&v, buf, sizeof(T));
  return v;
}

/// The message for a log file over the limit `max_bytes` [B]: `size` [B] is its size, or 0 for a
/// pipe or device read until it passed the limit.
inline std::string tooLargeMessage(const std::string& path, unsigned long long size, long long max_bytes) {
  const auto mib = [](unsigned long long b) { return std::to_string((b + (1ULL << 20) - 1) >> 20); };
  const auto limit = static_cast<unsigned long long>(max_bytes);
  return path + (size > 0 ? ": the file is " + std::to_string(size) + " bytes (" + mib(size) + " MiB)"
                          : ": more than " + std::to_string(limit) + " bytes") +
         "; flight logs are read whole, at most " + mib(limit) + " MiB (memory is about 2-3x the file); " +
         "--max-log-size MIB raises the limit, or cut the log first";
}

/// The whole file at `path` as `Bytes` (std::string or std::vector<std::uint8_t>), refused before
/// reading when larger than `max_bytes` [B] (pipes and devices: as soon as they pass it); throws
/// std::runtime_error naming the file.
template <typename Bytes>
Bytes readWholeFile(const std::string& path, long long max_bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  Bytes out;
  std::error_code ec;
  const bool regular = std::filesystem::is_regular_file(path, ec);
  const auto size = regular ? std::filesystem::file_size(path, ec) : 0;
  if (regular && !ec) {
    if (size > static_cast<unsigned long long>(max_bytes)) throw std::runtime_error(tooLargeMessage(path, size, max_bytes));
    out.resize(static_cast<std::size_t>(size));
    in.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(size));
    out.resize(static_cast<std::size_t>(in.gcount()));
    return out;
  }
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    const auto n = static_cast<std::size_t>(in.gcount());
    if (out.size() + n > static_cast<unsigned long long>(max_bytes)) {
      throw std::runtime_error(tooLargeMessage(path, 0, max_bytes));
    }
    out.insert(out.end(), buf, buf + n);
  }
  return out;
}

/// The bytes of the file at `path` (at most `max_bytes` [B]); throws std::runtime_error naming it
/// when it cannot be opened or is larger.
inline std::vector<std::uint8_t> readFileBytes(const std::string& path, long long max_bytes = tol::kLogMaxFileBytes) {
  return readWholeFile<std::vector<std::uint8_t>>(path, max_bytes);
}

}  // namespace wattswath::logs::binary
