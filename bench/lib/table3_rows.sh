# shellcheck shell=bash
# The rows of the MSP-MVS ablation in the shape of the paper's Table 3, shared
# by bench/table3.sh (the bundled scene) and bench/real_gt.sh (real frames
# with sensor ground truth). Sourcing it sets `rows`, one "id|label|options"
# a row.

# Deformable patches, which every part of the method runs in: off by default
# (docs/method.md section 9), so every row turns them on.
METHOD="--MspStereo.deformable true"
# The parts of the method, each switched off.
NO_PRIOR="--MspStereo.segmentation_prior false"
NO_AGR="--MspStereo.edge_aggregation false"
NO_REF="--MspStereo.edge_refinement false"
NO_GEO="--MspStereo.geometry_layers false"
NO_EQD="--MspStereo.equidistribution false"
NO_CLU="--MspStereo.disassemble_clustering false"
NO_SYN="--MspStereo.synergistic_optimization false"

# id | label | options. From the baseline to `full` each row adds one part to
# the row above (segment planes, our own step, stay on throughout); the next
# three take one piece out of the full method's 3D optimization; `default`
# is what msp_stereo runs without options (the conventional core), and the
# last seven take one of its answers to weak texture out (docs/method.md
# sections 2.7, 2.9, 2.12 and 2.13).
rows=(
  "baseline|APD-MVS baseline|$METHOD $NO_PRIOR $NO_EQD $NO_CLU $NO_SYN"
  "prior|+ prior: colour layers, union of their edges|$METHOD $NO_AGR $NO_REF $NO_GEO $NO_EQD $NO_CLU $NO_SYN"
  "aggregation|+ edge aggregation (eqs. 4-5)|$METHOD $NO_REF $NO_GEO $NO_EQD $NO_CLU $NO_SYN"
  "refinement|+ edge refinement (CRF, eq. 6)|$METHOD $NO_GEO $NO_EQD $NO_CLU $NO_SYN"
  "geometry|+ geometry layers|$METHOD $NO_EQD $NO_CLU $NO_SYN"
  "equidistribution|+ adaptive equidistribution (eq. 7)|$METHOD $NO_CLU $NO_SYN"
  "clustering|+ disassemble-clustering|$METHOD $NO_SYN"
  "full|+ 3D optimization (eqs. 8-9) = MSP-MVS|$METHOD"
  "novar|MSP-MVS w/o Var. (omega = 0)|$METHOD --MspStereo.advanced_variance_weight 0"
  "nocost|MSP-MVS w/o Cst.|$METHOD --MspStereo.advanced_profile_cost_term false"
  "mu3|MSP-MVS, mu = 3|$METHOD --MspStereo.advanced_disparity_samples 3"
  "default|default options (conventional core, segment planes, planar prior, open sky)|"
  "no_planar_prior|default w/o the planar prior|--MspStereo.planar_prior false"
  "sweep_normals|default with the sweeps' normals (not from the depth)|--MspStereo.normals_from_depth false"
  "reprojection_filter|default with COLMAP's 1 px reprojection filter|--MspStereo.filter_max_depth_error 0"
  "two_view_filter|default with two sources always needed by the filter|--MspStereo.filter_single_view_depth_error 0"
  "pixel_geometry|default with the geometric passes' error in pixels|--MspStereo.geom_consistency_depth_error 0"
  "colmap_weight|default with the geometric term in depth weighted as COLMAP's in pixels (0.3)|--MspStereo.geom_consistency_depth_weight 0.3"
  "no_consensus_planes|default w/o the consensus planes|--MspStereo.consensus_planes false"
)

# Rows with the scene's ideal mask layers (msp_make_scene --ideal_masks: its
# surface ids, a perfect segmenter) instead of the embedded segmenter, for
# bench/table3.sh --ideal_masks, which puts them after `full`. `full` is
# `default` with deformable patches, so full_ideal is both with the perfect
# prior (`default` itself runs no prior); noref_ideal shows what the CRF does
# to edges that are already exact; default_ideal gives the matching windows
# the true objects and the segment planes and the consensus planes the true
# surfaces as regions (docs/method.md sections 2.3, 2.10, 2.13), and
# whole_windows_ideal leaves the windows whole.
# shellcheck disable=SC2034  # used by bench/table3.sh
ideal_rows=(
  "full_ideal|MSP-MVS, ideal masks|$METHOD"
  "noref_ideal|MSP-MVS, ideal masks, w/o Ref. (no CRF)|$METHOD $NO_REF"
  "default_ideal|default options, ideal masks (the windows', segment and consensus planes' regions)|"
  "whole_windows_ideal|default options, ideal masks, whole windows|--MspStereo.region_windows false"
)

# plan_fields ROW: sets `id`, `label` and the array `options` from an
# "id|label|options" row.
plan_fields() {
  id=${1%%|*}
  local rest=${1#*|}
  label=${rest%%|*}
  read -r -a options <<< "${rest#*|}"
}

# table3_row ID: the row's "id|label|options", or nothing.
table3_row() {
  local row
  for row in "${rows[@]}"; do
    [ "${row%%|*}" = "$1" ] && { echo "$row"; return; }
  done
}
