#include "tools/evaluate/ply_points.h"

#include <cstring>
#include <fstream>
#include <sstream>

#include "io/errors.h"

namespace msp {
namespace eval {
namespace {

struct Property {
  std::string name;
  int size = 0;  // bytes in binary files
  bool is_float = false;
  bool is_signed = false;
};

bool TypeInfo(const std::string& type, Property* p) {
  struct Entry {
    const char* names[2];
    int size;
    bool is_float;
    bool is_signed;
  };
  static const Entry kTypes[] = {
      {{"char", "int8"}, 1, false, true},    {{"uchar", "uint8"}, 1, false, false},
      {{"short", "int16"}, 2, false, true},  {{"ushort", "uint16"}, 2, false, false},
      {{"int", "int32"}, 4, false, true},    {{"uint", "uint32"}, 4, false, false},
      {{"float", "float32"}, 4, true, true}, {{"double", "float64"}, 8, true, true},
  };
  for (const Entry& e : kTypes) {
    if (type == e.names[0] || type == e.names[1]) {
      p->size = e.size;
      p->is_float = e.is_float;
      p->is_signed = e.is_signed;
      return true;
    }
  }
  return false;
}

// Little-endian binary value of property p at `data` as double.
double DecodeBinary(const Property& p, const char* data) {
  // Hosts are little endian (x86-64, arm64), as COLMAP assumes when writing.
  if (p.is_float) {
    if (p.size == 4) {
      float f;
      std::memcpy(&f, data, 4);
      return f;
    }
    double d;
    std::memcpy(&d, data, 8);
    return d;
  }
  uint64_t u = 0;
  std::memcpy(&u, data, p.size);
  if (p.is_signed && p.size < 8 && (u >> (8 * p.size - 1)) & 1u) {
    u |= ~((uint64_t{1} << (8 * p.size)) - 1);  // sign-extend
  }
  return p.is_signed ? static_cast<double>(static_cast<int64_t>(u)) : static_cast<double>(u);
}

}  // namespace

PlyPoints ReadPlyPoints(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError("cannot read point cloud " + path);
  std::string line;
  std::getline(file, line);
  if (line.rfind("ply", 0) != 0) throw InputError(path + ": not a PLY file");
  bool binary = false, in_vertex = false;
  size_t num_vertices = 0;
  std::vector<Property> props;
  while (std::getline(file, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream s(line);
    std::string word;
    s >> word;
    if (word == "format") {
      std::string format;
      s >> format;
      if (format == "binary_little_endian") {
        binary = true;
      } else if (format != "ascii") {
        throw InputError(path + ": unsupported PLY format " + format);
      }
    } else if (word == "element") {
      std::string element;
      size_t count = 0;
      s >> element >> count;
      // Only a leading vertex element can be read without parsing the rest.
      if (element == "vertex") {
        if (!props.empty() || in_vertex) throw InputError(path + ": vertex must be first");
        num_vertices = count;
        in_vertex = true;
      } else {
        in_vertex = false;
      }
    } else if (word == "property" && in_vertex) {
      std::string type;
      Property p;
      s >> type >> p.name;
      if (type == "list" || !TypeInfo(type, &p)) {
        throw InputError(path + ": unsupported vertex property type " + type);
      }
      props.push_back(p);
    } else if (word == "end_header") {
      break;
    }
  }
  int index[4] = {-1, -1, -1, -1};  // x, y, z, num_views
  const char* wanted[4] = {"x", "y", "z", "num_views"};
  size_t stride = 0;
  for (size_t i = 0; i < props.size(); ++i) {
    for (int k = 0; k < 4; ++k) {
      if (props[i].name == wanted[k]) index[k] = static_cast<int>(i);
    }
    stride += props[i].size;
  }
  if (index[0] < 0 || index[1] < 0 || index[2] < 0) {
    throw InputError(path + ": vertex element lacks x, y or z");
  }
  PlyPoints out;
  out.points.resize(num_vertices);
  if (index[3] >= 0) out.num_views.resize(num_vertices);
  std::vector<double> values(props.size());
  std::vector<char> buffer(stride);
  for (size_t v = 0; v < num_vertices; ++v) {
    if (binary) {
      if (!file.read(buffer.data(), static_cast<std::streamsize>(stride))) {
        throw InputError(path + ": truncated after " + std::to_string(v) + " vertices");
      }
      size_t offset = 0;
      for (size_t i = 0; i < props.size(); ++i) {
        values[i] = DecodeBinary(props[i], buffer.data() + offset);
        offset += props[i].size;
      }
    } else {
      for (size_t i = 0; i < props.size(); ++i) {
        if (!(file >> values[i])) {
          throw InputError(path + ": truncated after " + std::to_string(v) + " vertices");
        }
      }
    }
    out.points[v] =
        Eigen::Vector3f(static_cast<float>(values[index[0]]), static_cast<float>(values[index[1]]),
                        static_cast<float>(values[index[2]]));
    if (index[3] >= 0) out.num_views[v] = static_cast<uint8_t>(values[index[3]]);
  }
  return out;
}

}  // namespace eval
}  // namespace msp
