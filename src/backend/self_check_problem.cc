#include "backend/self_check_problem.h"

#include <cmath>
#include <cstdint>
#include <utility>

#include "base/value_noise.h"
#include "core/math/camera.h"
#include "core/math/homography.h"
#include "core/math/rng.h"
#include "options/stereo_options.h"

namespace msp {
namespace {

// 64 x 48: 3,072 pixels, so that one pixel is 0.03 % of the image, well
// below the share of differing pixels the check allows (device_self_check.cc).
constexpr int kWidth = 64, kHeight = 48;
// The plane n . X = kPlaneOffset (world = reference frame): 2 m in front
// of the reference, tilted about both axes, so that neither the depth nor
// the normal is the same at every pixel.
constexpr float kPlaneNormal[3] = {0.2f, -0.15f, -1.0f};
constexpr float kPlaneDepthAtCentre = 2.0f;
// The sources' centres (world, metres): baselines of 0.2-0.25 m at 2 m,
// about 6-7 px of disparity per pixel of depth change at this focal length.
constexpr float kSourceCentres[2][3] = {{0.25f, 0.0f, 0.0f}, {-0.2f, 0.15f, 0.05f}};
// Focal length as a share of the width (a 58-degree field of view).
constexpr float kFocalPerWidth = 0.9f;
// The texture: value noise of this many cells per metre, about 2 px a cell
// at 2 m; with a coarser octave so every window sees contrast.
constexpr float kCellsPerMetre = 30.0f;
constexpr uint64_t kTextureSeed = 0x5E1FC4EC;
// The pass: a depth range around the plane; the cost and the view sampling
// are the options' defaults (see Params); the refinement's perturbations
// ACMM's +-2 % depth and +-1.8 degrees of normal, as patch_match/pass_runner.cc.
constexpr float kDepthMin = 1.0f, kDepthMax = 4.0f;
constexpr float kPerturbDepth = 0.02f, kPerturbNormal = 1.8f * 3.14159265f / 180.0f;
constexpr uint32_t kSeed = 0x5E1F;

core::Camera MakeCamera(const float centre[3]) {
  core::Camera cam;
  cam.width = kWidth;
  cam.height = kHeight;
  cam.fx = cam.fy = kFocalPerWidth * kWidth;
  cam.cx = 0.5f * kWidth;
  cam.cy = 0.5f * kHeight;
  cam.R = core::Mat3{{1, 0, 0, 0, 1, 0, 0, 0, 1}};
  cam.center = core::Vec3{centre[0], centre[1], centre[2]};
  cam.t = -core::Mul(cam.R, cam.center);
  return cam;
}

float Texture(const core::Vec3& X) {
  const float x = X.x * kCellsPerMetre, y = X.y * kCellsPerMetre;
  return 0.7f * ValueNoise(x, y, kTextureSeed) +
         0.3f * ValueNoise(0.3f * x + 7.0f, 0.3f * y, kTextureSeed);
}

// Where the ray of pixel (col, row) of `cam` meets the plane (world).
core::Vec3 OnPlane(const core::Camera& cam, int col, int row) {
  const core::Vec3 n{kPlaneNormal[0], kPlaneNormal[1], kPlaneNormal[2]};
  const float offset = core::Dot(n, core::Vec3{0.0f, 0.0f, kPlaneDepthAtCentre});
  const core::Vec3 dir = core::MulTransposed(
      cam.R, core::ViewRay(cam, static_cast<float>(col), static_cast<float>(row)));
  const float s = (offset - core::Dot(n, cam.center)) / core::Dot(n, dir);
  return cam.center + s * dir;
}

core::ImageView ViewOf(const std::vector<float>& image) {
  return core::ImageView{image.data(), kWidth, kHeight, kWidth};
}

}  // namespace

SelfCheckProblem::SelfCheckProblem() : width_(kWidth), height_(kHeight) {
  const float origin[3] = {0.0f, 0.0f, 0.0f};
  cameras_.push_back(MakeCamera(origin));
  for (const float* centre : kSourceCentres) cameras_.push_back(MakeCamera(centre));
  for (const core::Camera& cam : cameras_) {
    std::vector<float> image(kWidth * kHeight), depth(kWidth * kHeight);
    for (int row = 0; row < kHeight; ++row) {
      for (int col = 0; col < kWidth; ++col) {
        const core::Vec3 X = OnPlane(cam, col, row);
        image[row * kWidth + col] = Texture(X);
        depth[row * kWidth + col] = core::WorldToCam(cam, X).z;
      }
    }
    images_.push_back(std::move(image));
    plane_depth_.push_back(std::move(depth));
  }
}

core::PassParams SelfCheckProblem::Params(bool geometric, PixelState* state) const {
  core::PassParams p{};
  p.ref_camera = cameras_[0];
  p.ref_image = ViewOf(images_[0]);
  p.num_src = static_cast<int>(cameras_.size()) - 1;
  for (int j = 0; j < p.num_src; ++j) {
    core::SourceView& src = p.src[j];
    src.camera = cameras_[j + 1];
    src.rel = core::ComputeRelativePose(p.ref_camera, src.camera);
    src.image = ViewOf(images_[j + 1]);
    src.depth = geometric ? ViewOf(plane_depth_[j + 1]) : core::ImageView{nullptr, 0, 0, 0};
  }
  // The default cost window and view sampling, as a run with default options
  // builds them (patch_match/pass_runner.cc).
  const PatchMatchStereoOptions pm;
  const MspStereoOptions msp;
  p.ncc.window_radius = pm.window_radius;
  p.ncc.window_step = msp.window_step;
  p.ncc.bilateral = msp.bilateral_ncc ? 1 : 0;
  p.ncc.sigma_spatial =
      static_cast<float>(pm.sigma_spatial > 0 ? pm.sigma_spatial : pm.window_radius);
  p.ncc.sigma_color = static_cast<float>(pm.sigma_color);
  p.depth_min = kDepthMin;
  p.depth_max = kDepthMax;
  p.geometric = geometric ? 1 : 0;
  p.geom_lambda = static_cast<float>(pm.geom_consistency_regularizer);
  p.geom_max_error = static_cast<float>(pm.geom_consistency_max_cost);
  p.num_samples = pm.num_samples;
  p.perturb_depth = kPerturbDepth;
  p.perturb_normal = kPerturbNormal;
  p.seed = kSeed;
  p.state = state->View();
  return p;
}

}  // namespace msp
