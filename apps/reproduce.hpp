#pragma once
/// @file reproduce.hpp
/// `wattswath reproduce`: paper numbers side by side with ours. Each paper (or case) is one
/// section in its own apps/reproduce_*.cpp; cmd_reproduce.cpp runs them in order, merges their
/// JSON objects into one (top-level keys are a contract, e.g. `hwang_table3`, `spiral_case`) and
/// concatenates their Markdown into docs/reproduction.md.

#include <string>

#include <nlohmann/json.hpp>

namespace wattswath::apps {

/// Where a reproduction section finds its inputs.
struct ReproContext {
  std::string source_dir;   ///< the wattswath checkout (for data/vehicles/...)
  std::string shared_data;  ///< ../shared/data (may be absent: sections then say so)
};

/// One section of the reproduction report.
struct ReproSection {
  nlohmann::json json = nlohmann::json::object();  ///< merged into the top-level --json object
  std::string markdown;                            ///< a Markdown section starting with "## "
};

/// One row of a paper-vs-ours table: the paper's value, ours, the difference in percent.
nlohmann::json reproRow(const std::string& quantity, double paper, double ours, const std::string& unit,
                        const std::string& note = "");

/// Marins, Cabreira & Ferreira closed-form model: P0, P_hov, Fig. 3, Strategy 1/2, Table V.
ReproSection reproduceMarins(const ReproContext& ctx);

}  // namespace wattswath::apps
