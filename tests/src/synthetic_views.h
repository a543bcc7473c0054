// Views of a textured plane rendered analytically, for driver tests.
#pragma once

#include <vector>

#include "base/mvs_input.h"

namespace msp {
namespace testing_support {

// `num_views` cameras (the first is the reference at the origin looking down
// +z) seeing the plane z = plane_depth covered with smooth random texture
// (grey, and a colour image whose hue follows the grey value).
// Sources sit on a circle of radius `baseline` in the z = 0 plane.
std::vector<View> RenderFrontoParallelPlane(int width, int height, int num_views, float plane_depth,
                                            float baseline);

core::Camera MakeTestCamera(int width, int height, core::Vec3 center);

}  // namespace testing_support
}  // namespace msp
