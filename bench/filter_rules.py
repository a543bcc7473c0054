#!/usr/bin/python3
"""What other tests of the output filter would keep: each rule's share of the
ground truth's measured pixels kept, kept and right, and its precision.

    filter_rules.py <workspace> [--threshold 0.05]

<workspace> was run with --MspStereo.write_previews 1: each image's stages map
(stereo/prior_previews/<image>.stages.bin) holds the depth before the filter.
Every pixel's point is checked against every other image's depth before the
filter (the nearest pixel where it projects): the triangulation angle, the
forward-backward reprojection error in pixels (COLMAP's test) and the relative
depth disagreement |z - z_source| / z_source. The NCC test is left out (on the
benchmarks it removes under 1 % of the pixels). An offline model of the filter,
close to it but not the same: the filter reads the sources' depths of the
previous pass, and only the sources in patch-match.cfg. Needs colmap on PATH.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from map_stages import read_array, read_cameras  # noqa: E402

# name: (minimum angle in degrees, pixel tolerance or None, depth tolerance or None, views,
#        and optionally the depth tolerance at which one view alone keeps a pixel)
RULES = [
    ("COLMAP: angle 3, reprojection 1 px, 2 views", (3, 1.0, None, 2)),
    ("angle 2, reprojection 1 px, 2 views", (2, 1.0, None, 2)),
    ("angle 0, reprojection 1 px, 2 views", (0, 1.0, None, 2)),
    ("angle 3, reprojection 2 px, 2 views", (3, 2.0, None, 2)),
    ("angle 3, reprojection 1 px, 1 view", (3, 1.0, None, 1)),
    ("angle 3, depth 1 %, 2 views", (3, None, 0.01, 2)),
    ("angle 3, depth 0.5 %, 2 views", (3, None, 0.005, 2)),
    ("angle 3, depth 2 %, 2 views", (3, None, 0.02, 2)),
    ("angle 2, depth 1 %, 2 views", (2, None, 0.01, 2)),
    ("angle 1, depth 1 %, 3 views", (1, None, 0.01, 3)),
    ("angle 3, depth 1 %, 2 views, or 1 view at 0.5 % (default)", (3, None, 0.01, 2, 0.005)),
    ("angle 3, depth 1 %, 2 views, or 1 view at 0.3 %", (3, None, 0.01, 2, 0.003)),
    ("angle 3, depth 1 %, 2 views, or 1 view at 1 %", (3, None, 0.01, 2, 0.01)),
]


def centre(camera):
    _, R, t, _, _ = camera
    return -R.T @ t


def view_tests(name, names, depth, cameras):
    """Per other view: the angle, reprojection error and depth disagreement of
    every pixel of `name` with a depth, and those pixels' (rows, cols)."""
    K, R, t, _, _ = cameras[name]
    d = depth[name]
    height, width = d.shape
    cols, rows = np.meshgrid(np.arange(width), np.arange(height))
    has = d > 0
    u0, v0, z0 = cols[has].astype(float), rows[has].astype(float), d[has]
    X = R.T @ (np.stack([(u0 - K[0, 2]) / K[0, 0] * z0, (v0 - K[1, 2]) / K[1, 1] * z0, z0])
               - t[:, None])
    c = centre(cameras[name])
    angles, pixels, depths = [], [], []
    for other in names:
        if other == name:
            continue
        Ko, Ro, to, _, _ = cameras[other]
        Xo = Ro @ X + to[:, None]
        z = Xo[2]
        with np.errstate(divide="ignore", invalid="ignore"):
            u = np.round(Ko[0, 0] * Xo[0] / z + Ko[0, 2]).astype(int)
            v = np.round(Ko[1, 1] * Xo[1] / z + Ko[1, 2]).astype(int)
        ok = (z > 0) & (u >= 0) & (u < width) & (v >= 0) & (v < height)
        zo = np.zeros_like(z)
        zo[ok] = depth[other][v[ok], u[ok]]
        ok &= zo > 0
        Y = Ro.T @ (np.stack([(u - Ko[0, 2]) / Ko[0, 0] * zo, (v - Ko[1, 2]) / Ko[1, 1] * zo, zo])
                    - to[:, None])
        Yi = R @ Y + t[:, None]
        with np.errstate(divide="ignore", invalid="ignore"):
            error = np.hypot(K[0, 0] * Yi[0] / Yi[2] + K[0, 2] - u0,
                             K[1, 1] * Yi[1] / Yi[2] + K[1, 2] - v0)
            disagreement = np.abs(z - zo) / zo
        error[~ok] = np.inf
        disagreement[~ok] = np.inf
        a, b = c[:, None] - X, centre(cameras[other])[:, None] - X
        cos = (a * b).sum(0) / np.linalg.norm(a, axis=0) / np.linalg.norm(b, axis=0)
        angles.append(np.degrees(np.arccos(np.clip(cos, -1, 1))))
        pixels.append(error)
        depths.append(disagreement)
    return np.array(angles), np.array(pixels), np.array(depths), has


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("workspace")
    parser.add_argument("--threshold", type=float, default=0.05)
    args = parser.parse_args()
    ws = args.workspace
    gt_dir = os.path.join(ws, "ground_truth")
    names = [l.strip() for l in open(os.path.join(gt_dir, "images.txt")) if l.strip()]
    cameras = read_cameras(ws)
    depth = {}
    for n in names:
        path = os.path.join(ws, "stereo", "prior_previews", n + ".stages.bin")
        if not os.path.exists(path):
            sys.exit("filter_rules.py: %s is missing (run msp_stereo with "
                     "--MspStereo.write_previews 1)" % path)
        depth[n] = read_array(path)[:, :, 1]
    totals = np.zeros((len(RULES), 2))
    measured = 0
    for n in names:
        angles, pixels, depths, has = view_tests(n, names, depth, cameras)
        gt = read_array(os.path.join(gt_dir, "depth_maps", n + ".bin"))[:, :, 0]
        measured += np.sum(gt > 0)
        g = gt[has]
        right = (g > 0) & (np.abs(depth[n][has] - g) <= args.threshold * g)
        for k, (_, (angle, pixel, relative, views, *alone)) in enumerate(RULES):
            wide = angles >= angle
            agree = wide & (pixels <= pixel if pixel is not None else depths <= relative)
            keep = agree.sum(0) >= views
            if alone:
                keep |= (wide & (depths <= alone[0])).any(0)
            totals[k] += [np.sum(keep & (g > 0)), np.sum(keep & right)]
    print("| rule | kept %% | kept and within %g %% | precision %% |" % (100 * args.threshold))
    print("|---|---|---|---|")
    for (label, _), (kept, right) in zip(RULES, totals):
        print("| %s | %.1f | %.1f | %.1f |" % (label, 100 * kept / measured,
                                              100 * right / measured, 100 * right / max(kept, 1)))


if __name__ == "__main__":
    main()
