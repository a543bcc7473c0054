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
    // What the view does not hold, load_images gives, for this call only.
    const bool load_gray = view.gray.Empty() && view.load_images;
    const bool load_color = with_color && view.color.Empty() && view.load_images;
    DenseMap gray, color;
    if (load_gray || load_color) {
      view.load_images(load_gray ? &gray : nullptr, load_color ? &color : nullptr);
    }
    const DenseMap& full_gray = load_gray ? gray : view.gray;
    const DenseMap& full_color = load_color ? color : view.color;
    if (with_color && (full_color.channels != 3 || full_color.width != full_gray.width ||
                       full_color.height != full_gray.height)) {
      throw std::invalid_argument("view " + view.name +
                                  ": the segmentation prior and segment planes need its RGB image");
    }
    level.gray.emplace(v, Halved(load_gray ? std::move(gray) : view.gray, halvings));
    if (with_color)
      level.color.emplace(v, Halved(load_color ? std::move(color) : view.color, halvings));
    level.cameras.emplace(v, LevelCamera(view, halvings));
  }
  return level;
}

}  // namespace msp
