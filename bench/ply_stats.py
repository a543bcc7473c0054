#!/usr/bin/python3
"""Point count, optional bounding-box share and a rendered view of a fused.ply.

    ply_stats.py fused.ply [--bbox x0 y0 z0 x1 y1 z1 [--margin 0.005] [--voxel 0.002]]
                 [--render out.png]

--voxel counts the occupied cubes of that side inside the box: a coverage
figure that, unlike the point count, does not grow with points piled up.

The rendering looks along the cloud's smallest principal axis (orthographic,
nearest point wins, 2x2 splats), shaded by the points' normals (brighter =
facing the viewer), so a person can see the shape that was reconstructed.
"""
import argparse

import cv2
import numpy as np


def read_ply(path):
    with open(path, "rb") as f:
        header = b""
        while not header.endswith(b"end_header\n"):
            header += f.readline()
        n = int([l for l in header.split(b"\n") if l.startswith(b"element vertex")][0].split()[2])
        dtype = np.dtype([("x", "<f4"), ("y", "<f4"), ("z", "<f4"), ("nx", "<f4"), ("ny", "<f4"),
                          ("nz", "<f4"), ("r", "u1"), ("g", "u1"), ("b", "u1")])
        data = np.frombuffer(f.read(n * dtype.itemsize), dtype=dtype, count=n)
    xyz = np.stack([data["x"], data["y"], data["z"]], 1).astype(np.float64)
    normals = np.stack([data["nx"], data["ny"], data["nz"]], 1).astype(np.float64)
    return xyz, normals


def render(xyz, normals, path, size=600):
    centre = np.median(xyz, 0)
    _, _, vt = np.linalg.svd(xyz - centre, full_matrices=False)
    uv = (xyz - centre) @ vt[:2].T
    depth = (xyz - centre) @ vt[2]
    lo, hi = np.percentile(uv, 1, 0), np.percentile(uv, 99, 0)
    scale = (size - 20) / np.max(hi - lo)
    px = ((uv - lo) * scale + 10).astype(int)
    keep = (px[:, 0] >= 0) & (px[:, 0] < size) & (px[:, 1] >= 0) & (px[:, 1] < size)
    order = np.argsort(-depth[keep])  # far first, near last (nearest wins)
    shade = (40 + 215 * np.abs(normals @ vt[2]))[keep][order].astype(np.uint8)
    img = np.zeros((size + 1, size + 1), np.uint8)
    p = px[keep][order]
    for dy in (0, 1):
        for dx in (0, 1):
            img[p[:, 1] + dy, p[:, 0] + dx] = shade
    cv2.imwrite(path, img[:size, :size])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("ply")
    parser.add_argument("--bbox", type=float, nargs=6)
    parser.add_argument("--margin", type=float, default=0.005)
    parser.add_argument("--voxel", type=float)
    parser.add_argument("--render")
    args = parser.parse_args()
    xyz, normals = read_ply(args.ply)
    print(f"fused points: {len(xyz)}")
    if args.bbox and len(xyz):
        lo = np.array(args.bbox[:3]) - args.margin
        hi = np.array(args.bbox[3:]) + args.margin
        inside = np.all((xyz >= lo) & (xyz <= hi), 1)
        print(f"inside bbox (+{args.margin} m): {inside.sum()} = {100.0 * inside.mean():.1f} %")
        if args.voxel:
            cells = np.floor((xyz[inside] - lo) / args.voxel).astype(np.int64)
            print(f"occupied voxels inside bbox ({args.voxel} m): {len(np.unique(cells, axis=0))}")
    if args.render and len(xyz):
        render(xyz, normals, args.render)
        print(f"rendered view: {args.render}")


if __name__ == "__main__":
    main()
