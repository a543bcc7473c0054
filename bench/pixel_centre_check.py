#!/usr/bin/python3
"""Which pixel-centre convention does an RGB-D capture's K use? Checked against its depth.

COLMAP centres pixel (0, 0) at (0.5, 0.5); most RGB-D datasets centre it at (0, 0).
msp_import_rgbd's --pixel_centre_offset (0.5 or 0) says which. Two measures:

1. Cross-frame depth agreement: each frame's depth back-projected with K's principal point
   shifted by s pixels, moved into every overlapping frame and compared with that frame's
   depth (bilinear, where all four neighbours are measured). The convention is the shift at
   which the agreement peaks, if the depth can tell.
2. With --workspaces (msp_import_rgbd outputs made with different --pixel_centre_offset):
   COLMAP's mean reprojection error of the triangulated SIFT tracks, and the median
   |z_sift / z_sensor - 1| of the tracks' depth against the sensor's at their pixels.

  bench/pixel_centre_check.py RGBD_DIR [--frames 0-8,35-39] [--units 1000] [--workspaces WS...]
"""
import argparse
import glob
import os
import struct

import cv2
import numpy as np

SHIFTS = [-1.0, -0.5, 0.0, 0.5, 1.0, 1.5]  # pixels added to cx (then cy)
MIN_OVERLAP = 0.3  # share of a frame's measured pixels seen by the other frame
MAX_RELATIVE = 0.03  # pixels disagreeing more are another surface (occlusion), not error
MIN_DEPTH = 0.2  # metres in front of a camera


def frame_list(text, count):
    if not text:
        return list(range(count))
    out = []
    for part in text.split(","):
        a, _, b = part.partition("-")
        out += list(range(int(a), int(b or a) + 1))
    return out


def project(K, X):
    p = K @ X
    return p[0] / p[2], p[1] / p[2]


def agreement(K, poses, depths, pairs, shift_x, shift_y):
    """Median relative depth difference over the pairs, K's centre shifted."""
    Ks = K.copy()
    Ks[0, 2] += shift_x
    Ks[1, 2] += shift_y
    Ki = np.linalg.inv(Ks)
    errors = []
    for a, b in pairs:
        d = depths[a]
        rows, cols = np.nonzero(d > 0)
        X = (Ki @ np.stack([cols, rows, np.ones_like(cols)])) * d[rows, cols]
        world = poses[a][:3, :3] @ X + poses[a][:3, 3:4]
        Xb = poses[b][:3, :3].T @ (world - poses[b][:3, 3:4])
        Xb = Xb[:, Xb[2] > MIN_DEPTH]
        c, r = project(Ks, Xb)
        c0, r0 = np.floor(c).astype(int), np.floor(r).astype(int)
        h, w = depths[b].shape
        inside = (c0 >= 0) & (r0 >= 0) & (c0 < w - 1) & (r0 < h - 1)
        c, r, c0, r0, z = c[inside], r[inside], c0[inside], r0[inside], Xb[2, inside]
        db = depths[b]
        q = [db[r0, c0], db[r0, c0 + 1], db[r0 + 1, c0], db[r0 + 1, c0 + 1]]
        fx, fy = c - c0, r - r0
        sampled = (q[0] * (1 - fx) * (1 - fy) + q[1] * fx * (1 - fy) + q[2] * (1 - fx) * fy +
                   q[3] * fx * fy)
        rel = np.abs(sampled - z) / z
        keep = (q[0] > 0) & (q[1] > 0) & (q[2] > 0) & (q[3] > 0) & (rel < MAX_RELATIVE)
        errors.append(rel[keep])
    return np.median(np.concatenate(errors))


def overlapping_pairs(K, poses, depths, frames):
    pairs = []
    Ki = np.linalg.inv(K)
    for a in frames:
        rows, cols = np.nonzero(depths[a] > 0)
        X = (Ki @ np.stack([cols, rows, np.ones_like(cols)])) * depths[a][rows, cols]
        world = poses[a][:3, :3] @ X + poses[a][:3, 3:4]
        for b in frames:
            if a == b:
                continue
            Xb = poses[b][:3, :3].T @ (world - poses[b][:3, 3:4])
            Xb = Xb[:, Xb[2] > MIN_DEPTH]
            c, r = project(K, Xb)
            h, w = depths[b].shape
            seen = ((c >= 0) & (r >= 0) & (c < w) & (r < h)).sum() / max(len(rows), 1)
            if seen >= MIN_OVERLAP:
                pairs.append((a, b))
    return pairs


