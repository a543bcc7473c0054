#!/usr/bin/python3
"""Where are the wrong depths? Splits the depth-map figures of a bundled-scene
workspace by distance to a ground-truth depth edge and by texture, so a change
that moves accuracy (deformable patches, the segmentation prior) can be traced
to the places it acts on.

  bench/edge_accuracy.py <workspace> [--input_type geometric] [--band 4]

Depth edges: neighbouring ground-truth pixels whose depths differ by more than
3%. "Near" = within --band pixels of an edge at the map's resolution. Per band
and texture class it prints the valid predictions, the share of them within
1% and 5% of the true depth (accuracy), and the share of ground-truth pixels
with such a prediction (completeness).
"""
import argparse
import os
import sys

import cv2
import numpy as np

EDGE_JUMP = 0.03


def read_map(path):
    """A COLMAP dense map: "W&H&C&" then float32 values, channel planes row-major."""
    with open(path, "rb") as f:
        data = f.read()
    fields, pos = [], 0
    for _ in range(3):
        end = data.index(b"&", pos)
        fields.append(int(data[pos:end]))
        pos = end + 1
    w, h, c = fields
    values = np.frombuffer(data, dtype=np.float32, offset=pos, count=w * h * c)
    return values.reshape(c, h, w)[0] if c == 1 else values.reshape(c, h, w)


def depth_edges(gt):
    valid = gt > 0
    edges = np.zeros(gt.shape, bool)
    for dy, dx in ((0, 1), (1, 0)):
        a = gt[: gt.shape[0] - dy, : gt.shape[1] - dx]
        b = gt[dy:, dx:]
        jump = np.abs(a - b) > EDGE_JUMP * np.minimum(a, b)
        jump &= (a > 0) & (b > 0)
        edges[: gt.shape[0] - dy, : gt.shape[1] - dx] |= jump
        edges[dy:, dx:] |= jump
    return edges & valid


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("workspace")
    parser.add_argument("--input_type", default="geometric")
    parser.add_argument("--band", type=int, default=4, help="pixels at the map's resolution")
    args = parser.parse_args()
    ws = args.workspace
    gt_dir = os.path.join(ws, "ground_truth")
    names = [l.split()[0] for l in open(os.path.join(gt_dir, "images.txt")) if l.strip()]
    # counts[(band, texture)] = [gt pixels, valid, within 1%, within 5%]
    counts = {}
    for name in names:
        pred_path = os.path.join(ws, "stereo", "depth_maps", f"{name}.{args.input_type}.bin")
        if not os.path.exists(pred_path):
            sys.exit(f"missing {pred_path}")
        pred = read_map(pred_path)
        h, w = pred.shape
        gt = cv2.resize(read_map(os.path.join(gt_dir, "depth_maps", f"{name}.bin")), (w, h),
                        interpolation=cv2.INTER_NEAREST)
        flat = cv2.imread(os.path.join(gt_dir, "textureless", f"{name}.png"), cv2.IMREAD_GRAYSCALE)
        flat = cv2.resize(flat, (w, h), interpolation=cv2.INTER_NEAREST) > 0
        edges = depth_edges(gt).astype(np.uint8)
        kernel = np.ones((2 * args.band + 1, 2 * args.band + 1), np.uint8)
        near = cv2.dilate(edges, kernel) > 0
        has_gt = gt > 0
        valid = np.isfinite(pred) & (pred > 0) & has_gt
        rel = np.where(valid, np.abs(pred - gt) / np.where(has_gt, gt, 1), np.inf)
        for band_name, band in (("near edge", near), ("away", ~near)):
            for tex_name, tex in (("textureless", flat), ("textured", ~flat)):
                sel = has_gt & band & tex
                c = counts.setdefault((band_name, tex_name), [0, 0, 0, 0])
                c[0] += int(sel.sum())
                c[1] += int((sel & valid).sum())
                c[2] += int((sel & (rel <= 0.01)).sum())
                c[3] += int((sel & (rel <= 0.05)).sum())
    print(f"{'region':<24} {'gt px':>9} {'valid%':>7} {'acc1%':>7} {'acc5%':>7} "
          f"{'cmp1%':>7} {'cmp5%':>7}")
    for (band_name, tex_name), (n, v, a1, a5) in sorted(counts.items()):
        pct = lambda x, d: 100.0 * x / d if d else 0.0
        print(f"{band_name + ', ' + tex_name:<24} {n:>9} {pct(v, n):>7.1f} {pct(a1, v):>7.1f} "
              f"{pct(a5, v):>7.1f} {pct(a1, n):>7.1f} {pct(a5, n):>7.1f}")


if __name__ == "__main__":
    main()
