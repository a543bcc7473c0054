#include "patch_match/pixel_state_io.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace msp {
namespace {

// "MSPS" and the layout version: a file of another kind or version is refused.
constexpr uint32_t kMagic = 0x5350534d;
constexpr uint32_t kVersion = 2;
// Refuses headers whose pixel count cannot be a state of this program.
constexpr int64_t kMaxPixels = int64_t(1) << 31;

struct Header {
  uint32_t magic;
  uint32_t version;
  int32_t width;
  int32_t height;
  uint8_t has_edges;
  uint8_t has_classes;
  uint8_t has_previous_depth;
  uint8_t padding;
};

template <typename T>
void Append(const std::vector<T>& v, std::string* out) {
  out->append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

// Reads v->size() elements at *offset; false when the bytes run out.
template <typename T>
bool Extract(const std::string& bytes, size_t* offset, std::vector<T>* v) {
  const size_t size = v->size() * sizeof(T);
  if (bytes.size() - *offset < size) return false;
  std::memcpy(v->data(), bytes.data() + *offset, size);
  *offset += size;
  return true;
}

}  // namespace

std::string SerializePixelState(const PixelState& state) {
  Header header{};
  header.magic = kMagic;
  header.version = kVersion;
  header.width = state.width;
  header.height = state.height;
  header.has_edges = state.edges.empty() ? 0 : 1;
  header.has_classes = state.classes.empty() ? 0 : 1;
  header.has_previous_depth = state.previous_depth.empty() ? 0 : 1;
  std::string bytes(reinterpret_cast<const char*>(&header), sizeof(header));
  bytes.reserve(sizeof(header) + state.Bytes());
  Append(state.depth, &bytes);
  Append(state.normal, &bytes);
  Append(state.cost, &bytes);
  Append(state.mask, &bytes);
  Append(state.edges, &bytes);
  Append(state.classes, &bytes);
  Append(state.previous_depth, &bytes);
  return bytes;
}

bool DeserializePixelState(const std::string& bytes, PixelState* state) {
  Header header{};
  if (bytes.size() < sizeof(header)) return false;
  std::memcpy(&header, bytes.data(), sizeof(header));
  const int64_t pixels = static_cast<int64_t>(header.width) * header.height;
  if (header.magic != kMagic || header.version != kVersion || header.width < 0 ||
      header.height < 0 || pixels > kMaxPixels) {
    return false;
  }
  const size_t n = static_cast<size_t>(pixels);
  // Per pixel: depth, 3 normal components and cost (floats), the view mask,
  // then the optional byte planes and the optional depth the pass started from.
  const size_t expected = sizeof(header) + n * (5 * sizeof(float) + sizeof(uint32_t)) +
                          (header.has_edges ? n : 0) + (header.has_classes ? n : 0) +
                          (header.has_previous_depth ? n * sizeof(float) : 0);
  if (bytes.size() != expected) return false;
  *state = PixelState(header.width, header.height);
  if (header.has_edges) state->edges.resize(n);
  if (header.has_classes) state->classes.resize(n);
  if (header.has_previous_depth) state->previous_depth.resize(n);
  size_t offset = sizeof(header);
  return Extract(bytes, &offset, &state->depth) && Extract(bytes, &offset, &state->normal) &&
         Extract(bytes, &offset, &state->cost) && Extract(bytes, &offset, &state->mask) &&
         Extract(bytes, &offset, &state->edges) && Extract(bytes, &offset, &state->classes) &&
         Extract(bytes, &offset, &state->previous_depth);
}

}  // namespace msp
