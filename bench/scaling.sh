#!/usr/bin/env bash
# How the time of a run grows with the pixels, with the source views and with
# the threads: default options (or the options given) on generated scenes, one
# run per row, printing per image wall and user CPU seconds, user CPU seconds
# per megapixel per source view and fused F1; then, from the size rows, the
# speed-up at the largest thread count, the parallel fraction by Amdahl's law
# and the speed-up it predicts on 16 and 64 cores.
#
#   bench/scaling.sh [--sizes "320 640 1280"] [--sources "4 9 19"]
#                    [--threads "1 2"] [msp_stereo options...]
#
# Pixels: 10-view scenes at each width (4:3). Sources: one 20-view scene at
# 320x240 whose patch-match.cfg asks for `__auto__, N`. Every size and every
# sources row runs once per thread count (--PatchMatchStereo.num_threads N);
# --sizes "" or --sources "" skips that part. The thread scaling needs 1 and a
# larger count in --threads; counts above this machine's cores measure
# oversubscription, not scaling, and other load on the machine lowers the
# speed-up. Megapixels are those of the written maps (after
# --PatchMatchStereo.max_image_size) and sources those `__auto__` selects from
# the sparse model (COLMAP's rule), averaged over the images. Binaries from
# $MSP_BIN (default build/bin), COLMAP from $COLMAP (default /usr/bin/colmap).
set -euo pipefail
# shellcheck source=bench/lib/run_row.sh
source "$(dirname "$0")/lib/run_row.sh"
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="${MSP_BIN:-$root/build/bin}"

sizes="320 640 1280" sources="4 9 19" threads="1 2"
while [ $# -gt 0 ]; do
  case "$1" in
    --sizes) sizes=$2; shift 2 ;;
    --sources) sources=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    *) break ;;
  esac
done
[ -n "${threads// /}" ] || { echo "--threads: give at least one thread count" >&2; exit 1; }
for t in $threads; do
  [[ "$t" =~ ^[1-9][0-9]*$ ]] || { echo "--threads: '$t' is not a positive thread count" >&2; exit 1; }
done
options=("$@")
for arg in "${options[@]}"; do
  case "$arg" in
    --PatchMatchStereo.num_threads*)
      echo "give the thread counts with --threads, not --PatchMatchStereo.num_threads" >&2
      exit 1 ;;
  esac
done
top=$(mktemp -d)
trap 'rm -rf "$top"' EXIT
read -r load _ < /proc/loadavg  # other work on the machine skews the thread scaling

