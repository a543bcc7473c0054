#!/bin/sh
# The Debian package: `cpack -G DEB` from the build folder, unpacked into a
# scratch root with `dpkg-deb -x` (no root needed): it holds msp_stereo, the
# tools and the dispatcher under /usr/lib/msp-stereo/bin and nothing in
# /usr/bin, declares colmap and the runtime libraries as dependencies, and the
# installed msp_stereo and dispatcher run; the Python module, when built, is
# in /usr/lib/python3/dist-packages and imports.
# Usage: deb_package_test.sh <build folder>
set -u
[ $# -eq 1 ] || { echo "usage: $0 <build folder>" >&2; exit 2; }
BUILD=$1

. "$(dirname "$0")/../support/checks.sh"

if ! cpack -G DEB --config "$BUILD/CPackConfig.cmake" -B "$TMP/package" > "$TMP/cpack.log" 2>&1; then
  cat "$TMP/cpack.log"
  fail "cpack -G DEB"
  finish
fi
pass "cpack -G DEB"
DEB=$(ls "$TMP"/package/msp-stereo_*.deb 2>/dev/null | head -n 1)
[ -n "$DEB" ] || { fail "a msp-stereo_*.deb is written"; finish; }

depends=$(dpkg-deb -f "$DEB" Depends)
expect_contains "Depends names colmap" "$depends" "colmap"
expect_contains "Depends names OpenCV" "$depends" "libopencv-imgcodecs"
expect_contains "Depends names Boost.Program_options" "$depends" "libboost-program-options"

contents=$(dpkg-deb -c "$DEB")
expect_eq "nothing in /usr/bin" "$(printf '%s\n' "$contents" | grep -c ' \./usr/bin/')" "0"

ROOT="$TMP/root"
dpkg-deb -x "$DEB" "$ROOT"
BIN="$ROOT/usr/lib/msp-stereo/bin"
for tool in msp_stereo colmap msp_evaluate msp_make_scene msp_write_gt_maps msp_convert_masks \
    msp_import_rgbd; do
  if [ -x "$BIN/$tool" ]; then pass "installed $tool"; else fail "installed $tool"; fi
done

help=$("$BIN/msp_stereo" --help 2>&1); rc=$?
expect_eq "msp_stereo --help exits 0" "$rc" "0"
expect_contains "msp_stereo --help prints the usage" "$help" "Usage: msp_stereo"
# The dispatcher, called by its path with only the system on PATH, finds
# the msp_stereo next to it and the real colmap in /usr/bin.
help=$(env -u MSP_STEREO PATH=/usr/bin:/bin "$BIN/colmap" msp_stereo --help 2>&1); rc=$?
expect_eq "colmap msp_stereo --help exits 0" "$rc" "0"
expect_contains "colmap msp_stereo --help is msp_stereo's" "$help" "Usage: msp_stereo"
help=$(env -u MSP_STEREO PATH=/usr/bin:/bin "$BIN/colmap" --help 2>&1)
expect_contains "colmap --help lists msp_stereo" "$help" "msp_stereo"

# The Python module, when the build has one: in Debian's python3 folder (not
# under the prefix), importable from there, python3 and numpy recommended.
if ls "$BUILD"/python/msp_stereo*.so > /dev/null 2>&1; then
  SITE=usr/lib/python3/dist-packages
  expect_eq "the Python module in /$SITE" \
    "$(printf '%s\n' "$contents" | grep -c " \./$SITE/msp_stereo\..*\.so\$")" "1"
  expect_eq "no Python module under /usr/lib/msp-stereo" \
    "$(printf '%s\n' "$contents" | grep -c ' \./usr/lib/msp-stereo/.*msp_stereo\..*\.so$')" "0"
  recommends=$(dpkg-deb -f "$DEB" Recommends)
  expect_contains "Recommends names python3-numpy" "$recommends" "python3-numpy"
  expect_contains "Recommends names python3" "$recommends" "python3 (>= "
  imported=$(PYTHONPATH="$ROOT/$SITE" /usr/bin/python3 -c \
    'import msp_stereo; print(msp_stereo.PatchMatchOptions().window_radius)' 2>&1)
  expect_eq "the packaged Python module imports" "$imported" "5"
fi
finish
