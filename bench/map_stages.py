#!/usr/bin/python3
"""Where the measured surface is lost: per image and per surface kind, the share
of the ground truth's pixels at each stage between the last pass and the fused
cloud, and how much of what each stage removes was right.

    map_stages.py <workspace> [--fused fused.ply] [--threshold 0.05] [--json out.json]

<workspace> was run with --MspStereo.write_previews 1, so that
stereo/prior_previews/<image>.stages.bin exists (channel 0 the stage, 1 the
depth before the output filter), and has a ground_truth/ folder (the bundled
scene's or msp_import_rgbd's). Stages (src/core/patch_match/map_stage.h): kept;
no plane; open sky; removed by the filter's triangulation angle, its NCC, its
reprojection error, or several tests. "right" means the depth before the
filter is within --threshold (relative) of the ground truth.

With --seen, two more surface kinds split the measured pixels by what the
views can give: "seen" pixels are visible (in the image, not occluded by the
ground truth's own surface) in at least --min_views other images at a
triangulation angle of at least --min_angle degrees (the output filter's
defaults: 2 views, 3 degrees), "unseen" the rest. The filter cannot keep an
unseen pixel, so the seen share is the ceiling of what the filtered maps can
reach (every other image counts as a source: an upper bound under __auto__).

With --fused, a kept pixel whose depth no fused point reproduces (a point of
fused.ply projecting within 1 pixel of it, depth within the threshold) counts
as "dropped by fusion". With --fused or --seen the sparse model is read
through `colmap model_converter` ($COLMAP, or colmap on PATH).

Surface kinds from the ground truth: textured / weak texture (its textureless
masks), and, from its normals in the camera frame of an upright camera, floor
(the normal within 40 degrees of the camera's up, -y) and wall (within 30
degrees of horizontal).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import cv2
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from ply_stats import read_ply  # noqa: E402

STAGES = ["kept", "no plane", "open sky", "filter: angle", "filter: NCC", "filter: geometric",
          "filter: several"]
KINDS = ["all", "textured", "weak texture", "floor", "wall", "seen", "unseen"]


def read_array(path):
    with open(path, "rb") as f:
        header = b""
        while header.count(b"&") < 3:
            header += f.read(1)
        w, h, c = (int(v) for v in header.split(b"&")[:3])
        data = np.fromfile(f, np.float32, w * h * c)
    return data.reshape(c, h, w).transpose(1, 2, 0)


def qvec_to_rotation(q):
    w, x, y, z = q
    return np.array([[1 - 2 * y * y - 2 * z * z, 2 * x * y - 2 * w * z, 2 * x * z + 2 * w * y],
                     [2 * x * y + 2 * w * z, 1 - 2 * x * x - 2 * z * z, 2 * y * z - 2 * w * x],
                     [2 * x * z - 2 * w * y, 2 * y * z + 2 * w * x, 1 - 2 * x * x - 2 * y * y]])


def read_cameras(workspace):
    """{image name: (K, R, t, width, height)} of the workspace's sparse model."""
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([os.environ.get("COLMAP", "colmap"), "model_converter", "--input_path",
                        os.path.join(workspace, "sparse"), "--output_path", tmp,
                        "--output_type", "TXT"], check=True, stdout=subprocess.DEVNULL)
        cams = {}
        for line in open(os.path.join(tmp, "cameras.txt")):
            if line.startswith("#") or not line.strip():
                continue
            v = line.split()
            if v[1] != "PINHOLE":
                sys.exit("map_stages.py: camera model %s (undistorted workspaces are PINHOLE)" % v[1])
            fx, fy, cx, cy = map(float, v[4:8])
            cams[v[0]] = (np.array([[fx, 0, cx], [0, fy, cy], [0, 0, 1]]), int(v[2]), int(v[3]))
        images = {}
        lines = [l for l in open(os.path.join(tmp, "images.txt")) if not l.startswith("#")]
        for line in lines[0::2]:
            v = line.split()
            if len(v) < 10:
                continue
            K, w, h = cams[v[8]]
            images[v[9]] = (K, qvec_to_rotation([float(a) for a in v[1:5]]),
                            np.array([float(a) for a in v[5:8]]), w, h)
    return images


