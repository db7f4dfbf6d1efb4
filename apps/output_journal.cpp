#include "output_journal.hpp"

#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <unistd.h>

namespace wattswath::apps {
namespace {

namespace fs = std::filesystem;

// A plain file name: no folder part, no line break or tab (the journal's separators).
bool plainName(const std::string& n) {
  return !n.empty() && n != "." && n != ".." && n.find_first_of("/\t\n\r") == std::string::npos;
}

// An absolute path of a file elsewhere (a --report outside the folder): no line break or tab.
bool absolutePath(const std::string& n) {
  return n.size() > 1 && n[0] == '/' && n.find_first_of("\t\n\r") == std::string::npos &&
         fs::path(n).filename() != ".." && fs::path(n).filename() != ".";
}

// Whether `tmp` is `target` + ".tmp." + 16 hex digits: a temporary this program made for it.
bool temporaryOf(const std::string& tmp, const std::string& target) {
  const std::string prefix = target + ".tmp.";
  if (tmp.size() != prefix.size() + 16 || tmp.compare(0, prefix.size(), prefix) != 0) return false;
  for (std::size_t i = prefix.size(); i < tmp.size(); ++i)
    if (!std::isxdigit(static_cast<unsigned char>(tmp[i]))) return false;
  return true;
}

void writeFlushed(const fs::path& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error(path.string() + ": cannot write the commit journal (" + std::strerror(errno) + ")");
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t w = ::write(fd, text.data() + done, text.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) break;
    done += static_cast<std::size_t>(w);
  }
  const bool ok = done == text.size() && ::fsync(fd) == 0;
  ::close(fd);
  if (!ok) throw std::runtime_error(path.string() + ": cannot write the commit journal (" + std::strerror(errno) + ")");
}

}  // namespace

void syncFolder(const std::string& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

void writeCommitJournal(const std::string& dir, const std::vector<std::pair<std::string, std::string>>& renames) {
  std::string text = "# wattswath: files of an interrupted run, renamed into place by the next run into this folder\n";
  for (const auto& [tmp, target] : renames) {
    const bool inside = plainName(tmp) && plainName(target);
    const bool elsewhere = absolutePath(tmp) && absolutePath(target) && fs::path(tmp).parent_path() == fs::path(target).parent_path();
    if (!inside && !elsewhere) {
      throw std::invalid_argument("commit journal: '" + tmp + "' -> '" + target +
                                  "' is neither a plain file name nor an absolute path in one folder");
    }
    text += tmp + "\t" + target + "\n";
  }
  const fs::path journal = fs::path(dir) / kCommitJournal;
  const fs::path tmp = fs::path(dir) / (std::string(kCommitJournal) + ".new");
  writeFlushed(tmp, text);
  std::error_code ec;
  fs::rename(tmp, journal, ec);
  if (ec) throw std::runtime_error(journal.string() + ": cannot write the commit journal (" + ec.message() + ")");
  syncFolder(dir);
}

void removeCommitJournal(const std::string& dir) {
  std::error_code ec;
  if (fs::remove(fs::path(dir) / kCommitJournal, ec)) syncFolder(dir);
}

int completeInterruptedCommit(const std::string& dir) {
  const fs::path journal = fs::path(dir) / kCommitJournal;
  std::error_code ec;
  if (!fs::is_regular_file(fs::symlink_status(journal, ec))) return 0;
  std::ifstream in(journal);
  std::string line;
  int renamed = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto tab = line.find('\t');
    if (tab == std::string::npos) continue;
    const std::string tmp = line.substr(0, tab), target = line.substr(tab + 1);
    // A file of the folder by name, or one elsewhere (a --report path) by absolute path in one
    // folder; either way only this program's temporary of that very target is renamed.
    const bool inside = plainName(tmp) && plainName(target) && temporaryOf(tmp, target);
    const bool elsewhere = absolutePath(tmp) && absolutePath(target) &&
                           fs::path(tmp).parent_path() == fs::path(target).parent_path() &&
                           temporaryOf(fs::path(tmp).filename().string(), fs::path(target).filename().string());
    if (!inside && !elsewhere) continue;
    const fs::path from = inside ? fs::path(dir) / tmp : fs::path(tmp), to = inside ? fs::path(dir) / target : fs::path(target);
    if (!fs::is_regular_file(fs::symlink_status(from, ec))) continue;  // renamed before the crash
    fs::rename(from, to, ec);
    if (ec) throw std::runtime_error(to.string() + ": cannot complete the interrupted commit of an earlier run (" + ec.message() + ")");
    if (elsewhere) syncFolder(to.parent_path().string());
    ++renamed;
  }
  in.close();
  syncFolder(dir);
  removeCommitJournal(dir);
  return renamed;
}

}  // namespace wattswath::apps
