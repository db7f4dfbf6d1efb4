#pragma once
/// @file reproduce.hpp
/// `wattswath reproduce`: paper numbers side by side with ours. Each paper (or case) is one
/// section in its own apps/reproduce_*.cpp that registers itself; cmd_reproduce.cpp runs them, merges their
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

/// `x` rounded for a report: no decimals from 1,000 up (with thousands separators), else
/// `digits` significant digits.
std::string reproNumber(double x, int digits = 4);

/// A Markdown table "| Quantity | Paper | Ours | Diff | Note |" of reproRow() rows; rows whose
/// |diff| exceeds 1 % without a note get "unexplained" so that none goes unremarked.
std::string reproMarkdownTable(const nlohmann::json& rows);

/// A section producer.
using ReproFn = ReproSection (*)(const ReproContext&);

/// Registers a section from a static initializer in its reproduce_*.cpp (sections run by `order`):
///   static const bool kRegistered = registerReproSection(10, "marins", &reproduceMarins);
/// Orders in use: 10 Marins closed form, 20 spiral case (Marins Table III/IV), 30 Hwang, 40 peers.
bool registerReproSection(int order, const std::string& name, ReproFn fn);

/// Runs every registered section in order and merges their JSON and Markdown.
ReproSection runAllReproSections(const ReproContext& ctx);

}  // namespace wattswath::apps
