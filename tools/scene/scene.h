// The bundled test scene: a closed room (walls, floor, ceiling) with a few
// objects, described analytically so that rays can be cast exactly. Geometry
// and materials only; images and ground truth are made by renderer.h.
//
// World frame: metres, z up, the floor is z = 0 and the inspected corner is at
// the origin (walls x = 0 and y = 0).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace msp {
namespace scene {

enum class Texture {
  kPlain,    // albedo1 with a faint low-frequency variation (walls, floor)
  kChecker,  // 3D checker of albedo1 / albedo2 with period `scale`
  kNoise,    // fractal value noise blending albedo1 and albedo2, feature size `scale`
  kStripes,  // horizontal bands of albedo1 / albedo2, period `scale`
};

struct Material {
  Texture texture = Texture::kPlain;
  Eigen::Vector3d albedo1 = Eigen::Vector3d::Constant(0.7);
  Eigen::Vector3d albedo2 = Eigen::Vector3d::Constant(0.3);
  double scale = 0.1;      // metres, see Texture
  double variation = 0.0;  // kPlain: relative amplitude of the low-frequency variation
  // Ground-truth label: surfaces with no usable texture (MSP-MVS's target).
  bool textureless = false;
};

enum class ShapeType {
  kRoom,      // axis-aligned box seen from inside; face_material per face
  kBox,       // axis-aligned box seen from outside
  kSphere,    // center, radius
  kCylinder,  // vertical: axis through center.xy, z in [lo.z, hi.z], radius
};

// Face order of kRoom: -x, +x, -y, +y, -z (floor), +z (ceiling).
constexpr int kNumRoomFaces = 6;
// Faces of a shape (Hit::face): a room's or a box's six in the room's order
// (a box's by its outward normal), the sphere's one (0), a cylinder's side
// (0), bottom cap (1) and top cap (2).
constexpr int kMaxShapeFaces = 6;

struct Shape {
  ShapeType type = ShapeType::kBox;
  Eigen::Vector3d lo = Eigen::Vector3d::Zero();
  Eigen::Vector3d hi = Eigen::Vector3d::Zero();
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0.0;
  int material = 0;
  int face_material[kNumRoomFaces] = {0, 0, 0, 0, 0, 0};
  // kRoom: a window. A ray that reaches face `opening_face` (-1: none) inside
  // the box [opening_lo, opening_hi] leaves the room and sees the sky.
  int opening_face = -1;
  Eigen::Vector3d opening_lo = Eigen::Vector3d::Zero();
  Eigen::Vector3d opening_hi = Eigen::Vector3d::Zero();
};

struct Hit {
  double t = 0.0;          // ray parameter (the direction is unit length)
  Eigen::Vector3d point;   // world point
  Eigen::Vector3d normal;  // unit, facing the ray origin
  int material = -1;
  int shape = -1;  // index in Scene::shapes
  int face = -1;   // face of that shape, see kMaxShapeFaces
};

// What a ray that hits nothing sees (Scene::SkyRadiance). Every kind is open
// sky: its pixels' ground truth is empty, whatever their colour.
enum class SkyKind {
  kPale,      // the bundled scene's: pale at the horizon to light blue overhead
  kBlue,      // a deeper daylight gradient, darker than the facades' highlights
  kOvercast,  // white-grey, brighter at the horizon: as bright as a white wall
  kClouds,    // kBlue with soft white clouds: smooth, but not one colour
};

struct Light {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double diffuse = 0.6;
  double ambient = 0.35;
};

class Scene {
 public:
  std::vector<Material> materials;
  std::vector<Shape> shapes;
  Light light;
  SkyKind sky = SkyKind::kPale;

  // Nearest intersection with t > min_t along origin + t * dir (dir unit length).
  bool Intersect(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, Hit* hit,
                 double min_t = 1e-9) const;

  // Linear-space reflectance of `material` at world point p.
  Eigen::Vector3d Albedo(int material, const Eigen::Vector3d& p) const;

  // Which of the two colours of a two-colour pattern (kChecker, kStripes)
  // covers p: 0 = albedo1, 1 = albedo2. 0 for kPlain and kNoise, whose colour
  // varies without edges.
  int Paint(int material, const Eigen::Vector3d& p) const;

  // Lambertian shading (point light + ambient) of a hit, before camera noise.
  Eigen::Vector3d Radiance(const Hit& hit) const;

  // What a ray that hits nothing sees (unit direction `dir`): the sky of
  // kind `sky`, smooth and without depth (sky.cc).
  Eigen::Vector3d SkyRadiance(const Eigen::Vector3d& dir) const;
};

// A material of `texture` between albedos a1 and a2 at feature size `scale`.
Material Textured(Texture texture, const Eigen::Vector3d& a1, const Eigen::Vector3d& a2,
                  double scale);

// An axis-aligned box [lo, hi] seen from outside, of material `material`.
Shape Box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, int material);

// Room of kRoomSize with the textured and the camouflaged objects; with
// `sky_window`, a window in the y = 0 wall through which every view sees open
// sky (pixels whose ground truth is empty: nothing is there to reconstruct).
Scene MakeRoomScene(bool sky_window = true);

// Size of the room of MakeRoomScene (x, y, z extent in metres).
Eigen::Vector3d RoomSize();

}  // namespace scene
}  // namespace msp
