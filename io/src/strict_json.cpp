#include "wattswath/io/strict_json.hpp"

#include <string>
#include <unordered_set>
#include <vector>

namespace wattswath::io {
namespace {

template <class Json>
Json parseStrict(const std::string& text, int max_depth) {
  std::vector<std::unordered_set<std::string>> keys;  // the keys of each open object
  const typename Json::parser_callback_t check = [&](int depth, typename Json::parse_event_t event, Json& parsed) {
    if (depth > max_depth) throw JsonError(JsonProblem::too_deep, "JSON nested more than " + std::to_string(max_depth) + " levels deep");
    if (event == Json::parse_event_t::object_start) keys.emplace_back();
    if (event == Json::parse_event_t::object_end && !keys.empty()) keys.pop_back();
    if (event == Json::parse_event_t::key && !keys.empty() && parsed.is_string()) {
      const auto& k = parsed.template get_ref<const std::string&>();
      if (!keys.back().insert(k).second) throw JsonError(JsonProblem::duplicate_key, "key \"" + k + "\" appears twice in one JSON object", k);
    }
    return true;
  };
  try {
    return Json::parse(text, check);
  } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for a number like 1e999
    throw JsonError(JsonProblem::invalid, std::string("not valid JSON: ") + e.what());
  }
}

}  // namespace

nlohmann::json parseStrictJson(const std::string& text, int max_depth) {
  return parseStrict<nlohmann::json>(text, max_depth);
}

nlohmann::ordered_json parseStrictOrderedJson(const std::string& text, int max_depth) {
  return parseStrict<nlohmann::ordered_json>(text, max_depth);
}

}  // namespace wattswath::io