def fused_depth_hits(points, camera, depth, threshold):
    """Pixels of `depth` (the map's size) that a fused point reproduces."""
    K, R, t, w, h = camera
    hits = np.zeros(depth.shape, bool)
    X = points @ R.T + t
    z = X[:, 2]
    front = z > 0
    X, z = X[front], z[front]
    sx, sy = depth.shape[1] / w, depth.shape[0] / h
    u = (K[0, 0] * X[:, 0] / z + K[0, 2]) * sx
    v = (K[1, 1] * X[:, 1] / z + K[1, 2]) * sy
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            c = np.round(u).astype(int) + dx
            r = np.round(v).astype(int) + dy
            inside = (c >= 0) & (c < depth.shape[1]) & (r >= 0) & (r < depth.shape[0])
            c, r, zz = c[inside], r[inside], z[inside]
            d = depth[r, c]
            ok = (d > 0) & (np.abs(zz - d) <= threshold * d)
            hits[r[ok], c[ok]] = True
    return hits


def seen_by_sources(name, cameras, gts, shape, min_angle):
    """Per pixel of a map of `shape` (rows, cols), the number of other images
    that see its ground-truth point unoccluded at a triangulation angle of at
    least `min_angle` degrees (0 where the point is not measured)."""
    K, R, t, w, h = cameras[name]
    gt = gts[name]
    rows, cols = np.mgrid[0:shape[0], 0:shape[1]]
    depth = gt[np.ix_(nearest_gt(shape[0], gt.shape[0]), nearest_gt(shape[1], gt.shape[1]))]
    measured = depth > 0
    x = ((cols[measured] + 0.5) * w / shape[1] - K[0, 2]) / K[0, 0]
    y = ((rows[measured] + 0.5) * h / shape[0] - K[1, 2]) / K[1, 1]
    world = (np.stack([x, y, np.ones_like(x)], -1) * depth[measured][:, None] - t) @ R
    to_ref = -R.T @ t - world
    to_ref /= np.linalg.norm(to_ref, axis=1, keepdims=True)
    count = np.zeros(len(world), int)
    for other, (Ks, Rs, ts, ws, hs) in cameras.items():
        if other == name or other not in gts:
            continue
        X = world @ Rs.T + ts
        z = np.maximum(X[:, 2], 1e-9)
        g = gts[other]
        u = np.floor((Ks[0, 0] * X[:, 0] / z + Ks[0, 2]) * g.shape[1] / ws).astype(int)
        v = np.floor((Ks[1, 1] * X[:, 1] / z + Ks[1, 2]) * g.shape[0] / hs).astype(int)
        inside = (X[:, 2] > 0) & (u >= 0) & (v >= 0) & (u < g.shape[1]) & (v < g.shape[0])
        there = g[np.clip(v, 0, g.shape[0] - 1), np.clip(u, 0, g.shape[1] - 1)]
        # Unmeasured there (a sensor hole) counts as seen: an upper bound.
        visible = inside & ((there <= 0) | (np.abs(there - z) <= 0.05 * z))
        to_other = -Rs.T @ ts - world
        to_other /= np.linalg.norm(to_other, axis=1, keepdims=True)
        angle = np.degrees(np.arccos(np.clip(np.sum(to_ref * to_other, axis=1), -1.0, 1.0)))
        count += visible & (angle >= min_angle)
    out = np.zeros(shape, int)
    out[measured] = count
    return out


