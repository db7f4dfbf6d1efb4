#pragma once
// Shared body of the reader fuzz targets: run `read` strict and lenient on the input; any
// std::exception is an accepted outcome, anything else (crash, sanitizer report) is a finding.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <vector>

#include "wattswath/logs/autopilot_log.hpp"

template <typename Reader>
int fuzzReader(const std::uint8_t* data, std::size_t size, Reader read) {
  for (bool lenient : {false, true}) {
    wattswath::logs::LogReadOptions o;
    o.lenient = lenient;
    try {
      read(std::vector<std::uint8_t>(data, data + size), o);
    } catch (const std::exception&) {
    }
  }
  return 0;
}
