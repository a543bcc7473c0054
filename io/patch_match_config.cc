// Parsing of stereo/patch-match.cfg, following COLMAP's
// PatchMatchController::ReadProblems (COLMAP's src/mvs/patch_match.cc).
#include "io/patch_match_config.h"

#include <cerrno>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "io/errors.h"
#include "io/file_util.h"
#include "options/option_name.h"
#include "options/stereo_options.h"

namespace msp {
namespace {

constexpr char kAllToken[] = "__all__";
constexpr char kAutoToken[] = "__auto__";

std::string Trim(const std::string& s) {
  const char* kSpace = " \t\r\n\f\v";
  const size_t begin = s.find_first_not_of(kSpace);
  if (begin == std::string::npos) return "";
  return s.substr(begin, s.find_last_not_of(kSpace) - begin + 1);
}

// COLMAP's CSVToVector: split on ',' or ';', trim items, drop empty ones.
std::vector<std::string> SplitSourceSpec(const std::string& line) {
  std::vector<std::string> items;
  std::string item;
  for (const char c : line) {
    if (c == ',' || c == ';') {
      item = Trim(item);
      if (!item.empty()) items.push_back(item);
      item.clear();
    } else {
      item.push_back(c);
    }
  }
  item = Trim(item);
  if (!item.empty()) items.push_back(item);
  return items;
}

struct NumberedLine {
  size_t number;  // 1-based, for messages
  std::string text;
};

}  // namespace

std::vector<PatchMatchConfigEntry> ParsePatchMatchConfig(const std::string& path) {
  if (!IsFile(path)) {
    throw InputError("patch-match config " + path +
                     " does not exist (it is written by `colmap image_undistorter`; use " +
                     MSP_OPTION_FLAG_OF(StereoCommandOptions, config_path) +
                     " to give another file)");
  }
  return ParsePatchMatchConfigText(ReadFileToString(path), path);
}

std::vector<PatchMatchConfigEntry> ParsePatchMatchConfigText(const std::string& text,
                                                             const std::string& path_for_errors) {
  std::vector<NumberedLine> lines;
  std::istringstream stream(text);
  std::string line;
  for (size_t number = 1; std::getline(stream, line); ++number) {
    line = Trim(line);
    if (line.empty() || line[0] == '#') continue;
    lines.push_back({number, line});
  }
  // COLMAP silently drops a trailing reference without a source line; that is
  // almost always a truncated or hand-edited file, so it is reported instead.
  if (lines.size() % 2 != 0) {
    const NumberedLine& last = lines.back();
    throw InputError(path_for_errors + ":" + std::to_string(last.number) + ": reference image `" +
                     last.text +
                     "` has no source line (the file must hold pairs of lines: reference "
                     "name, then `__auto__, N`, `__all__` or a list of source names)");
  }

  std::vector<PatchMatchConfigEntry> entries;
  for (size_t i = 0; i < lines.size(); i += 2) {
    PatchMatchConfigEntry entry;
    entry.ref_name = lines[i].text;
    const std::vector<std::string> spec = SplitSourceSpec(lines[i + 1].text);
    if (spec.size() == 1 && spec[0] == kAllToken) {
      entry.kind = PatchMatchConfigEntry::Kind::kAll;
    } else if (spec.size() == 2 && spec[0] == kAutoToken) {
      entry.kind = PatchMatchConfigEntry::Kind::kAuto;
      errno = 0;
      char* end = nullptr;
      const long long num = std::strtoll(spec[1].c_str(), &end, 10);
      if (*end != '\0' || errno == ERANGE || num < 0 || num > (1 << 20)) {
        throw InputError(path_for_errors + ":" + std::to_string(lines[i + 1].number) +
                         ": invalid number of source images `" + spec[1] + "` after __auto__");
      }
      entry.num_auto = static_cast<int>(num);
    } else {
      entry.kind = PatchMatchConfigEntry::Kind::kList;
      entry.src_names = spec;
    }
    entries.push_back(std::move(entry));
  }
  return entries;
}

}  // namespace msp
