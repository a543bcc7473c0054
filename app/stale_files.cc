#include "app/stale_files.h"

#include <cctype>
#include <filesystem>
#include <system_error>

#include "io/file_util.h"

namespace msp {
namespace fs = std::filesystem;
namespace {

bool AllDigits(const std::string& text, size_t begin, size_t end) {
  if (begin >= end) return false;
  for (size_t i = begin; i < end; ++i) {
    if (!std::isdigit(static_cast<unsigned char>(text[i]))) return false;
  }
  return true;
}

void RemoveInto(const fs::path& path, std::vector<std::string>* removed) {
  std::error_code ec;
  if (fs::remove(path, ec)) removed->push_back(path.string());
}

}  // namespace

bool IsTemporaryFileName(const std::string& file_name) {
  const size_t at = file_name.rfind(kTemporarySuffix);
  if (at == std::string::npos || at == 0) return false;
  return AllDigits(file_name, at + std::string(kTemporarySuffix).size(), file_name.size());
}

bool IsSpilledStateFileName(const std::string& file_name) {
  const std::string prefix = "state-", suffix = ".bin";
  if (file_name.size() <= prefix.size() + suffix.size() ||
      file_name.compare(0, prefix.size(), prefix) != 0 ||
      file_name.compare(file_name.size() - suffix.size(), suffix.size(), suffix) != 0) {
    return false;
  }
  const size_t begin = prefix.size(), end = file_name.size() - suffix.size();
  const size_t dash = file_name.find('-', begin);
  return dash != std::string::npos && dash < end && AllDigits(file_name, begin, dash) &&
         AllDigits(file_name, dash + 1, end);
}

std::vector<std::string> RemoveStaleFiles(const std::string& stereo_dir,
                                          const std::string& scratch_dir) {
  std::vector<std::string> removed;
  std::error_code ec;
  if (IsDirectory(stereo_dir)) {
    std::vector<fs::path> stale;
    for (fs::recursive_directory_iterator it(stereo_dir, ec), end; !ec && it != end;
         it.increment(ec)) {
      if (it->is_regular_file(ec) && IsTemporaryFileName(it->path().filename().string())) {
        stale.push_back(it->path());
      }
    }
    for (const fs::path& path : stale) RemoveInto(path, &removed);
  }
  if (IsDirectory(scratch_dir)) {
    std::vector<fs::path> stale;
    for (fs::directory_iterator it(scratch_dir, ec), end; !ec && it != end; it.increment(ec)) {
      if (it->is_regular_file(ec) && IsSpilledStateFileName(it->path().filename().string())) {
        stale.push_back(it->path());
      }
    }
    for (const fs::path& path : stale) RemoveInto(path, &removed);
  }
  return removed;
}

}  // namespace msp
