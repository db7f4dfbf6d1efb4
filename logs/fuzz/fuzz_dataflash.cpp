// libFuzzer target: the ArduPilot DataFlash reader on arbitrary bytes, strict and lenient.
#include "fuzz_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return fuzzReader(data, size, [](std::vector<std::uint8_t> b, const wattswath::logs::LogReadOptions& o) {
    return wattswath::logs::readDataFlashBytes(std::move(b), "fuzz.bin", o);
  });
}
