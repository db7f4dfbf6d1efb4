#include "wattswath/io/text_file.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace wattswath::io {

std::string tooLargeMessage(const std::string& path, long long size, const TextFileLimit& limit) {
  char mib[32];
  std::snprintf(mib, sizeof mib, "%g", static_cast<double>(limit.max_bytes) / (1024.0 * 1024.0));
  std::string m = path + ": the file has " + std::to_string(size) + " bytes; " + limit.kind + " of at most " +
                  std::to_string(limit.max_bytes) + " bytes (" + mib + " MiB) are read";
  if (!limit.hint.empty()) m += " (" + limit.hint + ")";
  return m;
}

std::string readTextFile(const std::string& path, const TextFileLimit& limit) {
  std::ifstream f(path, std::ios::binary | std::ios::ate);
  if (!f) throw FileError(path + ": cannot open the file");
  const auto end = f.tellg();
  // A pipe or a character device has no size: read it up to the limit and refuse what is beyond.
  const bool sized = end != std::streampos(-1);
  if (sized && static_cast<long long>(end) > limit.max_bytes) {
    throw FileError(tooLargeMessage(path, static_cast<long long>(end), limit));
  }
  if (sized) f.seekg(0);
  std::string text;
  char buffer[1 << 16];
  while (f.read(buffer, sizeof buffer) || f.gcount() > 0) {
    text.append(buffer, static_cast<size_t>(f.gcount()));
    if (static_cast<long long>(text.size()) > limit.max_bytes) {
      throw FileError(tooLargeMessage(path, static_cast<long long>(text.size()), limit) +
                      "; the input grew while it was read or is a pipe, so its size is at least that");
    }
  }
  if (f.bad()) throw FileError(path + ": cannot read the file");
  return text;
}

}  // namespace wattswath::io
