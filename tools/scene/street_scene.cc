#include "tools/scene/street_scene.h"

namespace msp {
namespace scene {
namespace {

enum MaterialId : int { kRoad = 0, kBrick, kPanels, kTower, kTrunk, kLeaves, kNumMaterials };

}  // namespace

Scene MakeStreetScene(SkyKind sky) {
  Scene scene;
  scene.sky = sky;
  scene.materials.resize(kNumMaterials);
  // Every surface is textured: the sky is the only region without evidence,
  // so a depth there is the sky's error, not a wall's.
  scene.materials[kRoad] = Textured(Texture::kNoise, {0.22, 0.22, 0.23}, {0.5, 0.49, 0.47}, 0.04);
  scene.materials[kBrick] = Textured(Texture::kNoise, {0.5, 0.27, 0.2}, {0.85, 0.7, 0.55}, 0.06);
  scene.materials[kPanels] =
      Textured(Texture::kChecker, {0.35, 0.36, 0.42}, {0.8, 0.78, 0.7}, 0.15);
  scene.materials[kTower] = Textured(Texture::kStripes, {0.62, 0.62, 0.66}, {0.3, 0.3, 0.36}, 0.12);
  scene.materials[kTrunk] = Textured(Texture::kNoise, {0.25, 0.18, 0.1}, {0.5, 0.4, 0.3}, 0.03);
  scene.materials[kLeaves] = Textured(Texture::kNoise, {0.1, 0.3, 0.08}, {0.5, 0.7, 0.3}, 0.04);

  // The road, wide enough that no view sees past its edge below the horizon.
  scene.shapes.push_back(Box({-4.0, -4.0, -0.1}, {12.0, 12.0, 0.0}, kRoad));
  // Two buildings of different heights whose facades meet at the corner;
  // their roofs are above every camera, so the roofline is the facade's top
  // edge against the sky.
  scene.shapes.push_back(Box({-4.0, 0.0, 0.0}, {0.0, 2.8, 2.9}, kBrick));
  scene.shapes.push_back(Box({0.0, -4.0, 0.0}, {3.0, 0.0, 2.2}, kPanels));
  // A tower behind the corner: vertical outlines with sky on both sides.
  scene.shapes.push_back(Box({-2.2, -2.2, 0.0}, {-1.4, -1.4, 4.6}, kTower));
  // A tree past the brick building's end: a round outline against the sky.
  Shape trunk;
  trunk.type = ShapeType::kCylinder;
  trunk.center = {0.7, 3.6, 0.0};
  trunk.radius = 0.1;
  trunk.lo = {0.0, 0.0, 0.0};
  trunk.hi = {0.0, 0.0, 1.7};
  trunk.material = kTrunk;
  scene.shapes.push_back(trunk);
  Shape crown;
  crown.type = ShapeType::kSphere;
  crown.center = {0.7, 3.6, 2.1};
  crown.radius = 0.6;
  crown.material = kLeaves;
  scene.shapes.push_back(crown);

  // Daylight from high above the street.
  scene.light.position = {8.0, 6.0, 12.0};
  scene.light.diffuse = 0.55;
  scene.light.ambient = 0.45;
  return scene;
}

RigOptions StreetRig(RigOptions rig) {
  rig.look_at = Eigen::Vector3d(1.1, 1.1, 1.7);
  return rig;
}

}  // namespace scene
}  // namespace msp
