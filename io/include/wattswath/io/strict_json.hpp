#pragma once
/// \file
/// JSON parsed strictly: nesting bounded while parsing (deep input would overflow the stack in
/// recursive readers and in dump()) and a key given twice in one object refused (JSON readers
/// disagree on which one counts, so the value would be a guess).

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <utility>

namespace wattswath::io {

/// What strict parsing refused.
enum class JsonProblem {
  invalid,        ///< not JSON, or a number out of range
  too_deep,       ///< nested deeper than allowed
  duplicate_key,  ///< a key given twice in one object
};

/// Why strict parsing refused a text; what() says why, without the file's name (the caller adds it).
class JsonError : public std::runtime_error {
 public:
  /// A refusal of kind `problem`; `key` is the repeated key (duplicate_key only).
  JsonError(JsonProblem problem, const std::string& message, std::string key = "")
      : std::runtime_error(message), problem_(problem), key_(std::move(key)) {}
  /// What was refused.
  JsonProblem problem() const { return problem_; }
  /// The key given twice (duplicate_key), else empty.
  const std::string& key() const { return key_; }

 private:
  JsonProblem problem_;
  std::string key_;
};

/// Parses `text` as JSON with at most `max_depth` levels of nesting and each key at most once per
/// object; throws JsonError: "JSON nested more than N levels deep", "key \"K\" appears twice in one
/// JSON object" or "not valid JSON: <the parser's message>".
nlohmann::json parseStrictJson(const std::string& text, int max_depth);

/// parseStrictJson keeping the objects' key order (for files that are rewritten for the user).
nlohmann::ordered_json parseStrictOrderedJson(const std::string& text, int max_depth);

}  // namespace wattswath::io
