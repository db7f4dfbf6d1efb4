#pragma once
// Private helpers of the binary log readers: little-endian reads from a byte buffer.
#include <cstdint>
#include <cstring>
#include <type_traits>

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

}  // namespace wattswath::logs::binary
