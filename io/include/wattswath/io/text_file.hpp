#pragma once
/// \file
/// Whole text files read with a size limit checked before reading (a user's file is never read
/// into memory unbounded).

#include <stdexcept>
#include <string>

namespace wattswath::io {

/// A file that cannot be opened or read, or is refused before reading; what() names the file.
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What a reader accepts: its largest file and how the refusal names the files and what to do.
struct TextFileLimit {
  long long max_bytes = 0;  ///< [B] largest file read; > 0
  std::string kind;         ///< the files in the refusal, e.g. "area files"
  std::string hint;         ///< what to do with a larger file, said in parentheses; may be empty
};

/// Reads the file at `path` whole, refusing it (FileError) before reading when it is larger than
/// `limit.max_bytes`: "PATH: the file has N bytes; KIND of at most M bytes (X MiB) are read (HINT)".
std::string readTextFile(const std::string& path, const TextFileLimit& limit);

/// The refusal of a file of `size` bytes [B] under `limit`, as readTextFile words it.
std::string tooLargeMessage(const std::string& path, long long size, const TextFileLimit& limit);

}  // namespace wattswath::io
