// Small fixed-size float vector / matrix math for the per-pixel code.
#pragma once

#include <cmath>

#include "core/math/hd.h"

namespace msp {
namespace core {

struct Vec2 {
  float x, y;
};

struct Vec3 {
  float x, y, z;
};

// Row-major 3x3 matrix.
struct Mat3 {
  float m[9];
};

MSP_HD Vec3 operator+(Vec3 a, Vec3 b) { return Vec3{a.x + b.x, a.y + b.y, a.z + b.z}; }
MSP_HD Vec3 operator-(Vec3 a, Vec3 b) { return Vec3{a.x - b.x, a.y - b.y, a.z - b.z}; }
MSP_HD Vec3 operator*(float s, Vec3 a) { return Vec3{s * a.x, s * a.y, s * a.z}; }
MSP_HD Vec3 operator-(Vec3 a) { return Vec3{-a.x, -a.y, -a.z}; }
MSP_HD float Dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
MSP_HD Vec3 Cross(Vec3 a, Vec3 b) {
  return Vec3{a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
MSP_HD float Norm(Vec3 a) { return sqrtf(Dot(a, a)); }
MSP_HD Vec3 Normalized(Vec3 a) {
  const float n = Norm(a);
  return n > 0.0f ? (1.0f / n) * a : a;
}

MSP_HD Vec3 Mul(const Mat3& A, Vec3 v) {
  return Vec3{A.m[0] * v.x + A.m[1] * v.y + A.m[2] * v.z,
              A.m[3] * v.x + A.m[4] * v.y + A.m[5] * v.z,
              A.m[6] * v.x + A.m[7] * v.y + A.m[8] * v.z};
}
// A^T v
MSP_HD Vec3 MulTransposed(const Mat3& A, Vec3 v) {
  return Vec3{A.m[0] * v.x + A.m[3] * v.y + A.m[6] * v.z,
              A.m[1] * v.x + A.m[4] * v.y + A.m[7] * v.z,
              A.m[2] * v.x + A.m[5] * v.y + A.m[8] * v.z};
}
MSP_HD Mat3 Mul(const Mat3& A, const Mat3& B) {
  Mat3 C;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      C.m[3 * r + c] =
          A.m[3 * r + 0] * B.m[0 + c] + A.m[3 * r + 1] * B.m[3 + c] + A.m[3 * r + 2] * B.m[6 + c];
    }
  }
  return C;
}
MSP_HD Mat3 Transposed(const Mat3& A) {
  return Mat3{{A.m[0], A.m[3], A.m[6], A.m[1], A.m[4], A.m[7], A.m[2], A.m[5], A.m[8]}};
}

MSP_HD float Clamp(float v, float lo, float hi) { return fminf(fmaxf(v, lo), hi); }
MSP_HD int ClampInt(int v, int lo, int hi) { return v < lo ? lo : (v > hi ? hi : v); }

}  // namespace core
}  // namespace msp
