#include "tools/scene/scene.h"

#include <limits>

#include "tools/scene/shapes.h"

namespace msp {
namespace scene {
namespace {

// Materials of MakeRoomScene, by index.
enum MaterialId : int {
  kWall = 0,
  kFloor,
  kCeiling,
  kChecker,
  kNoise,
  kStripes,
  kPoster,
  kNumMaterials
};

Material Plain(const Eigen::Vector3d& albedo, double variation) {
  Material m;
  m.texture = Texture::kPlain;
  m.albedo1 = albedo;
  m.variation = variation;
  m.textureless = true;
  return m;
}

// Whether `p`, on face `face` of a room, lies in the room's window.
bool InOpening(const Shape& room, int face, const Eigen::Vector3d& p) {
  if (face != room.opening_face) return false;
  const int normal_axis = face / 2;
  for (int a = 0; a < 3; ++a) {
    if (a == normal_axis) continue;
    if (p[a] < room.opening_lo[a] || p[a] > room.opening_hi[a]) return false;
  }
  return true;
}

}  // namespace

Material Textured(Texture texture, const Eigen::Vector3d& a1, const Eigen::Vector3d& a2,
                  double scale) {
  Material m;
  m.texture = texture;
  m.albedo1 = a1;
  m.albedo2 = a2;
  m.scale = scale;
  return m;
}

Shape Box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, int material) {
  Shape s;
  s.type = ShapeType::kBox;
  s.lo = lo;
  s.hi = hi;
  s.material = material;
  return s;
}

Eigen::Vector3d RoomSize() { return Eigen::Vector3d(5.0, 5.0, 2.6); }

Scene MakeRoomScene(bool sky_window) {
  Scene scene;
  scene.materials.resize(kNumMaterials);
  // Walls, floor and ceiling vary by only 1-3 % over metres: well below what
  // an 11x11 NCC window can lock on to once camera noise is added.
  scene.materials[kWall] = Plain({0.78, 0.76, 0.72}, 0.02);
  scene.materials[kFloor] = Plain({0.52, 0.48, 0.43}, 0.03);
  scene.materials[kCeiling] = Plain({0.85, 0.85, 0.84}, 0.01);
  scene.materials[kChecker] =
      Textured(Texture::kChecker, {0.85, 0.25, 0.15}, {0.95, 0.92, 0.85}, 0.12);
  scene.materials[kNoise] = Textured(Texture::kNoise, {0.15, 0.35, 0.7}, {0.9, 0.85, 0.6}, 0.05);
  scene.materials[kStripes] = Textured(Texture::kStripes, {0.2, 0.6, 0.25}, {0.9, 0.9, 0.85}, 0.06);
  scene.materials[kPoster] = Textured(Texture::kNoise, {0.1, 0.1, 0.1}, {0.9, 0.7, 0.3}, 0.03);

  Shape room;
  room.type = ShapeType::kRoom;
  room.lo = Eigen::Vector3d::Zero();
  room.hi = RoomSize();
  const int faces[kNumRoomFaces] = {kWall, kWall, kWall, kWall, kFloor, kCeiling};
  for (int f = 0; f < kNumRoomFaces; ++f) room.face_material[f] = faces[f];
  if (sky_window) {
    // Above the sphere and the wall-coloured box at the y = 0 wall, up to the
    // ceiling: the sky meets the top border of the views that look up least,
    // and its outline against the wall is a roofline-like silhouette between
    // two untextured, bright regions.
    room.opening_face = 2;  // -y
    room.opening_lo = {1.25, 0.0, 1.25};
    room.opening_hi = {2.45, 0.0, RoomSize().z()};
  }
  scene.shapes.push_back(room);

  // Textured objects on the floor near the corner.
  scene.shapes.push_back(Box({0.7, 1.5, 0.0}, {1.3, 2.1, 0.55}, kChecker));
  Shape sphere;
  sphere.type = ShapeType::kSphere;
  sphere.center = {1.9, 0.8, 0.35};
  sphere.radius = 0.35;
  sphere.material = kNoise;
  scene.shapes.push_back(sphere);
  Shape cylinder;
  cylinder.type = ShapeType::kCylinder;
  cylinder.center = {0.55, 0.55, 0.0};
  cylinder.radius = 0.22;
  cylinder.lo = {0.0, 0.0, 0.0};
  cylinder.hi = {0.0, 0.0, 1.1};
  cylinder.material = kStripes;
  scene.shapes.push_back(cylinder);
  // A thin textured poster on the x = 0 wall.
  scene.shapes.push_back(Box({0.0, 1.3, 1.2}, {0.012, 2.0, 1.75}, kPoster));

  // Camouflage: boxes painted like the surface behind them, so their depth
  // edges have (almost) the same colour on both sides, and a low platform
  // painted like the floor.
  scene.shapes.push_back(Box({0.0, 2.5, 0.0}, {0.4, 3.2, 1.3}, kWall));
  scene.shapes.push_back(Box({2.6, 0.0, 0.0}, {3.3, 0.45, 0.9}, kWall));
  scene.shapes.push_back(Box({2.0, 1.8, 0.0}, {2.8, 2.6, 0.12}, kFloor));
  // More camouflage where every camera looks (the rig aims near (1.3, 1.3)),
  // so that edges between alike colours fill a measurable share of each
  // image: a free-standing wall-coloured panel 0.25 m in front of the x = 0
  // wall, taller than any camera so that its top face stays hidden and its
  // whole outline is its front face against the wall; and a floor-coloured
  // step whose far edges stand against the floor.
  scene.shapes.push_back(Box({0.25, 0.9, 0.0}, {0.27, 1.25, 2.0}, kWall));
  scene.shapes.push_back(Box({1.5, 1.3, 0.0}, {2.3, 1.7, 0.15}, kFloor));

  // Light near the ceiling above the cameras: smooth shading gradients over
  // the walls, no shadows (they would add texture to the floor).
  scene.light.position = {3.5, 3.0, 2.4};
  scene.light.diffuse = 0.6;
  scene.light.ambient = 0.35;
  return scene;
}

bool Scene::Intersect(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir, Hit* hit,
                      double min_t) const {
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector3d best_n = Eigen::Vector3d::Zero();
  int best_material = -1;
  int best_shape = -1;
  int best_face = -1;
  for (size_t i = 0; i < shapes.size(); ++i) {
    const Shape& shape = shapes[i];
    double t = 0.0;
    Eigen::Vector3d n;
    bool ok = false;
    int material = shape.material;
    int face = 0;
    switch (shape.type) {
      case ShapeType::kRoom: {
        ok = IntersectRoom(shape, origin, dir, min_t, &t, &n, &face) &&
             !InOpening(shape, face, origin + t * dir);
        if (ok) material = shape.face_material[face];
        break;
      }
      case ShapeType::kBox:
        ok = IntersectBox(shape, origin, dir, min_t, &t, &n, &face);
        break;
      case ShapeType::kSphere:
        ok = IntersectSphere(shape, origin, dir, min_t, &t, &n);
        break;
      case ShapeType::kCylinder:
        ok = IntersectCylinder(shape, origin, dir, min_t, &t, &n, &face);
        break;
    }
    if (ok && t < best) {
      best = t;
      best_n = n;
      best_material = material;
      best_shape = static_cast<int>(i);
      best_face = face;
    }
  }
  if (best_material < 0) return false;
  hit->t = best;
  hit->point = origin + best * dir;
  hit->normal = best_n;
  hit->material = best_material;
  hit->shape = best_shape;
  hit->face = best_face;
  return true;
}

}  // namespace scene
}  // namespace msp
