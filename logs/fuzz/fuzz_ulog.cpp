// libFuzzer target: the PX4 ULog reader on arbitrary bytes, strict and lenient.
#include "fuzz_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fuzzReader(data, size, [](std::vector<std::uint8_t> b, const wattswath::logs::LogReadOptions& o) {
    return wattswath::logs::readUlogBytes(std::move(b), "fuzz.ulg", o);
  });
}
