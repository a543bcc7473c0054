#include "backend/gpu_index.h"

#include <cctype>
#include <stdexcept>

#include "options/option_name.h"
#include "options/stereo_options.h"

namespace msp {
namespace {

std::string Trimmed(const std::string& s) {
  size_t begin = 0, end = s.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(s[begin]))) ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(s[end - 1]))) --end;
  return s.substr(begin, end - begin);
}

std::invalid_argument GpuIndexError(const std::string& text, const std::string& why) {
  return std::invalid_argument(MSP_OPTION_FLAG_OF(PatchMatchStereoOptions, gpu_index) + " \"" +
                               text + "\": " + why);
}

// A non-negative decimal integer, or -1 for "-1"; throws on anything else.
int ParseEntry(const std::string& text, const std::string& entry) {
  const std::string digits = entry.size() > 1 && entry[0] == '-' ? entry.substr(1) : entry;
  if (digits.empty() || digits.size() > 6) {
    throw GpuIndexError(text, "\"" + entry + "\" is not a device index");
  }
  for (char c : digits) {
    if (!std::isdigit(static_cast<unsigned char>(c))) {
      throw GpuIndexError(text, "\"" + entry + "\" is not a device index");
    }
  }
  const int value = std::stoi(entry);
  if (value < -1) throw GpuIndexError(text, "device indices are >= 0 (or -1 alone = all)");
  return value;
}

}  // namespace

std::vector<int> ParseGpuIndex(const std::string& text, int num_devices) {
  std::vector<int> entries;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    const std::string entry =
        Trimmed(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    entries.push_back(ParseEntry(text, entry));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (entries.size() == 1 && entries[0] == -1) {
    if (num_devices <= 0) throw GpuIndexError(text, "no CUDA device found");
    std::vector<int> all;
    for (int d = 0; d < num_devices; ++d) all.push_back(d);
    return all;
  }
  for (int d : entries) {
    if (d == -1) throw GpuIndexError(text, "-1 (all devices) cannot be part of a list");
    if (d >= num_devices) {
      throw GpuIndexError(text, "device " + std::to_string(d) + " does not exist (" +
                                    std::to_string(num_devices) + " CUDA device(s) found)");
    }
  }
  return entries;
}

std::vector<std::vector<int>> SpreadOverWorkers(int num_items, int num_workers) {
  if (num_workers <= 0) throw std::invalid_argument("SpreadOverWorkers: no worker");
  std::vector<std::vector<int>> workers(num_workers);
  for (int n = 0; n < num_items; ++n) workers[n % num_workers].push_back(n);
  return workers;
}

}  // namespace msp
