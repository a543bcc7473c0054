#!/usr/bin/python3
"""Point count, optional bounding-box share and a rendered view of a fused.ply.

    ply_stats.py fused.ply [--bbox x0 y0 z0 x1 y1 z1 [--margin 0.005]] [--voxel 0.002]
                 [--render out.png]

--voxel counts the occupied cubes of that side inside the box (of the whole
cloud without --bbox): a coverage figure that, unlike the point count, does
not grow with points piled up.

Reads COLMAP's fused.ply and other point clouds (binary little-endian or ASCII,
a leading vertex element with x, y, z of any scalar type, normals optional).

The rendering looks along the cloud's smallest principal axis (orthographic,
nearest point wins, 2x2 splats), shaded by the points' normals (brighter =
facing the viewer), so a person can see the shape that was reconstructed.
"""
import argparse

import cv2
import numpy as np


# PLY scalar types and their little-endian numpy codes.
PLY_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "<i2",
             "int16": "<i2", "ushort": "<u2", "uint16": "<u2", "int": "<i4", "int32": "<i4",
             "uint": "<u4", "uint32": "<u4", "float": "<f4", "float32": "<f4",
             "double": "<f8", "float64": "<f8"}


def read_ply(path):
    """(xyz, normals) of a PLY's vertices as float64 arrays; normals zero when it has none.

    Reads COLMAP's fused.ply and other point clouds (e.g. another MVS program's) as
    msp_evaluate does: binary_little_endian or ascii, a leading vertex element of
    scalar properties with x, y, z (nx, ny, nz optional), any types.
    """
    with open(path, "rb") as f:
        if f.readline().strip() != b"ply":
            raise SystemExit(f"{path}: not a PLY file")
        fmt, n, props, in_vertex, seen_element = None, 0, [], False, False
        while True:
            line = f.readline()
            if not line:
                raise SystemExit(f"{path}: no end_header")
            words = line.decode("ascii", "replace").split()
            if not words:
                continue
            if words[0] == "format":
                fmt = words[1]
            elif words[0] == "element":
                in_vertex = words[1] == "vertex"
                if in_vertex and seen_element:
                    raise SystemExit(f"{path}: vertex must be the first element")
                if in_vertex:
                    n = int(words[2])
                seen_element = True
            elif words[0] == "property" and in_vertex:
                if words[1] not in PLY_TYPES:
                    raise SystemExit(f"{path}: unsupported vertex property type {words[1]}")
                props.append((words[2], PLY_TYPES[words[1]]))
            elif words[0] == "end_header":
                break
        names = [name for name, _ in props]
        if not all(c in names for c in "xyz"):
            raise SystemExit(f"{path}: vertex element lacks x, y or z")
        dtype = np.dtype(props)
        if fmt == "binary_little_endian":
            body = f.read(n * dtype.itemsize)
            if len(body) < n * dtype.itemsize:
                raise SystemExit(f"{path}: truncated after {len(body) // dtype.itemsize} vertices")
            data = np.frombuffer(body, dtype=dtype, count=n)
        elif fmt == "ascii":
            rows = [f.readline().split()[:len(props)] for _ in range(n)]
            table = np.array([r for r in rows if len(r) == len(props)], np.float64)
            table = table.reshape(-1, len(props))
            if len(table) < n:
                raise SystemExit(f"{path}: truncated after {len(table)} vertices")
            data = {name: table[:, i] for i, name in enumerate(names)}
        else:
            raise SystemExit(f"{path}: unsupported PLY format {fmt}")
    xyz = np.stack([data["x"], data["y"], data["z"]], 1).astype(np.float64)
    if all(c in names for c in ("nx", "ny", "nz")):
        normals = np.stack([data["nx"], data["ny"], data["nz"]], 1).astype(np.float64)
    else:
        normals = np.zeros_like(xyz)
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
    elif args.voxel and len(xyz):
        cells = np.floor(xyz / args.voxel).astype(np.int64)
        print(f"occupied voxels ({args.voxel} m): {len(np.unique(cells, axis=0))}")
    if args.render and len(xyz):
        render(xyz, normals, args.render)
        print(f"rendered view: {args.render}")


if __name__ == "__main__":
    main()
