// readMission: a mission file by its extension and content.
#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "files_internal.hpp"
#include "wattswath/io/text_file.hpp"

namespace wattswath::mission {
namespace {
using detail::fail;

enum class Format { Unknown, Plan, Wpl };

const char* formatName(Format f) { return f == Format::Plan ? ".plan (JSON)" : f == Format::Wpl ? "QGC WPL 110" : "unknown"; }

Format byExtension(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return Format::Unknown;
  std::string e = path.substr(dot + 1);
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (e == "plan") return Format::Plan;
  if (e == "waypoints" || e == "txt") return Format::Wpl;
  return Format::Unknown;
}

Format byContent(const std::string& text) {
  const auto i = text.find_first_not_of(" \t\r\n");
  if (i == std::string::npos) return Format::Unknown;
  if (text[i] == '{') return Format::Plan;
  if (text.compare(i, 7, "QGC WPL") == 0) return Format::Wpl;
  return Format::Unknown;
}

std::string readText(const std::string& path) {
  try {
    return io::readTextFile(path, {kMaxMissionFileBytes, "mission files", ""});
  } catch (const io::FileError& e) {
    throw MissionError(e.what());
  }
}

}  // namespace

Mission readMission(const std::string& path, const ReadOptions& o) {
  const std::string text = detail::withoutBom(readText(path));
  detail::checkText(text, path);
  const Format ext = byExtension(path), content = byContent(text);
  if (ext != Format::Unknown && content != Format::Unknown && ext != content)
    fail(path, std::string("the extension says ") + formatName(ext) + " but the content looks like " + formatName(content));
  const Format f = content != Format::Unknown ? content : ext;
  if (f == Format::Plan) return parseQgcPlan(text, path, o);
  if (f == Format::Wpl) return parseQgcWpl(text, path, o);
  fail(path, "unknown mission format, expected a QGroundControl .plan (JSON) or a QGC WPL 110 .waypoints file");
}

}  // namespace wattswath::mission
