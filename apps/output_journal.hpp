#pragma once
// The commit journal of an output folder (OutputSet): before the staged files of a run are renamed
// into place, the list of (temporary, target) names is written to `.wattswath-commit` in the folder
// and flushed; it is removed once every rename is done. A commit cut short by a crash (a power cut,
// SIGKILL) leaves the journal behind, and the next run that locks the folder completes it, so the
// folder never stays a mix of two runs' files.
#include <string>
#include <utility>
#include <vector>

namespace wattswath::apps {

/// The journal's file name inside the output folder.
inline constexpr const char* kCommitJournal = ".wattswath-commit";

/// Writes (atomically, flushed to the disk) the journal of `dir` listing `renames`, temporary
/// first: file names inside `dir`, or absolute paths of a file elsewhere (a --report outside the
/// folder; temporary and target in one folder). Throws std::runtime_error naming the journal when it cannot.
void writeCommitJournal(const std::string& dir, const std::vector<std::pair<std::string, std::string>>& renames);

/// Removes the journal of `dir` (and flushes the folder); no error when there is none.
void removeCommitJournal(const std::string& dir);

/// Completes the commit the journal of `dir` records, if any: renames each temporary still present
/// onto its target and removes the journal. Returns the number of files renamed. Entries that are
/// not a `<target>.tmp.<16 hex digits>` pair of plain names, or of absolute paths in one folder,
/// are skipped.
int completeInterruptedCommit(const std::string& dir);

/// Flushes the folder `dir` itself (its renames) to the disk; errors are ignored (best effort).
void syncFolder(const std::string& dir);

}  // namespace wattswath::apps
