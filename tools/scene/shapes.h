// Exact ray / primitive intersections for the scene's shape types.
#pragma once

#include <Eigen/Core>

#include "tools/scene/scene.h"

namespace msp {
namespace scene {

// Each returns true and fills t (> min_t) and the unit normal facing the ray
// origin (for a point on the surface) when the ray hits the shape; `face`
// (may be null for a box or a cylinder) gets the face hit (kMaxShapeFaces).
bool IntersectRoom(const Shape& room, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                   double min_t, double* t, Eigen::Vector3d* normal, int* face);
bool IntersectBox(const Shape& box, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                  double min_t, double* t, Eigen::Vector3d* normal, int* face = nullptr);
bool IntersectSphere(const Shape& sphere, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                     double min_t, double* t, Eigen::Vector3d* normal);
bool IntersectCylinder(const Shape& cyl, const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                       double min_t, double* t, Eigen::Vector3d* normal, int* face = nullptr);

}  // namespace scene
}  // namespace msp
