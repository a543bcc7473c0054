// cameras.txt / images.txt / points3D.txt as COLMAP's
// Reconstruction::{Read,Write}Text handle them: '#' comments, one record per
// line (two lines per image), values separated by single spaces.
#include <cerrno>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/errors.h"
#include "io/file_util.h"
#include "io/sparse_model.h"
#include "io/sparse_model_internal.h"

namespace msp {
namespace {

// Full-precision doubles so that a text round trip is exact.
constexpr int kDoublePrecision = std::numeric_limits<double>::max_digits10;

std::string Trim(const std::string& s) {
  const char* kSpace = " \t\r\n\f\v";
  const size_t begin = s.find_first_not_of(kSpace);
  if (begin == std::string::npos) return "";
  return s.substr(begin, s.find_last_not_of(kSpace) - begin + 1);
}

std::vector<std::string> SplitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  std::string line;
  while (std::getline(stream, line)) lines.push_back(Trim(line));
  return lines;
}

// COLMAP splits on single spaces; any run of whitespace is accepted here,
// which reads every file COLMAP writes and forgives hand-edited ones.
std::vector<std::string> Tokens(const std::string& line) {
  std::vector<std::string> tokens;
  std::istringstream stream(line);
  std::string token;
  while (stream >> token) tokens.push_back(token);
  return tokens;
}

// Parses the values of one line, naming the file and line on errors.
class LineParser {
 public:
  LineParser(const std::string& path, size_t line_index)
      : where_(path + ":" + std::to_string(line_index + 1)) {}

  double Double(const std::string& token, const char* what) const {
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (token.empty() || *end != '\0' || errno == ERANGE) Bad(token, what);
    return value;
  }
  uint64_t Uint(const std::string& token, const char* what) const {
    if (token.empty() || token[0] == '-' || token[0] == '+') Bad(token, what);
    errno = 0;
    char* end = nullptr;
    const unsigned long long value = std::strtoull(token.c_str(), &end, 10);
    if (*end != '\0' || errno == ERANGE) Bad(token, what);
    return value;
  }
  uint32_t Uint32(const std::string& token, const char* what) const {
    const uint64_t value = Uint(token, what);
    if (value > std::numeric_limits<uint32_t>::max()) Bad(token, what);
    return static_cast<uint32_t>(value);
  }
  // A 3D point id in images.txt, where -1 marks "no 3D point".
  uint64_t PointId(const std::string& token) const {
    if (token == "-1") return kInvalidPoint3DId;
    return Uint(token, "POINT3D_ID");
  }
  [[noreturn]] void Fail(const std::string& what) const { throw InputError(where_ + ": " + what); }

 private:
  [[noreturn]] void Bad(const std::string& token, const char* what) const {
    Fail(std::string("invalid ") + what + " `" + token + "`");
  }

  std::string where_;
};

bool IsSkipped(const std::string& line) { return line.empty() || line[0] == '#'; }

std::vector<SparseCamera> ReadCameras(const std::string& path) {
  const std::vector<std::string> lines = SplitLines(ReadFileToString(path));
  std::vector<SparseCamera> cameras;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (IsSkipped(lines[i])) continue;
    const LineParser parse(path, i);
    const std::vector<std::string> t = Tokens(lines[i]);
    if (t.size() < 4) parse.Fail("expected CAMERA_ID MODEL WIDTH HEIGHT PARAMS...");
    SparseCamera camera;
    camera.camera_id = parse.Uint32(t[0], "CAMERA_ID");
    camera.model_id = CameraModelIdFromName(t[1]);
    if (camera.model_id < 0) {
      parse.Fail("unknown or unsupported camera model `" + t[1] +
                 "`; undistort the images with `colmap image_undistorter`");
    }
    camera.width = parse.Uint(t[2], "WIDTH");
    camera.height = parse.Uint(t[3], "HEIGHT");
    const size_t num_params = CameraModelNumParams(camera.model_id);
    if (t.size() != 4 + num_params) {
      parse.Fail(std::string("camera model ") + t[1] + " takes " + std::to_string(num_params) +
                 " parameters, found " + std::to_string(t.size() - 4));
    }
    for (size_t k = 0; k < num_params; ++k) {
      camera.params.push_back(parse.Double(t[4 + k], "camera parameter"));
    }
    cameras.push_back(std::move(camera));
  }
  return cameras;
}

std::vector<SparseImage> ReadImages(const std::string& path) {
  const std::vector<std::string> lines = SplitLines(ReadFileToString(path));
  std::vector<SparseImage> images;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (IsSkipped(lines[i])) continue;
    const LineParser parse(path, i);
    const std::vector<std::string> t = Tokens(lines[i]);
    if (t.size() != 10) {
      parse.Fail(
          "expected IMAGE_ID QW QX QY QZ TX TY TZ CAMERA_ID NAME (names cannot "
          "contain spaces)");
    }
    SparseImage image;
    image.image_id = parse.Uint32(t[0], "IMAGE_ID");
    for (int k = 0; k < 4; ++k) image.qvec[k] = parse.Double(t[1 + k], "quaternion value");
    for (int k = 0; k < 3; ++k) image.tvec[k] = parse.Double(t[5 + k], "translation value");
    image.camera_id = parse.Uint32(t[8], "CAMERA_ID");
    image.name = t[9];
    // The line after an image holds its 2D points; it may be empty, and is
    // read as is (COLMAP does not skip comments there). A missing last line
    // counts as empty rather than silently dropping the image.
    ++i;
    if (i < lines.size()) {
      const LineParser parse_points(path, i);
      const std::vector<std::string> p = Tokens(lines[i]);
      if (p.size() % 3 != 0) parse_points.Fail("expected triples X Y POINT3D_ID");
      for (size_t k = 0; k < p.size(); k += 3) {
        Point2D point;
        point.x = parse_points.Double(p[k], "X");
        point.y = parse_points.Double(p[k + 1], "Y");
        point.point3D_id = parse_points.PointId(p[k + 2]);
        image.points2D.push_back(point);
      }
    }
    images.push_back(std::move(image));
  }
  return images;
}

