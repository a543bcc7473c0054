#include "tools/scene/shapes.h"

#include <cmath>
#include <limits>

namespace msp {
namespace scene {
namespace {

// Directions closer than this to parallel with a slab or cap never hit it.
constexpr double kParallelEpsilon = 1e-12;

Eigen::Vector3d FaceTowards(const Eigen::Vector3d& n, const Eigen::Vector3d& d) {
  return n.dot(d) > 0.0 ? Eigen::Vector3d(-n) : n;
}

}  // namespace

bool IntersectRoom(const Shape& room, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                   double min_t, double* t, Eigen::Vector3d* normal, int* face) {
  // Seen from inside, the ray leaves through the first face it reaches on
  // each axis in its direction of travel.
  double best = std::numeric_limits<double>::infinity();
  int best_axis = -1;
  bool best_positive = false;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < kParallelEpsilon) continue;
    const bool positive = d[a] > 0.0;
    const double ta = ((positive ? room.hi[a] : room.lo[a]) - o[a]) / d[a];
    if (ta > min_t && ta < best) {
      best = ta;
      best_axis = a;
      best_positive = positive;
    }
  }
  if (best_axis < 0) return false;
  *t = best;
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  n[best_axis] = best_positive ? -1.0 : 1.0;
  *normal = n;
  *face = 2 * best_axis + (best_positive ? 1 : 0);
  return true;
}

bool IntersectBox(const Shape& box, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                  double min_t, double* t, Eigen::Vector3d* normal, int* face) {
  double t_near = -std::numeric_limits<double>::infinity();
  double t_far = std::numeric_limits<double>::infinity();
  int near_axis = -1;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < kParallelEpsilon) {
      if (o[a] < box.lo[a] || o[a] > box.hi[a]) return false;
      continue;
    }
    double t1 = (box.lo[a] - o[a]) / d[a];
    double t2 = (box.hi[a] - o[a]) / d[a];
    if (t1 > t2) std::swap(t1, t2);
    if (t1 > t_near) {
      t_near = t1;
      near_axis = a;
    }
    t_far = std::min(t_far, t2);
  }
  // Only entering hits: the scene never puts a camera inside an object.
  if (near_axis < 0 || t_near > t_far || t_near <= min_t) return false;
  *t = t_near;
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  n[near_axis] = d[near_axis] > 0.0 ? -1.0 : 1.0;
  *normal = n;
  if (face) *face = 2 * near_axis + (d[near_axis] > 0.0 ? 0 : 1);
  return true;
}

bool IntersectSphere(const Shape& sphere, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                     double min_t, double* t, Eigen::Vector3d* normal) {
  const Eigen::Vector3d oc = o - sphere.center;
  const double b = oc.dot(d);
  const double c = oc.squaredNorm() - sphere.radius * sphere.radius;
  const double disc = b * b - c;
  if (disc < 0.0) return false;
  const double s = std::sqrt(disc);
  double root = -b - s;
  if (root <= min_t) root = -b + s;
  if (root <= min_t) return false;
  *t = root;
  *normal = FaceTowards((o + root * d - sphere.center) / sphere.radius, d);
  return true;
}

bool IntersectCylinder(const Shape& cyl, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                       double min_t, double* t, Eigen::Vector3d* normal, int* face) {
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector3d best_n = Eigen::Vector3d::Zero();
  int best_face = 0;  // side
  const double r2 = cyl.radius * cyl.radius;
  // Side: (ox + t dx - cx)^2 + (oy + t dy - cy)^2 = r^2, clipped to the z range.
  const double ox = o.x() - cyl.center.x();
  const double oy = o.y() - cyl.center.y();
  const double a = d.x() * d.x() + d.y() * d.y();
  if (a > kParallelEpsilon) {
    const double b = ox * d.x() + oy * d.y();
    const double c = ox * ox + oy * oy - r2;
    const double disc = b * b - a * c;
    if (disc >= 0.0) {
      const double s = std::sqrt(disc);
      for (const double root : {(-b - s) / a, (-b + s) / a}) {
        if (root <= min_t || root >= best) continue;
        const double z = o.z() + root * d.z();
        if (z < cyl.lo.z() || z > cyl.hi.z()) continue;
        best = root;
        best_n = Eigen::Vector3d(ox + root * d.x(), oy + root * d.y(), 0.0) / cyl.radius;
        best_face = 0;
      }
    }
  }
  // Caps.
  if (std::abs(d.z()) > kParallelEpsilon) {
    for (const int cap : {1, 2}) {  // bottom, top
      const double zc = cap == 1 ? cyl.lo.z() : cyl.hi.z();
      const double root = (zc - o.z()) / d.z();
      if (root <= min_t || root >= best) continue;
      const double px = ox + root * d.x();
      const double py = oy + root * d.y();
      if (px * px + py * py > r2) continue;
      best = root;
      best_n = Eigen::Vector3d(0.0, 0.0, 1.0);
      best_face = cap;
    }
  }
  if (!std::isfinite(best)) return false;
  *t = best;
  *normal = FaceTowards(best_n, d);
  if (face) *face = best_face;
  return true;
}

}  // namespace scene
}  // namespace msp