# row KIND LABEL WORKSPACE IMAGES THREADS: one run (run_row) with THREADS
# threads and its figures per image; appends "KIND THREADS WALL USER LABEL" to
# $top/walls for the thread scaling.
row() {
  ablation_init "$3"
  trap 'rm -rf "$scratch" "$top"' EXIT
  run_row "${options[@]}" --PatchMatchStereo.num_threads "$5" > /dev/null
  read -r wall user < "$scratch/time"
  python3 - "$1" "$2" "$4" "$5" "$wall" "$user" "$scratch/eval.json" "$scratch/ws" \
    "$top/walls" "$top/angles-$(basename "$3").json" "${options[@]}" <<'PY'
import json, math, os, struct, sys
kind, label, images, threads = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
wall, user, path, ws, walls = float(sys.argv[5]), float(sys.argv[6]), sys.argv[7], sys.argv[8], sys.argv[9]
cache, options = sys.argv[10], sys.argv[11:]


def option(name, default):
    """The value of msp_stereo option `name` among the options given."""
    value = default
    for i, arg in enumerate(options):
        if arg == name and i + 1 < len(options):
            value = options[i + 1]
        elif arg.startswith(name + "="):
            value = arg[len(name) + 1:]
    return value


def problems():
    """(reference, source spec) pairs of stereo/patch-match.cfg, as msp_stereo reads it."""
    lines = [l.strip() for l in open(os.path.join(ws, "stereo", "patch-match.cfg"))]
    lines = [l for l in lines if l and not l.startswith("#")]
    return [(lines[i], [s.strip() for s in lines[i + 1].replace(";", ",").split(",") if s.strip()])
            for i in range(0, len(lines) - 1, 2)]


def read_model():
    """Names, centres and the point tracks (image ids) of sparse/*.bin."""
    names, centres, tracks = {}, {}, []
    with open(os.path.join(ws, "sparse", "images.bin"), "rb") as f:
        for _ in range(struct.unpack("<Q", f.read(8))[0]):
            image_id, qw, qx, qy, qz, tx, ty, tz, _ = struct.unpack("<I7dI", f.read(64))
            name = b""
            while (ch := f.read(1)) != b"\0":
                name += ch
            f.read(24 * struct.unpack("<Q", f.read(8))[0])
            n = math.sqrt(qw * qw + qx * qx + qy * qy + qz * qz)
            qw, qx, qy, qz = qw / n, qx / n, qy / n, qz / n
            R = [[1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy - qw * qz), 2 * (qx * qz + qw * qy)],
                 [2 * (qx * qy + qw * qz), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz - qw * qx)],
                 [2 * (qx * qz - qw * qy), 2 * (qy * qz + qw * qx), 1 - 2 * (qx * qx + qy * qy)]]
            names[image_id] = name.decode()
            centres[image_id] = [-sum(R[r][c] * (tx, ty, tz)[r] for r in range(3)) for c in range(3)]
    with open(os.path.join(ws, "sparse", "points3D.bin"), "rb") as f:
        for _ in range(struct.unpack("<Q", f.read(8))[0]):
            _, x, y, z, _, _, _, _, n = struct.unpack("<Q3d3BdQ", f.read(51))
            track = struct.unpack("<%dI" % (2 * n), f.read(8 * n))[0::2]
            tracks.append(((x, y, z), [i for i in track if i in names]))
    return names, centres, tracks


def pair_angles():
    """Per reference name, the 75th percentile triangulation angle with every
    image it shares points with (COLMAP's rule, io/source_selection.cc);
    cached in `cache` for the other rows on the same scene."""
    if os.path.exists(cache):
        return json.load(open(cache))
    names, centres, tracks = read_model()
    angles = {}  # (image id, other image id) -> [(angle, count)]
    for X, track in tracks:
        counts = {i: track.count(i) for i in set(track)}
        ids = sorted(counts)
        r2 = {i: sum((a - b) ** 2 for a, b in zip(X, centres[i])) for i in ids}
        for j, a in enumerate(ids):
            for b in ids[j + 1:]:
                d = 2 * math.sqrt(r2[a] * r2[b])
                b2 = sum((u - v) ** 2 for u, v in zip(centres[a], centres[b]))
                t = abs(math.acos(max(-1.0, min(1.0, (r2[a] + r2[b] - b2) / d)))) if d else 0.0
                value = (min(t, math.pi - t), counts[a] * counts[b])
                angles.setdefault((a, b), []).append(value)
                angles.setdefault((b, a), []).append(value)
    result = {}
    for (a, b), values in angles.items():
        values.sort()
        total = sum(c for _, c in values)
        idx = min(max(round(0.75 * (total - 1)), 0), total - 1)
        seen = 0
        for t, c in values:
            seen += c
            if seen > idx:
                break
        result.setdefault(names[a], {})[names[b]] = t
    result["__images__"] = len(names)
    json.dump(result, open(cache, "w"))
    return result


def megapixels(ref):
    """Width x height of the map msp_stereo wrote for `ref`, in megapixels."""
    for suffix in ("geometric", "photometric"):
        p = os.path.join(ws, "stereo", "depth_maps", "%s.%s.bin" % (ref, suffix))
        if os.path.exists(p):
            with open(p, "rb") as f:
                w, h = f.read(64).split(b"&")[:2]
            return int(w) * int(h) / 1e6
    sys.exit("%s: no depth map of %s" % (ws, ref))


angles = None
min_angle = math.radians(float(option("--PatchMatchStereo.min_triangulation_angle", "1")))
mp_sources = 0.0
for ref, spec in problems():
    if spec == ["__all__"]:
        angles = angles or pair_angles()
        n = angles["__images__"] - 1
    elif len(spec) == 2 and spec[0] == "__auto__":
        angles = angles or pair_angles()
        n = min(sum(t >= min_angle for t in angles.get(ref, {}).values()), int(spec[1]))
    else:
        n = len(spec)
    mp_sources += megapixels(ref) * n
