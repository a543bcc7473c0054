#!/usr/bin/env bash
# The main job: install, build, render the bundled scene, run
# `colmap msp_stereo` on it, fuse with `colmap stereo_fusion` and print the
# evaluation against the exact ground truth, with the paths of the pictures of
# each depth map (depth, normals, error). Re-running resumes: existing maps
# are kept, fusion and evaluation run again. Delete out/scene to start over.
# The scene is 640x480; stereo runs at MSP_DEMO_MAX_IMAGE_SIZE (default 320,
# under 2 minutes of stereo on 2 cores; -1 = full size, see BENCHMARKS.md).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
export PATH="$PWD/build/bin:$PATH"  # our `colmap` dispatcher first: it adds msp_stereo
ws=out/scene
if [ ! -f "$ws/ground_truth/scene.json" ]; then
  rm -rf "$ws"
  msp_make_scene --output "$ws"
fi
colmap msp_stereo --workspace_path "$ws" --MspStereo.write_previews 1 \
  --PatchMatchStereo.max_image_size "${MSP_DEMO_MAX_IMAGE_SIZE:-320}"
colmap stereo_fusion --workspace_path "$ws" --input_type geometric --output_path "$ws/fused.ply"
msp_evaluate --workspace "$ws" --fused "$ws/fused.ply" --json "$ws/evaluation.json"
echo "Fused cloud: $ws/fused.ply; figures: $ws/evaluation.json"
