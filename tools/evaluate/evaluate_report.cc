#include "tools/evaluate/evaluate_report.h"

#include <cstdio>
#include <iomanip>
#include <sstream>

#include "tools/evaluate/edge_regions.h"

namespace msp {
namespace eval {
namespace {

std::string Percent(double v) {
  char buf[16];
  std::snprintf(buf, sizeof(buf), "%6.2f", 100.0 * v);
  return buf;
}

// `has_normals`: false prints "n/a" for the normal error (no ground truth).
void PrintRow(std::ostream& out, const std::string& name, const RegionMetrics& m,
              bool has_normals) {
  char normal[16] = "n/a";
  if (has_normals) std::snprintf(normal, sizeof(normal), "%.2f", m.median_normal_error_deg);
  char buf[256];
  std::snprintf(buf, sizeof(buf), "%-16s %7s %7s %7s %7s %7s %7s %7s %7s %7s %9.5f %9s\n",
                name.c_str(), Percent(m.valid_fraction).c_str(), Percent(m.complete[0]).c_str(),
                Percent(m.complete[1]).c_str(), Percent(m.accurate[0]).c_str(),
                Percent(m.accurate[1]).c_str(), Percent(m.complete_abs[0]).c_str(),
                Percent(m.complete_abs[1]).c_str(), Percent(m.accurate_abs[0]).c_str(),
                Percent(m.accurate_abs[1]).c_str(), m.median_rel_error, normal);
  out << buf;
}

// The pixels a map table covers: a figure of DepthMapMetrics, its name in
// the JSON document and its heading in the text.
// `split`: one of the textureless / textured pair, which needs the ground
// truth's textureless masks.
struct Region {
  RegionMetrics DepthMapMetrics::*figures;
  const char* key;
  const char* heading;
  bool split;
};

constexpr Region kRegions[] = {
    {&DepthMapMetrics::all, "all", "all pixels", false},
    {&DepthMapMetrics::textureless, "textureless", "textureless pixels only", true},
    {&DepthMapMetrics::textured, "textured", "textured pixels only", true},
    {&DepthMapMetrics::near_edge, "near_edge", "pixels near a depth edge", false},
    {&DepthMapMetrics::alike_edge, "alike_edge", "pixels near a depth edge between alike colours",
     false},
};

bool HasRegion(const GroundTruthInfo& info, const Region& region) {
  return !region.split || info.has_textureless;
}

// How the ground truth was made, when it is not the bundled scene's exact
// renders, and what it lacks.
void PrintProvenance(const GroundTruthInfo& info, std::ostream& out) {
  if (!info.depth_source.empty()) {
    out << "Ground-truth depth: " << info.depth_source
        << "; pixels without a measurement (0) count neither way\n";
  }
  if (!info.has_normals) {
    out << "No ground-truth normals (normal_maps/): normal errors not evaluated\n";
  } else if (!info.normals_rule.empty()) {
    out << "Ground-truth normals: " << info.normals_rule << "\n";
  }
  if (!info.has_textureless) {
    out << "No textureless masks (textureless/): no textureless / textured split\n";
  } else if (!info.textureless_rule.empty()) {
    out << "Textureless pixels: " << info.textureless_rule << "\n";
  }
}

// The headline of maps on exact renders: how much of where nothing is (sky,
// open background) the maps fill, overall and per image.
void PrintEmpty(const EvaluationResult& r, std::ostream& out) {
  if (!r.info.ZeroDepthIsEmpty()) return;
  const EmptyMetrics& total = r.average.empty;
  out << "\nDepth where the ground truth is empty (sky, open background): "
      << Percent(total.with_depth_fraction) << " % of " << total.num_empty << " pixels\n";
  if (total.num_empty == 0) return;
  char buf[128];
  std::snprintf(buf, sizeof(buf), "%-16s %9s %9s %7s\n", "image", "empty", "w/depth", "%");
  out << buf;
  for (const DepthMapMetrics& m : r.maps) {
    if (m.missing) continue;
    std::snprintf(buf, sizeof(buf), "%-16s %9d %9d %7s\n", m.name.c_str(), m.empty.num_empty,
                  m.empty.num_with_depth, Percent(m.empty.with_depth_fraction).c_str());
    out << buf;
  }
}

// How the edge bands were drawn, under their tables.
void PrintEdgeBand(const EvaluationResult& r, std::ostream& out) {
  out << "(near a depth edge = within " << r.average.edge_band_radius << " ground-truth pixels, "
      << kEdgeBandPixels << " of the map, of neighbours whose depths "
      << "differ by > " << 100.0 * kDepthEdgeJump << "%; alike colours = mean RGB "
      << kEdgeSideSamples << " px beyond each side closer than " << kAlikeColourDistance
      << " levels)\n";
}

void PrintMapTable(const EvaluationResult& r, const Region& region, std::ostream& out) {
  const double* t = r.info.depth_relative_thresholds;
  const double* a = r.info.absolute_thresholds_m;
  out << "\nDepth maps (" << r.input_type << "), " << region.heading << ", thresholds "
      << 100.0 * t[0] << "% / " << 100.0 * t[1] << "% relative depth error (cmp1, cmp2, acc1, "
      << "acc2) and " << a[0] << " m / " << a[1] << " m absolute (cmpA1, cmpA2, accA1, accA2)\n";
  char header[256];
  std::snprintf(header, sizeof(header), "%-16s %7s %7s %7s %7s %7s %7s %7s %7s %7s %9s %9s\n",
                "image", "valid%", "cmp1%", "cmp2%", "acc1%", "acc2%", "cmpA1%", "cmpA2%", "accA1%",
                "accA2%", "med_rel", "med_n_deg");
  out << header;
  for (const DepthMapMetrics& m : r.maps) {
    if (m.missing) {
      out << std::left << std::setw(16) << m.name << " (missing)\n" << std::right;
      continue;
    }
    PrintRow(out, m.name, m.*region.figures, r.info.has_normals);
  }
  PrintRow(out, "average", r.average.*region.figures, r.info.has_normals);
}

void JsonRegion(std::ostringstream& s, const RegionMetrics& m) {
  s << "{\"num_gt\": " << m.num_gt << ", \"num_valid\": " << m.num_valid
    << ", \"valid_fraction\": " << m.valid_fraction << ", \"complete_1\": " << m.complete[0]
    << ", \"complete_2\": " << m.complete[1] << ", \"accurate_1\": " << m.accurate[0]
    << ", \"accurate_2\": " << m.accurate[1] << ", \"complete_abs_1\": " << m.complete_abs[0]
    << ", \"complete_abs_2\": " << m.complete_abs[1]
    << ", \"accurate_abs_1\": " << m.accurate_abs[0]
    << ", \"accurate_abs_2\": " << m.accurate_abs[1]
    << ", \"median_rel_error\": " << m.median_rel_error
    << ", \"median_normal_error_deg\": " << m.median_normal_error_deg << "}";
}

// Where a person finds the pictures of each image, one line each.
void PrintPreviews(const EvaluationResult& r, std::ostream& out) {
  bool any = false;
  for (const DepthMapMetrics& m : r.maps) any = any || !m.previews.empty();
  if (!any) return;
  out << "\nPreviews (depth, normal, error against the ground truth, segmentation prior):\n";
  for (const DepthMapMetrics& m : r.maps) {
    for (const auto& preview : m.previews) {
      out << "  " << m.name << " " << preview.first << ": " << preview.second << "\n";
    }
  }
}

void JsonPreviews(std::ostringstream& s, const DepthMapMetrics& m) {
  s << "{";
  for (size_t i = 0; i < m.previews.size(); ++i) {
    s << (i > 0 ? ", " : "") << "\"" << m.previews[i].first << "\": \"" << m.previews[i].second
      << "\"";
  }
  s << "}";
}

// An image's figures; `with_previews` adds the pictures that exist (an
// average has none).
void JsonMap(std::ostringstream& s, const GroundTruthInfo& info, const DepthMapMetrics& m,
             bool with_previews) {
  s << "{\"name\": \"" << m.name << "\", \"missing\": " << (m.missing ? "true" : "false")
    << ", \"width\": " << m.width << ", \"height\": " << m.height
    << ", \"edge_band_radius\": " << m.edge_band_radius;
  for (const Region& region : kRegions) {
    s << ", \"" << region.key << "\": ";
    if (HasRegion(info, region)) {
      JsonRegion(s, m.*region.figures);
    } else {
      s << "null";
    }
  }
  s << ", \"empty\": ";
  if (info.ZeroDepthIsEmpty()) {
    s << "{\"num_empty\": " << m.empty.num_empty
      << ", \"num_with_depth\": " << m.empty.num_with_depth
      << ", \"with_depth_fraction\": " << m.empty.with_depth_fraction << "}";
  } else {
    s << "null";
  }
  if (with_previews) {
    s << ", \"previews\": ";
    JsonPreviews(s, m);
  }
  s << "}";
}

}  // namespace

void PrintReport(const EvaluationResult& r, std::ostream& out) {
  out << "Ground truth: " << r.info.dir << " (" << r.info.image_names.size() << " images, extent "
      << std::fixed << std::setprecision(3) << r.info.extent << " m)\n"
      << std::defaultfloat;
  PrintProvenance(r.info, out);
  if (!r.maps.empty()) {
    out << "cmpK = within threshold K over all ground-truth pixels; accK = over valid "
           "predictions\n";
    PrintEmpty(r, out);
    for (const Region& region : kRegions) {
      if (HasRegion(r.info, region)) PrintMapTable(r, region, out);
    }
    PrintEdgeBand(r, out);
    if (r.num_missing_maps > 0) out << r.num_missing_maps << " map(s) missing\n";
    PrintPreviews(r, out);
  }
  if (r.has_cloud) {
    const CloudMetrics& c = r.cloud;
    out << "\nFused point cloud " << r.fused << ": " << c.num_points << " points, " << c.num_judged
        << " judged (on a measured pixel of some ground-truth view; accuracy is "
        << "over those); ground truth " << c.num_gt << " samples, " << c.num_gt_multi
        << " seen by >= " << c.min_views << " views\n";
    char buf[256];
    std::snprintf(buf, sizeof(buf), "%-18s %7s %7s %7s %7s %7s\n", "threshold", "acc%", "comp%",
                  "F1%",
                  "comp"
                  "3v%",
                  "F1_3v%");
    out << buf;
    for (const CloudThresholdMetrics& m : c.thresholds) {
      char label[64];
      if (m.absolute) {
        std::snprintf(label, sizeof(label), "%.4f m", m.metres);
      } else {
        std::snprintf(label, sizeof(label), "%.2f%% = %.4f m", 100.0 * m.fraction, m.metres);
      }
      std::snprintf(buf, sizeof(buf), "%-18s %7s %7s %7s %7s %7s\n", label,
                    Percent(m.accuracy).c_str(), Percent(m.completeness).c_str(),
                    Percent(m.f1).c_str(), Percent(m.completeness_multi).c_str(),
                    Percent(m.f1_multi).c_str());
      out << buf;
    }
    out << "(3v = completeness over samples seen by >= " << c.min_views
        << " views, what COLMAP's default fusion can reach)\n";
    if (r.has_cloud_off_textureless) {
      const CloudMetrics& off = r.cloud_off_textureless;
      out << "Accuracy off textureless surfaces (" << off.num_judged
          << " points on textured surfaces or on none, as in the sky):";
      for (const CloudThresholdMetrics& m : off.thresholds) out << " " << Percent(m.accuracy);
      out << " %\n";
    }
  }
}

std::string ReportJson(const EvaluationResult& r) {
  std::ostringstream s;
  s << std::setprecision(8) << "{\n  \"ground_truth\": \"" << r.info.dir << "\",\n"
    << "  \"extent\": " << r.info.extent << ",\n  \"input_type\": \"" << r.input_type << "\",\n"
    << "  \"depth_relative_thresholds\": [" << r.info.depth_relative_thresholds[0] << ", "
    << r.info.depth_relative_thresholds[1] << "],\n  \"absolute_thresholds_metres\": ["
    << r.info.absolute_thresholds_m[0] << ", " << r.info.absolute_thresholds_m[1] << "],\n"
    << "  \"depth_source\": \"" << r.info.depth_source
    << "\",\n  \"has_normals\": " << (r.info.has_normals ? "true" : "false")
    << ",\n  \"has_textureless\": " << (r.info.has_textureless ? "true" : "false")
    << ",\n  \"num_missing_maps\": " << r.num_missing_maps << ",\n  \"depth_maps\": [\n";
  for (size_t i = 0; i < r.maps.size(); ++i) {
    s << "    ";
    JsonMap(s, r.info, r.maps[i], /*with_previews=*/true);
    s << (i + 1 < r.maps.size() ? ",\n" : "\n");
  }
  s << "  ],\n  \"average\": ";
  JsonMap(s, r.info, r.average, /*with_previews=*/false);
  s << ",\n  \"fused\": ";
  if (!r.has_cloud) {
    s << "null\n}\n";
    return s.str();
  }
  const CloudMetrics& c = r.cloud;
  s << "{\"path\": \"" << r.fused << "\", \"num_points\": " << c.num_points
    << ", \"num_judged\": " << c.num_judged << ", \"num_gt\": " << c.num_gt
    << ", \"num_gt_multi\": " << c.num_gt_multi << ", \"min_views\": " << c.min_views
    << ", \"thresholds\": [\n";
  for (size_t i = 0; i < c.thresholds.size(); ++i) {
    const CloudThresholdMetrics& m = c.thresholds[i];
    s << "    {\"fraction\": " << m.fraction << ", \"metres\": " << m.metres
      << ", \"absolute\": " << (m.absolute ? "true" : "false") << ", \"accuracy\": " << m.accuracy
      << ", \"completeness\": " << m.completeness
      << ", \"completeness_multi\": " << m.completeness_multi << ", \"f1\": " << m.f1
      << ", \"f1_multi\": " << m.f1_multi << "}" << (i + 1 < c.thresholds.size() ? ",\n" : "\n");
  }
  s << "  ], \"off_textureless\": ";
  if (r.has_cloud_off_textureless) {
    const CloudMetrics& off = r.cloud_off_textureless;
    s << "{\"num_judged\": " << off.num_judged << ", \"accuracy\": [";
    for (size_t i = 0; i < off.thresholds.size(); ++i) {
      s << (i > 0 ? ", " : "") << off.thresholds[i].accuracy;
    }
    s << "]}";
  } else {
    s << "null";
  }
  s << "}\n}\n";
  return s.str();
}

}  // namespace eval
}  // namespace msp
