#pragma once
// Private helpers of the binary log readers: whole-file reads, little-endian reads from a byte buffer.
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

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

/// The bytes of the file at `path`; throws std::runtime_error naming it when it cannot be opened.
inline std::vector<std::uint8_t> readFileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace wattswath::logs::binary