def nearest_gt(size, gt_size):
    return np.minimum(np.round(np.arange(size) * gt_size / size).astype(int), gt_size - 1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("workspace")
    parser.add_argument("--fused")
    parser.add_argument("--threshold", type=float, default=0.05)
    parser.add_argument("--seen", action="store_true",
                        help="split by what --min_views other images see at --min_angle")
    parser.add_argument("--min_views", type=int, default=2)
    parser.add_argument("--min_angle", type=float, default=3.0)
    parser.add_argument("--json")
    args = parser.parse_args()
    ws = args.workspace
    gt_dir = os.path.join(ws, "ground_truth")
    names = [l.strip() for l in open(os.path.join(gt_dir, "images.txt")) if l.strip()]
    points = read_ply(args.fused)[0] if args.fused else None
    cameras = read_cameras(ws) if args.fused or args.seen else None
    gts = {n: read_array(os.path.join(gt_dir, "depth_maps", n + ".bin"))[:, :, 0]
           for n in names} if args.seen else None
    map_type = "geometric"
    # totals[kind][stage] = [pixels, right]
    totals = {k: np.zeros((len(STAGES) + 1, 2)) for k in KINDS}
    per_image = []
    for name in names:
        path = os.path.join(ws, "stereo", "prior_previews", name + ".stages.bin")
        if not os.path.exists(path):
            sys.exit("map_stages.py: %s is missing (run msp_stereo with "
                     "--MspStereo.write_previews 1)" % path)
        stages = read_array(path)
        code, before = stages[:, :, 0].astype(int), stages[:, :, 1]
        gt = read_array(os.path.join(gt_dir, "depth_maps", name + ".bin"))[:, :, 0]
        rows, cols = nearest_gt(code.shape[0], gt.shape[0]), nearest_gt(code.shape[1], gt.shape[1])
        gt = gt[np.ix_(rows, cols)]
        measured = gt > 0
        right = measured & (before > 0) & (np.abs(before - gt) <= args.threshold * np.maximum(gt, 1e-9))
        kinds = {"all": measured}
        texless_path = os.path.join(gt_dir, "textureless", name + ".png")
        if os.path.exists(texless_path):
            texless = cv2.imread(texless_path, cv2.IMREAD_GRAYSCALE)[np.ix_(rows, cols)] > 0
            kinds["textured"] = measured & ~texless
            kinds["weak texture"] = measured & texless
        normal_path = os.path.join(gt_dir, "normal_maps", name + ".bin")
        if os.path.exists(normal_path):
            n = read_array(normal_path)[np.ix_(rows, cols)]
            kinds["floor"] = measured & (n[:, :, 1] < -np.cos(np.radians(40)))
            kinds["wall"] = measured & (np.abs(n[:, :, 1]) < np.sin(np.radians(30))) & (
                np.linalg.norm(n, axis=2) > 0.5)
        if args.seen:
            seen = seen_by_sources(name, cameras, gts, code.shape, args.min_angle) >= args.min_views
            kinds["seen"] = measured & seen
            kinds["unseen"] = measured & ~seen
        fused_lost = np.zeros(code.shape, bool)
        if points is not None:
            final = read_array(os.path.join(ws, "stereo", "depth_maps",
                                            "%s.%s.bin" % (name, map_type)))[:, :, 0]
            fused_lost = (code == 1) & ~fused_depth_hits(points, cameras[name], final,
                                                         args.threshold)
        image_row = {"image": name}
        for kind, mask in kinds.items():
            for s in range(1, len(STAGES) + 1):
                sel = mask & (code == s)
                if s == 1 and points is not None:
                    totals[kind][len(STAGES)] += [np.sum(sel & fused_lost),
                                                  np.sum(sel & fused_lost & right)]
                totals[kind][s - 1] += [np.sum(sel), np.sum(sel & right)]
            if kind == "all":
                m = max(np.sum(mask), 1)
                image_row.update({STAGES[s - 1]: np.sum(mask & (code == s)) / m
                                  for s in range(1, len(STAGES) + 1)})
                image_row["kept right"] = np.sum(mask & (code == 1) & right) / m
                image_row["right before filter"] = np.sum(mask & right) / m
        per_image.append(image_row)

    pct = lambda a, b: "%.1f" % (100.0 * a / b) if b > 0 else "-"
    labels = STAGES + (["kept, dropped by fusion"] if points is not None else [])
    print("Share of the measured pixels at each stage (right: depth before the filter within "
          "%g %%), over %d images\n" % (100 * args.threshold, len(names)))
    print("| stage | " + " | ".join("%s: share / right" % k for k in KINDS if k in totals
                                   and totals[k][:, 0].sum() > 0) + " |")
    shown = [k for k in KINDS if totals[k][:, 0].sum() > 0]
    print("|---|" + "---|" * len(shown))
    for s, label in enumerate(labels):
        cells = []
        for k in shown:
            all_px = totals[k][:len(STAGES), 0].sum()
            cells.append("%s / %s" % (pct(totals[k][s, 0], all_px), pct(totals[k][s, 1], all_px)))
        print("| %s | %s |" % (label, " | ".join(cells)))
    if args.seen:
        seen, measured = totals["seen"][:len(STAGES), 0].sum(), totals["all"][:len(STAGES), 0].sum()
        print("\nSeen by >= %d other images at >= %g degrees (ground truth): %s %% of the measured "
              "pixels, the ceiling of the filtered maps" % (args.min_views, args.min_angle,
                                                            pct(seen, measured)))
    print("\nPer image (all measured pixels): kept / kept and right / right before the filter / "
          "no plane / filter (angle, NCC, geometric, several) / open sky, %")
    for r in per_image:
        print("%-28s %5.1f %5.1f %5.1f %5.1f  %5.1f %5.1f %5.1f %5.1f  %5.1f" % (
            r["image"][:28], 100 * r["kept"], 100 * r["kept right"], 100 * r["right before filter"],
            100 * r["no plane"], 100 * r["filter: angle"], 100 * r["filter: NCC"],
            100 * r["filter: geometric"], 100 * r["filter: several"], 100 * r["open sky"]))
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"stages": labels, "totals": {k: v.tolist() for k, v in totals.items()},
                       "per_image": per_image}, f, indent=1, default=float)


if __name__ == "__main__":
    main()
