#include "patch_match/run_summary.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

#include "base/progress.h"

namespace msp {
namespace {

std::string Printf(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string Printf(const char* format, ...) {
  char text[256];
  va_list args;
  va_start(args, format);
  std::vsnprintf(text, sizeof(text), format, args);
  va_end(args);
  return text;
}

// Tenths of a second below a minute (short passes), else FormatDuration.
std::string PassDuration(double seconds) {
  return seconds < 59.95 ? Printf("%.1fs", seconds) : FormatDuration(seconds);
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
  out += Printf("  %-*s  %10s  %6s\n", lw, "pass", "time", "share");
  for (const PassTime& pass : passes) {
    out +=
        Printf("  %-*s  %10s  %5.1f%%\n", lw, pass.label.c_str(),
               PassDuration(pass.seconds).c_str(), total > 0 ? 100.0 * pass.seconds / total : 0.0);
  }
  out += Printf("  %-*s  %10s  %5.1f%%\n", lw, "all passes", PassDuration(total).c_str(), 100.0);

  size_t name_width = 5;
  for (const ImageOutcome& image : images) name_width = std::max(name_width, image.name.size());
  const int nw = static_cast<int>(name_width);
  out += Printf("  %-*s  %9s  %12s  %6s\n", nw, "image", "size", "valid pixels", "share");
  for (const ImageOutcome& image : images) {
    const std::string size = std::to_string(image.width) + "x" + std::to_string(image.height);
    if (image.valid_pixels < 0) {
      out += Printf("  %-*s  %9s  %s\n", nw, image.name.c_str(), size.c_str(),
                    "kept (final maps from an earlier run)");
      continue;
    }
    const double pixels = static_cast<double>(image.width) * image.height;
    out += Printf("  %-*s  %9s  %12ld  %5.1f%%\n", nw, image.name.c_str(), size.c_str(),
                  image.valid_pixels, pixels > 0 ? 100.0 * image.valid_pixels / pixels : 0.0);
  }
  return out;
}

}  // namespace msp
