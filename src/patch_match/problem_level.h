// The images and cameras one problem (a reference view and its sources) needs
// at one pyramid level, built when the problem's pass starts and dropped after
// it, so that the memory of a run's images does not grow with their number.
#pragma once

#include <map>
#include <vector>

#include "base/dense_map.h"
#include "base/mvs_input.h"
#include "core/math/camera.h"

namespace msp {

// Images and cameras of some views at one pyramid level, by view index;
// colour only where asked for.
struct Level {
  std::map<int, DenseMap> gray;
  std::map<int, DenseMap> color;
  std::map<int, core::Camera> cameras;
};

// `view`'s camera halved `halvings` times, as for its image halved as often.
core::Camera LevelCamera(const View& view, int halvings);

// The grey images and cameras of `ids` (indices into `views`) halved
// `halvings` times, with the colour image of `color_view` too unless it is
// -1. An image the view does not hold is given by its load_images.
// Throws std::invalid_argument naming the view when the colour image is
// missing or of another size than the grey one.
Level BuildLevel(const std::vector<View>& views, const std::vector<int>& ids, int color_view,
                 int halvings);

}  // namespace msp