def read_binary_model(sparse):
    """images.bin and points3D.bin of a COLMAP model: poses, observations, points."""
    images = {}
    with open(os.path.join(sparse, "images.bin"), "rb") as f:
        for _ in range(struct.unpack("<Q", f.read(8))[0]):
            image_id, qw, qx, qy, qz, tx, ty, tz, _ = struct.unpack("<I7dI", f.read(64))
            name = b""
            while (ch := f.read(1)) != b"\0":
                name += ch
            n = struct.unpack("<Q", f.read(8))[0]
            obs = [struct.unpack("<ddq", f.read(24)) for _ in range(n)]
            R = np.array([
                [1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qw * qz), 2 * (qx * qz + qw * qy)],
                [2 * (qx * qy + qw * qz), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qw * qx)],
                [2 * (qx * qz - qw * qy), 2 * (qy * qz + qw * qx), 1 - 2 * (qx * qx + qy * qy)]])
            images[image_id] = (name.decode(), R, np.array([tx, ty, tz]), obs)
    points, errors = {}, []
    with open(os.path.join(sparse, "points3D.bin"), "rb") as f:
        for _ in range(struct.unpack("<Q", f.read(8))[0]):
            pid, x, y, z, _, _, _, err, n = struct.unpack("<Q3d3BdQ", f.read(51))
            f.read(8 * n)
            points[pid] = np.array([x, y, z])
            errors.append(err)
    return images, points, float(np.mean(errors))


def sift_against_sensor(ws, depth_dir, units):
    images, points, error = read_binary_model(os.path.join(ws, "sparse"))
    ratios = []
    for name, R, t, obs in images.values():
        d = cv2.imread(os.path.join(depth_dir, os.path.splitext(name)[0] + ".png"),
                       cv2.IMREAD_UNCHANGED).astype(float) / units
        for x, y, pid in obs:
            if pid < 0:
                continue
            z = (R @ points[pid] + t)[2]
            col, row = int(np.floor(x)), int(np.floor(y))  # COLMAP: pixel i spans [i, i + 1)
            if 0 <= row < d.shape[0] and 0 <= col < d.shape[1] and d[row, col] > 0:
                ratios.append(z / d[row, col])
    ratios = np.array(ratios)
    return error, np.median(np.abs(ratios - 1)), len(ratios)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("rgbd")
    parser.add_argument("--frames", default="")
    parser.add_argument("--units", type=float, default=1000.0)
    parser.add_argument("--workspaces", nargs="*", default=[])
    args = parser.parse_args()
    K = np.loadtxt(os.path.join(args.rgbd, "K.txt")).reshape(3, 3)
    poses = np.loadtxt(os.path.join(args.rgbd, "poses.txt")).reshape(-1, 4, 4)
    names = sorted(glob.glob(os.path.join(args.rgbd, "depth", "*.png")))
    frames = frame_list(args.frames, len(names))
    depths = {i: cv2.imread(names[i], cv2.IMREAD_UNCHANGED).astype(float) / args.units
              for i in frames}
    pairs = overlapping_pairs(K, poses, depths, frames)
    print("cross-frame depth agreement, %d frame pairs (median |d - d'| / d):" % len(pairs))
    for s in SHIFTS:
        print("  cx %+.1f px: %.5f   cy %+.1f px: %.5f" %
              (s, agreement(K, poses, depths, pairs, s, 0.0), s,
               agreement(K, poses, depths, pairs, 0.0, s)))
    for ws in args.workspaces:
        error, median, n = sift_against_sensor(ws, os.path.join(args.rgbd, "depth"), args.units)
        print("%s: reprojection error %.3f px, SIFT tracks against the sensor: median "
              "|z/d - 1| %.4f over %d observations" % (ws, error, median, n))


if __name__ == "__main__":
    main()
