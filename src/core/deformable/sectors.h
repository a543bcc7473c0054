// The sectors of the anchor search (docs/method.md sections 3.2 and 5): per
// sector, the directions of its rays and the angular span a snapped hit must
// stay in. The APD-MVS baseline uses 8 fixed sectors of 45 degrees; adaptive
// equidistribution (equidistribution.h) re-cuts them per pixel.
#pragma once

#include <cmath>

#include "core/deformable/deformable_limits.h"
#include "core/math/hd.h"

namespace msp {
namespace core {

constexpr float kSectorDegrees = 360.0f / kNumSectors;
constexpr float kDegToRad = 3.14159265358979f / 180.0f;
// A snapped hit must stay inside the ray's fixed sector: within half a sector
// (22.5 degrees) of the sector's central direction.
constexpr float kHalfSectorCos = 0.923879533f;  // cos(22.5 deg)

// A unit direction in the image plane.
struct RayDirection {
  float x, y;
};

MSP_HD RayDirection DirectionAt(float degrees) {
  return RayDirection{cosf(degrees * kDegToRad), sinf(degrees * kDegToRad)};
}

// The rays of every sector. A snapped hit at offset o from p lies inside
// sector k when o . centre[k] >= min_cos[k] |o|, i.e. within half the
// sector's span of its central direction.
struct SectorRays {
  int rays;  // per sector, 1..kMaxRaysPerSector
  RayDirection centre[kNumSectors];
  float min_cos[kNumSectors];
  RayDirection ray[kNumSectors * kMaxRaysPerSector];  // sector k's rays at k * rays + j
};

MSP_HD int ClampRaysPerSector(int rays) {
  return rays < 1 ? 1 : (rays > kMaxRaysPerSector ? kMaxRaysPerSector : rays);
}

// The fixed sectors of the baseline: sector k centred on k * 45 degrees, its
// rays spread evenly over it.
MSP_HD void FixedSectorRays(int rays_per_sector, SectorRays* out) {
  const int rays = ClampRaysPerSector(rays_per_sector);
  const float ray_step = kSectorDegrees / rays;
  out->rays = rays;
  for (int sector = 0; sector < kNumSectors; ++sector) {
    out->centre[sector] = DirectionAt(kSectorDegrees * sector);
    out->min_cos[sector] = kHalfSectorCos;
    for (int k = 0; k < rays; ++k) {
      const float degrees = kSectorDegrees * sector - 0.5f * kSectorDegrees + (k + 0.5f) * ray_step;
      out->ray[sector * rays + k] = DirectionAt(degrees);
    }
  }
}

}  // namespace core
}  // namespace msp
