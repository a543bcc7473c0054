#include "patch_match/problem_level.h"

#include <stdexcept>
#include <utility>

#include "patch_match/image_pyramid.h"

namespace msp {
namespace {

DenseMap Halved(DenseMap image, int halvings) {
  for (int h = 0; h < halvings; ++h) image = DownsampleHalf(image);
  return image;
}

}  // namespace

core::Camera LevelCamera(const View& view, int halvings) {
  core::Camera camera = view.camera;
  for (int h = 0; h < halvings; ++h) {
    camera = HalveCamera(camera, camera.width / 2, camera.height / 2);
  }
  return camera;
}

Level BuildLevel(const std::vector<View>& views, const std::vector<int>& ids, int color_view,
                 int halvings) {
  Level level;
  for (int v : ids) {
    const View& view = views[v];
    const bool with_color = v == color_view;
    // Images beyond the cache's share live only for this call.
    DenseMap gray, color;
    const bool in_memory = !view.gray.Empty() || !view.load_images;
    if (!in_memory) view.load_images(&gray, with_color ? &color : nullptr);
    const DenseMap& full_gray = in_memory ? view.gray : gray;
    const DenseMap& full_color = in_memory ? view.color : color;
    if (with_color && (full_color.channels != 3 || full_color.width != full_gray.width ||
                       full_color.height != full_gray.height)) {
      throw std::invalid_argument("view " + view.name +
                                  ": the segmentation prior and segment planes need its RGB image");
    }
    level.gray.emplace(v, Halved(in_memory ? view.gray : std::move(gray), halvings));
    if (with_color)
      level.color.emplace(v, Halved(in_memory ? view.color : std::move(color), halvings));
    level.cameras.emplace(v, LevelCamera(view, halvings));
  }
  return level;
}

}  // namespace msp
