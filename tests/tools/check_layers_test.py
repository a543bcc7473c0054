#!/usr/bin/env python3
"""tools/check_layers.py: the tree passes; an include up a layer or across to
another group of the same layer fails, naming the file and line."""

import os
import pathlib
import subprocess
import sys
import tempfile
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "tools" / "check_layers.py"


def check(root):
    return subprocess.run([sys.executable, str(SCRIPT), "--root", str(root)], capture_output=True,
                          text=True)


class CheckLayersTest(unittest.TestCase):
    def setUp(self):
        self.scratch = tempfile.TemporaryDirectory(prefix="check_layers_test_")
        self.root = pathlib.Path(self.scratch.name)

    def tearDown(self):
        self.scratch.cleanup()

    def write(self, path, text):
        file = self.root / path
        file.parent.mkdir(parents=True, exist_ok=True)
        file.write_text(text)

    def test_the_tree_has_no_upward_include(self):
        result = check(ROOT)
        self.assertEqual(result.returncode, 0, result.stdout)

    def test_downward_includes_pass(self):
        self.write("src/core/math/camera.h", "#pragma once\n")
        self.write("src/patch_match/sweeps.h", '#include "core/math/camera.h"\n')
        self.write("io/workspace.cc", '#include "patch_match/sweeps.h"\n#include <vector>\n')
        result = check(self.root)
        self.assertEqual(result.returncode, 0, result.stdout)

    def test_an_include_up_a_layer_fails(self):
        self.write("src/patch_match/pixel_state.h", "#pragma once\n")
        self.write("src/base/mvs_input.h", '#pragma once\n\n#include "patch_match/pixel_state.h"\n')
        result = check(self.root)
        self.assertEqual(result.returncode, 1)
        self.assertIn("src/base/mvs_input.h:3: includes src/patch_match/pixel_state.h", result.stdout)
        self.assertIn("above", result.stdout)

    def test_an_include_beside_fails(self):
        self.write("tools/evaluate/evaluate_report.h", "#pragma once\n")
        self.write("python/module.cc", '#include "tools/evaluate/evaluate_report.h"\n')
        result = check(self.root)
        self.assertEqual(result.returncode, 1)
        self.assertIn("python/module.cc:1: includes tools/evaluate/evaluate_report.h (tools) from "
                      "python, which is beside it", result.stdout)

    def test_a_relative_include_is_resolved_from_its_folder(self):
        self.write("src/patch_match/pixel_state.h", "#pragma once\n")
        self.write("src/base/mvs_input.h", '#include "../patch_match/pixel_state.h"\n')
        result = check(self.root)
        self.assertEqual(result.returncode, 1)
        self.assertIn("src/base/mvs_input.h:1: includes src/patch_match/pixel_state.h", result.stdout)

if __name__ == "__main__":
    unittest.main()
