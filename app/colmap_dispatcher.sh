#!/bin/sh
# msp-colmap-dispatcher (marker: other dispatcher copies on PATH are skipped by it)
#
# Installed as `colmap` ahead of the real COLMAP (earlier in PATH, or in
# $COLMAP_EXE_PATH, which COLMAP's run-colmap-*.sh scripts call). COLMAP has no
# plugin mechanism, so this is how `colmap msp_stereo` becomes a command:
#
#   colmap msp_stereo ARGS          -> msp_stereo ARGS
#   colmap patch_match_stereo ARGS  -> msp_stereo ARGS if MSP_REPLACE_PATCH_MATCH=1
#   colmap [help|-h|--help]         -> the real help, with msp_stereo in the command list
#   colmap anything else            -> the real colmap, unchanged (exec: same arguments,
#                                      stdin/stdout/stderr and exit code)
#
# Environment:
#   REAL_COLMAP             the real colmap executable. Default: the first `colmap` on
#                           PATH that is not a dispatcher, else /usr/bin/colmap.
#   MSP_STEREO              the msp_stereo executable. Default: next to this script
#                           (as invoked, then with symlinks resolved), else PATH.
#   MSP_REPLACE_PATCH_MATCH 1 = route patch_match_stereo to msp_stereo (useful because
#                           Debian's COLMAP is built without CUDA and refuses to run it).

readonly MARKER='msp-colmap-dispatcher'

die() {
  echo "ERROR: colmap dispatcher: $*" >&2
  exit 127
}

# Absolute path with symlinks resolved; the input itself if no tool can do it.
resolve() {
  readlink -f -- "$1" 2>/dev/null || realpath -- "$1" 2>/dev/null || printf '%s\n' "$1"
}

SELF=$(resolve "$0")

is_executable_file() {
  [ -f "$1" ] && [ -x "$1" ]
}

# A copy of this script (build tree and install prefix can both be on PATH);
# exec'ing one would loop forever. Only the first bytes are read.
is_dispatcher() {
  [ "$(resolve "$1")" = "$SELF" ] && return 0
  head -c 256 -- "$1" 2>/dev/null | grep -q "$MARKER"
}

find_real_colmap() {
  if [ -n "${REAL_COLMAP:-}" ]; then
    is_executable_file "$REAL_COLMAP" || die "REAL_COLMAP=$REAL_COLMAP is not an executable file"
    [ "$(resolve "$REAL_COLMAP")" != "$SELF" ] || die "REAL_COLMAP points to this dispatcher"
    printf '%s\n' "$REAL_COLMAP"
    return
  fi
  old_ifs=$IFS
  IFS=:
  for dir in $PATH; do
    [ -n "$dir" ] || dir=.
    candidate="$dir/colmap"
    if is_executable_file "$candidate" && ! is_dispatcher "$candidate"; then
      IFS=$old_ifs
      printf '%s\n' "$candidate"
      return
    fi
  done
  IFS=$old_ifs
  if is_executable_file /usr/bin/colmap && ! is_dispatcher /usr/bin/colmap; then
    printf '%s\n' /usr/bin/colmap
    return
  fi
  die "cannot find the real colmap executable (not on PATH, no /usr/bin/colmap); set REAL_COLMAP"
}

find_msp_stereo() {
  if [ -n "${MSP_STEREO:-}" ]; then
    is_executable_file "$MSP_STEREO" || die "MSP_STEREO=$MSP_STEREO is not an executable file"
    printf '%s\n' "$MSP_STEREO"
    return
  fi
  for dir in "$(dirname -- "$0")" "$(dirname -- "$SELF")"; do
    if is_executable_file "$dir/msp_stereo"; then
      printf '%s\n' "$dir/msp_stereo"
      return
    fi
  done
  command -v msp_stereo 2>/dev/null && return
  die "cannot find msp_stereo (not next to $0, not on PATH); set MSP_STEREO"
}

run_msp_stereo() {
  msp_stereo=$(find_msp_stereo) || exit $?
  exec "$msp_stereo" "$@"
}

# The real help with msp_stereo inserted into the (alphabetical) command list,
# before patch_match_stereo, or at the end if the list looks different.
show_help() {
  real=$(find_real_colmap) || exit $?
  help_text=$("$real" "$@")
  rc=$?
  printf '%s\n' "$help_text" | awk '
    /^  patch_match_stereo$/ && !done { print "  msp_stereo"; done = 1 }
    { print }
    END { if (!done) print "  msp_stereo" }'
  exit "$rc"
}

case "${1-}" in
  msp_stereo)
    shift
    run_msp_stereo "$@"
    ;;
  patch_match_stereo)
    if [ "${MSP_REPLACE_PATCH_MATCH:-0}" = 1 ]; then
      shift
      run_msp_stereo "$@"
    fi
    ;;
  '' | help | -h | --help)
    show_help "$@"
    ;;
esac

real=$(find_real_colmap) || exit $?
exec "$real" "$@"
