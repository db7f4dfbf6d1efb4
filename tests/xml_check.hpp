#pragma once
// A strict little XML well-formedness checker for the report tests: balanced tags, quoted
// attributes, valid entities, no duplicate attributes, no "nan"/"inf" in numeric attributes.
#include <cctype>
#include <set>
#include <string>
#include <vector>

namespace wattswath::test {

/// Returns "" when `xml` is well formed, else a description of the first problem.
inline std::string xmlProblem(const std::string& xml) {
  std::vector<std::string> stack;
  std::size_t i = 0, roots = 0;
  auto entityOk = [&](std::size_t p) {
    const std::size_t e = xml.find(';', p);
    if (e == std::string::npos || e - p > 10) return false;
    const std::string name = xml.substr(p + 1, e - p - 1);
    if (name == "amp" || name == "lt" || name == "gt" || name == "quot" || name == "apos") return true;
    if (name.size() > 1 && name[0] == '#') {
      for (std::size_t k = 1; k < name.size(); ++k) {
        if (!std::isxdigit(static_cast<unsigned char>(name[k])) && !(k == 1 && name[k] == 'x')) return false;
      }
      return true;
    }
    return false;
  };
  auto isName = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == ':' || c == '.'; };
  while (i < xml.size()) {
    const char c = xml[i];
    if (c == '&') {
      if (!entityOk(i)) return "bad entity at " + std::to_string(i);
      ++i;
    } else if (c == '>') {
      return "stray '>' in text at " + std::to_string(i);
    } else if (c != '<') {
      ++i;
    } else if (xml.compare(i, 2, "<?") == 0) {
      const auto e = xml.find("?>", i);
      if (e == std::string::npos) return "unterminated <?";
      i = e + 2;
    } else if (xml.compare(i, 4, "<!--") == 0) {
      const auto e = xml.find("-->", i);
      if (e == std::string::npos) return "unterminated comment";
      i = e + 3;
    } else if (xml.compare(i, 2, "</") == 0) {
      std::size_t j = i + 2;
      while (j < xml.size() && isName(xml[j])) ++j;
      const std::string name = xml.substr(i + 2, j - i - 2);
      if (j >= xml.size() || xml[j] != '>') return "bad closing tag </" + name + " at " + std::to_string(i);
      if (stack.empty() || stack.back() != name) return "closing </" + name + "> does not match <" + (stack.empty() ? "" : stack.back()) + ">";
      stack.pop_back();
      i = j + 1;
    } else {
      std::size_t j = i + 1;
      while (j < xml.size() && isName(xml[j])) ++j;
      const std::string name = xml.substr(i + 1, j - i - 1);
      if (name.empty()) return "empty tag name at " + std::to_string(i);
      std::set<std::string> attrs;
      for (;;) {
        while (j < xml.size() && std::isspace(static_cast<unsigned char>(xml[j]))) ++j;
        if (j >= xml.size()) return "unterminated tag <" + name;
        if (xml[j] == '>' || xml.compare(j, 2, "/>") == 0) break;
        const std::size_t a = j;
        while (j < xml.size() && isName(xml[j])) ++j;
        const std::string attr = xml.substr(a, j - a);
        if (attr.empty() || j + 1 >= xml.size() || xml[j] != '=' || xml[j + 1] != '"') return "bad attribute in <" + name + "> at " + std::to_string(a);
        if (!attrs.insert(attr).second) return "duplicate attribute " + attr + " in <" + name + ">";
        const std::size_t v0 = j + 2, v1 = xml.find('"', v0);
        if (v1 == std::string::npos) return "unterminated attribute value";
        const std::string value = xml.substr(v0, v1 - v0);
        if (value.find('<') != std::string::npos) return "'<' in attribute " + attr;
        for (std::size_t k = 0; k < value.size(); ++k) {
          if (value[k] == '&' && !entityOk(v0 + k)) return "bad entity in attribute " + attr;
        }
        if (value.find("nan") != std::string::npos || value.find("inf") != std::string::npos) {
          if (attr != "font-family" && attr != "class") return "non-finite value in " + attr + "=\"" + value + "\"";
        }
        j = v1 + 1;
      }
      if (xml[j] == '/') {
        i = j + 2;
        if (stack.empty()) ++roots;
      } else {
        if (stack.empty()) ++roots;
        stack.push_back(name);
        i = j + 1;
      }
    }
  }
  if (!stack.empty()) return "unclosed <" + stack.back() + ">";
  if (roots != 1) return "expected one root element, found " + std::to_string(roots);
  return "";
}

/// Number of occurrences of `needle` in `hay`.
inline int countOf(const std::string& hay, const std::string& needle) {
  int n = 0;
  for (std::size_t p = hay.find(needle); p != std::string::npos; p = hay.find(needle, p + needle.size())) ++n;
  return n;
}

}  // namespace wattswath::test
