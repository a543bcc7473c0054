// File helpers shared by the COLMAP readers and writers: whole-file reads with
// clear errors, and atomic writes so that an interrupted run never leaves a
// half-written file behind under the final name.
#pragma once

#include <string>

namespace msp {

// Creates `dir` and its missing parents. Throws InputError on failure.
void CreateDirectories(const std::string& dir);

// Creates the parent folders of `path` (image names may contain sub-folders).
void CreateParentDirectories(const std::string& path);

// Reads a whole file. Throws InputError naming `path` when it cannot be read.
std::string ReadFileToString(const std::string& path);

// Writes `bytes` to TemporaryPath(path, pid), flushes it to the disk and
// renames it to `path`, creating missing parent folders. Throws InputError
// naming `path` and the system's reason (e.g. "No space left on device") on
// failure and removes the temporary file.
void WriteFileAtomic(const std::string& path, const std::string& bytes);

// "<path>.tmp-<pid>": where WriteFileAtomic writes before the rename.
constexpr char kTemporarySuffix[] = ".tmp-";
std::string TemporaryPath(const std::string& path, long pid);

// True when `path` exists and is a regular file (or a link to one).
bool IsFile(const std::string& path);
// True when `path` exists and is a directory (or a link to one).
bool IsDirectory(const std::string& path);

// "<a>/<b>" without doubling the separator.
std::string JoinPaths(const std::string& a, const std::string& b);

}  // namespace msp
