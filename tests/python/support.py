"""Shared by the Python module's tests: the build's programs, generated
workspaces, runs of the msp_stereo program with the options of the Python
classes, and byte-wise comparisons of the maps.

ctest sets PYTHONPATH to the build's python/ (the module) and MSP_BIN_DIR to
its bin/ (the programs)."""

import os
import pathlib
import shutil
import subprocess
import tempfile

import msp_stereo

BIN_DIR = pathlib.Path(os.environ["MSP_BIN_DIR"])

# A round of 3 small images: 12 image-passes of a fraction of a second.
SMALL_SCENE = ["--width", "128", "--height", "96", "--num_cameras", "3", "--seed", "5"]


def small_run_options():
    """The options of the small scene's runs: one round, one thread (CI
    machines are shared)."""
    return (msp_stereo.PatchMatchOptions(num_threads=1),
            msp_stereo.MspStereoOptions(advanced_coarsest_image_size=128))


class Scratch:
    """A scratch folder, removed with everything in it by cleanup()."""

    def __init__(self):
        self.path = pathlib.Path(tempfile.mkdtemp(prefix="msp_python_test_"))

    def cleanup(self):
        shutil.rmtree(self.path, ignore_errors=True)


def make_scene(path, *args):
    """A fresh workspace without maps: msp_make_scene's bundled scene."""
    subprocess.run([str(BIN_DIR / "msp_make_scene"), "--output", str(path), *args], check=True,
                   stdout=subprocess.DEVNULL)


def copy_workspace(source, target):
    shutil.copytree(source, target)
    return target


def option_words(options):
    """The program's words for an options object: --<Section>.<field> <value>,
    each value as the parser reads it back exactly (repr of a float is)."""
    section = "PatchMatchStereo" if isinstance(options, msp_stereo.PatchMatchOptions) \
        else "MspStereo"
    words = []
    for name, value in options.todict().items():
        if isinstance(value, bool):
            value = "true" if value else "false"
        words += ["--%s.%s" % (section, name), repr(value) if isinstance(value, float) else
                  str(value)]
    return words


def run_program(workspace, options, msp_options, random_seed=0):
    """msp_stereo on `workspace` with the options of the Python objects."""
    return subprocess.run([str(BIN_DIR / "msp_stereo"), "--workspace_path", str(workspace),
                           "--random_seed", str(random_seed)] +
                          option_words(options) + option_words(msp_options),
                          capture_output=True, text=True)


def map_files(workspace):
    """The files of the map folders, relative to stereo/, sorted."""
    stereo = pathlib.Path(workspace) / "stereo"
    return sorted(str(path.relative_to(stereo)) for folder in ("depth_maps", "normal_maps")
                  for path in (stereo / folder).rglob("*") if path.is_file())


def leftovers(workspace):
    """Temporary files of atomic writes and spilled states under stereo/."""
    stereo = pathlib.Path(workspace) / "stereo"
    return sorted(str(path) for path in stereo.rglob("*")
                  if ".tmp-" in path.name or path.name.startswith("state-"))


def differing_maps(workspace, reference):
    """The map files of `workspace` that are not byte-identical to the
    reference's (a file the reference lacks counts)."""
    differing = []
    for name in map_files(workspace):
        mine = pathlib.Path(workspace) / "stereo" / name
        theirs = pathlib.Path(reference) / "stereo" / name
        if not theirs.is_file() or mine.read_bytes() != theirs.read_bytes():
            differing.append(name)
    return differing
