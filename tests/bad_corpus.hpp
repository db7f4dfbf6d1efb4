#pragma once
// The malformed-input corpus tests/data/bad/ and its expectation tables: EXPECTED.tsv (inputs the
// CLI reads, checked by test_bad_inputs) and LIBRARY_EXPECTED.tsv (inputs only a library reads so
// far, checked by that library's tests). Row: file<TAB>command or reader<TAB>substrings separated by |.
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include "test_util.hpp"

namespace wattswath::test {

/// One row of an expectation table: the input, what reads it, what the error must contain.
struct Case {
  std::string file;                     ///< file name under tests/data/bad/
  std::string command;                  ///< wattswath arguments ({} = the file's path), or a reader's name
  std::vector<std::string> substrings;  ///< each must appear in the error
  int line = 0;                         ///< line of the table (for messages)
};

/// Prints a case as its file and table line (instead of gtest's byte dump).
inline void PrintTo(const Case& c, std::ostream* os) { *os << c.file << " (line " << c.line << ")"; }

/// `s` cut at every `sep`.
inline std::vector<std::string> split(const std::string& s, const std::string& sep) {
  std::vector<std::string> out;
  size_t pos = 0;
  while (true) {
    const size_t at = s.find(sep, pos);
    out.push_back(s.substr(pos, at == std::string::npos ? std::string::npos : at - pos));
    if (at == std::string::npos) break;
    pos = at + sep.size();
  }
  return out;
}

/// `s` without leading and trailing blanks.
inline std::string trimmed(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

/// The rows of tests/data/bad/`table` (blank and '#' lines skipped).
inline std::vector<Case> loadCases(const std::string& table = "EXPECTED.tsv") {
  std::vector<Case> out;
  std::ifstream in(sourcePath("tests/data/bad/" + table));
  std::string line;
  int ln = 0;
  while (std::getline(in, line)) {
    ++ln;
    if (trimmed(line).empty() || line[0] == '#') continue;
    const auto cols = split(line, "\t");
    Case c;
    c.line = ln;
    c.file = cols.size() > 0 ? trimmed(cols[0]) : "";
    c.command = cols.size() > 1 ? trimmed(cols[1]) : "";
    if (cols.size() > 2)
      for (const auto& s : split(cols[2], "|"))
        if (!trimmed(s).empty()) c.substrings.push_back(trimmed(s));
    out.push_back(c);
  }
  return out;
}

}  // namespace wattswath::test