std::vector<SparsePoint3D> ReadPoints3D(const std::string& path) {
  const std::vector<std::string> lines = SplitLines(ReadFileToString(path));
  std::vector<SparsePoint3D> points;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (IsSkipped(lines[i])) continue;
    const LineParser parse(path, i);
    const std::vector<std::string> t = Tokens(lines[i]);
    if (t.size() < 8 || (t.size() - 8) % 2 != 0) {
      parse.Fail("expected POINT3D_ID X Y Z R G B ERROR followed by IMAGE_ID POINT2D_IDX pairs");
    }
    SparsePoint3D point;
    point.point3D_id = parse.Uint(t[0], "POINT3D_ID");
    for (int k = 0; k < 3; ++k) point.xyz[k] = parse.Double(t[1 + k], "coordinate");
    for (int k = 0; k < 3; ++k) {
      const uint64_t c = parse.Uint(t[4 + k], "colour value");
      if (c > 255) parse.Fail("colour value `" + t[4 + k] + "` is larger than 255");
      point.rgb[k] = static_cast<uint8_t>(c);
    }
    point.error = parse.Double(t[7], "ERROR");
    for (size_t k = 8; k < t.size(); k += 2) {
      TrackElement element;
      element.image_id = parse.Uint32(t[k], "IMAGE_ID");
      element.point2D_idx = parse.Uint32(t[k + 1], "POINT2D_IDX");
      point.track.push_back(element);
    }
    points.push_back(std::move(point));
  }
  return points;
}

std::ostringstream MakeStream() {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << std::setprecision(kDoublePrecision);
  return out;
}

}  // namespace

SparseModel ReadSparseModelText(const std::string& dir) {
  SparseModel model;
  model.cameras = ReadCameras(JoinPaths(dir, "cameras.txt"));
  model.images = ReadImages(JoinPaths(dir, "images.txt"));
  model.points3D = ReadPoints3D(JoinPaths(dir, "points3D.txt"));
  CheckSparseModelReferences(model, dir, ".txt");
  return model;
}

void WriteSparseModelText(const SparseModel& model, const std::string& dir) {
  CreateDirectories(dir);

  std::ostringstream cameras = MakeStream();
  cameras << "# Camera list with one line of data per camera:\n"
          << "#   CAMERA_ID, MODEL, WIDTH, HEIGHT, PARAMS[]\n"
          << "# Number of cameras: " << model.cameras.size() << "\n";
  for (const SparseCamera& camera : model.cameras) {
    if (static_cast<int>(camera.params.size()) != CameraModelNumParams(camera.model_id)) {
      throw std::logic_error("WriteSparseModelText: camera " + std::to_string(camera.camera_id) +
                             " has a parameter count that does not match its model");
    }
    cameras << camera.camera_id << " " << CameraModelName(camera.model_id) << " " << camera.width
            << " " << camera.height;
    for (double param : camera.params) cameras << " " << param;
    cameras << "\n";
  }

  std::ostringstream images = MakeStream();
  images << "# Image list with two lines of data per image:\n"
         << "#   IMAGE_ID, QW, QX, QY, QZ, TX, TY, TZ, CAMERA_ID, NAME\n"
         << "#   POINTS2D[] as (X, Y, POINT3D_ID)\n"
         << "# Number of images: " << model.images.size() << "\n";
  for (const SparseImage& image : model.images) {
    if (image.name.empty() || image.name.find_first_of(" \t\r\n") != std::string::npos) {
      throw std::logic_error("WriteSparseModelText: image name `" + image.name +
                             "` is empty or contains whitespace");
    }
    images << image.image_id;
    for (double q : image.qvec) images << " " << q;
    for (double t : image.tvec) images << " " << t;
    images << " " << image.camera_id << " " << image.name << "\n";
    for (size_t k = 0; k < image.points2D.size(); ++k) {
      const Point2D& point = image.points2D[k];
      if (k > 0) images << " ";
      images << point.x << " " << point.y << " ";
      if (point.point3D_id == kInvalidPoint3DId) {
        images << "-1";
      } else {
        images << point.point3D_id;
      }
    }
    images << "\n";
  }

  std::ostringstream points = MakeStream();
  points << "# 3D point list with one line of data per point:\n"
         << "#   POINT3D_ID, X, Y, Z, R, G, B, ERROR, TRACK[] as (IMAGE_ID, POINT2D_IDX)\n"
         << "# Number of points: " << model.points3D.size() << "\n";
  for (const SparsePoint3D& point : model.points3D) {
    points << point.point3D_id;
    for (double x : point.xyz) points << " " << x;
    for (uint8_t c : point.rgb) points << " " << static_cast<int>(c);
    points << " " << point.error;
    for (const TrackElement& element : point.track) {
      points << " " << element.image_id << " " << element.point2D_idx;
    }
    points << "\n";
  }

  WriteFileAtomic(JoinPaths(dir, "cameras.txt"), cameras.str());
  WriteFileAtomic(JoinPaths(dir, "images.txt"), images.str());
  WriteFileAtomic(JoinPaths(dir, "points3D.txt"), points.str());
}

}  // namespace msp
