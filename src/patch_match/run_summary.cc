#include "patch_match/run_summary.h"

#include <algorithm>

#include "base/progress.h"
#include "base/string_printf.h"

namespace msp {
namespace {

// Tenths of a second below a minute (short passes), else FormatDuration.
std::string PassDuration(double seconds) {
  return seconds < 59.95 ? StringPrintf("%.1fs", seconds) : FormatDuration(seconds);
}

}  // namespace

std::string FormatRunSummary(const std::vector<PassTime>& passes,
                             const std::vector<ImageOutcome>& images) {
  double total = 0;
  for (const PassTime& pass : passes) total += pass.seconds;
  size_t label_width = 4;
  for (const PassTime& pass : passes) label_width = std::max(label_width, pass.label.size());
  const int lw = static_cast<int>(label_width);
  std::string out = "Summary\n";
  out += StringPrintf("  %-*s  %10s  %6s\n", lw, "pass", "time", "share");
  for (const PassTime& pass : passes) {
    out +=
        StringPrintf("  %-*s  %10s  %5.1f%%\n", lw, pass.label.c_str(),
               PassDuration(pass.seconds).c_str(), total > 0 ? 100.0 * pass.seconds / total : 0.0);
  }
  out += StringPrintf("  %-*s  %10s  %5.1f%%\n", lw, "all passes", PassDuration(total).c_str(), 100.0);

  size_t name_width = 5;
  for (const ImageOutcome& image : images) name_width = std::max(name_width, image.name.size());
  const int nw = static_cast<int>(name_width);
  out += StringPrintf("  %-*s  %9s  %12s  %6s\n", nw, "image", "size", "valid pixels", "share");
  for (const ImageOutcome& image : images) {
    const std::string size = std::to_string(image.width) + "x" + std::to_string(image.height);
    if (image.valid_pixels < 0) {
      out += StringPrintf("  %-*s  %9s  %s\n", nw, image.name.c_str(), size.c_str(),
                    "kept (final maps from an earlier run)");
      continue;
    }
    const double pixels = static_cast<double>(image.width) * image.height;
    out += StringPrintf("  %-*s  %9s  %12ld  %5.1f%%\n", nw, image.name.c_str(), size.c_str(),
                  image.valid_pixels, pixels > 0 ? 100.0 * image.valid_pixels / pixels : 0.0);
  }
  return out;
}

}  // namespace msp
