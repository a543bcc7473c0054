// What the stereo back-ends consume: views (camera + images at the working
// resolution) and problems (a reference view, its source views and its depth
// range). io/workspace.h fills these from a workspace; nothing here knows files.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "base/dense_map.h"
#include "base/label_layers.h"
#include "core/math/camera.h"

namespace msp {

struct View {
  std::string name;     // image name as in the sparse model, e.g. "sub/a.jpg"
  core::Camera camera;  // intrinsics scaled to the working resolution
  DenseMap gray;        // 1 channel, values in [0, 1], camera.width x camera.height
  DenseMap color;       // 3 channels RGB in [0, 1], same size (segmentation prior)
  // Gives gray and color, each unless null, where they are empty here:
  // converted from a smaller form kept in memory (the colour of an image at
  // its own size), or read again from the image file (a workspace larger
  // than the image share of --PatchMatchStereo.cache_size keeps only part of
  // its images in memory). Empty = the images above are all there is.
  std::function<void(DenseMap* gray, DenseMap* color)> load_images;
  // Segmentation mask layers of the prior at the working resolution, read by
  // io/mask_layers.h for reference views; kEmbeddedSegmenter (layers empty) = the
  // prior segments `color` itself at every round's resolution.
  ImageLabelLayers mask_layers;
};

struct Problem {
  int ref = -1;           // index into the views
  std::vector<int> srcs;  // indices into the views, best first
  float depth_min = 0.0f;
  float depth_max = 0.0f;
};

}  // namespace msp
