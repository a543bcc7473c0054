// Capacities of the per-pixel code, defined once. Option checks and fixed-size
// arrays both use these, so a value the options accept always fits.
#pragma once

namespace msp {
namespace core {

// Source views per problem: view masks are 32-bit sets.
constexpr int kMaxSourceViews = 32;
// Matching window half size (COLMAP allows 32; our window loops are sized for 20).
constexpr int kMaxWindowRadius = 20;
// ACMH checkerboard sampling: 8 regions give up to 8 propagation candidates.
constexpr int kNumPropagationCandidates = 8;
// Refinement hypotheses mixing current, perturbed and random depth/normal.
constexpr int kNumRefinementCandidates = 5;
// The local refinement's disparity sweep: pixels each side (local_refine.h).
constexpr int kLocalRefineRadius = 5;

// Cost of a failed match (no texture, outside the source image): NCC = -1.
constexpr float kMaxCost = 2.0f;

static_assert(kMaxSourceViews <= 32, "view masks are uint32_t bit sets");

}  // namespace core
}  // namespace msp
