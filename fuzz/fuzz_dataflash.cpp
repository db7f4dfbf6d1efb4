// libFuzzer target: the ArduPilot DataFlash reader on arbitrary bytes, strict and lenient.
#include "fuzz_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fuzzReader(data, size, [](std::vector<std::uint8_t> b, const wattswath::energy::LogReadOptions& o) {
    return wattswath::energy::readDataFlashBytes(std::move(b), "fuzz.bin", o);
  });
}