t = [x for x in json.load(open(path))["fused"]["thresholds"] if not x["absolute"]]
f1 = " / ".join("%.2f" % (100 * x["f1_multi"]) for x in t)
print("| %s | %d | %.1f | %.1f | %.1f | %s |" % (
    label, threads, wall / images, user / images, user / mp_sources if mp_sources else float("nan"), f1))
with open(walls, "a") as f:
    f.write("%s %d %.3f %.3f %s\n" % (kind, threads, wall, user, label))
PY
  rm -rf "$scratch"
}

echo "| run | threads | wall s / image | user CPU-s / image | user CPU-s / MP / source | fused F1 at 0.5 / 2 % |"
echo "|---|---|---|---|---|---|"
for width in $sizes; do
  ws="$top/scene-$width"
  "$bin/msp_make_scene" --output "$ws" --width "$width" --height $((width * 3 / 4)) > /dev/null
  for t in $threads; do
    row size "${width}x$((width * 3 / 4)), 10 views, 9 sources" "$ws" 10 "$t"
  done
done
if [ -n "${sources// /}" ]; then
  ws="$top/scene-20"
  "$bin/msp_make_scene" --output "$ws" --width 320 --height 240 --num_cameras 20 > /dev/null
  for n in $sources; do
    sed -i "s/^__auto__.*/__auto__, $n/" "$ws/stereo/patch-match.cfg"
    for t in $threads; do
      row sources "320x240, 20 views, $n sources" "$ws" 20 "$t"
    done
  done
fi

# The thread scaling of the size rows: S = wall(1) / wall(T) at the largest
# count T, Amdahl's parallel fraction p = (1 - 1/S) / (1 - 1/T) and the
# speed-up 1 / ((1 - p) + p / n) it predicts on n cores.
[ -s "$top/walls" ] || exit 0
python3 - "$top/walls" "$(nproc)" "$load" <<'PY'
import sys
rows, cores, load = {}, int(sys.argv[2]), float(sys.argv[3])
for line in open(sys.argv[1]):
    kind, threads, wall, user, label = line.rstrip("\n").split(" ", 4)
    if kind == "size":
        rows.setdefault(label, {})[int(threads)] = (float(wall), float(user))
T = max([t for walls in rows.values() for t in walls] or [1])
both = [(label, w) for label, w in rows.items() if 1 in w and T in w and T > 1]
print()
if not both:
    print("Thread scaling: needs size rows at 1 and at a larger thread count (--threads \"1 2\").")
    sys.exit(0)
print("Thread scaling of msp_stereo's wall time (Amdahl's law from 1 and %d threads):" % T)
print()
print("| run | speed-up at %d | cores used at %d (user / wall) | parallel fraction p | "
      "predicted speed-up on 16 cores | on 64 cores |" % (T, T))
print("|---|---|---|---|---|---|")
clamped = False
for label, w in both:
    S = w[1][0] / w[T][0]
    p = (1 - 1 / S) / (1 - 1 / T)
    q = min(max(p, 0.0), 1.0)
    clamped |= q != p
    predict = lambda n: 1 / ((1 - q) + q / n)
    print("| %s | %.2f | %.2f | %.3f | %.1f | %.1f |" % (
        label, S, w[T][1] / w[T][0], p, predict(16), predict(64)))
print()
print("The predictions assume the same per-core speed and memory bandwidth per core as here; "
      "a single measured speed-up at %d threads leaves p uncertain, and the error grows with n." % T)
if clamped:
    print("p outside [0, 1] (timing noise or a superlinear speed-up) is taken as 0 or 1 for the predictions.")
if load >= 0.5:
    print("WARNING: load average %.2f before the first run: other work shared the %d cores, so the "
          "speed-up and p are too low; measure on an idle machine." % (load, cores))
if T > cores:
    print("WARNING: %d threads on %d cores: the speed-up measures oversubscription, not scaling." % (T, cores))
PY
