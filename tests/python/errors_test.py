"""Errors of msp_stereo.patch_match_stereo and of the option classes: Python
exceptions carrying the msp_stereo program's messages (its "ERROR: ..."
line), and nothing written."""

import pathlib
import pickle
import unittest

import msp_stereo
import support


def program_error(result):
    """The message of the program's one "ERROR: ..." line on stderr."""
    lines = [line for line in result.stderr.splitlines() if line.startswith("ERROR: ")]
    assert len(lines) == 1, result.stderr
    return lines[0][len("ERROR: "):]


class ErrorsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scratch = support.Scratch()
        cls.scene = cls.scratch.path / "scene"
        support.make_scene(cls.scene, *support.SMALL_SCENE)

    @classmethod
    def tearDownClass(cls):
        cls.scratch.cleanup()

    def workspace(self, name):
        return support.copy_workspace(self.scene, self.scratch.path / name)

    def assert_same_error(self, workspace, options, msp_options, error_type):
        """The program fails with a message; the module raises `error_type`
        with the same message. Neither writes a map."""
        result = support.run_program(workspace, options, msp_options)
        self.assertEqual(result.returncode, 1, result.stdout)
        with self.assertRaises(error_type) as raised:
            msp_stereo.patch_match_stereo(workspace, options=options, msp_options=msp_options)
        self.assertEqual(str(raised.exception), program_error(result))
        if pathlib.Path(workspace).is_dir():
            self.assertEqual(support.map_files(workspace), [])
        return str(raised.exception)

    def test_a_missing_image_names_the_file(self):
        workspace = self.workspace("missing_image")
        missing = workspace / "images" / "img_001.png"
        missing.unlink()
        options, msp_options = support.small_run_options()
        message = self.assert_same_error(workspace, options, msp_options, msp_stereo.InputError)
        self.assertIn("image file %s does not exist" % missing, message)
        self.assertTrue(issubclass(msp_stereo.InputError, RuntimeError))

    def test_a_missing_workspace_is_named(self):
        options, msp_options = support.small_run_options()
        message = self.assert_same_error(self.scratch.path / "nowhere", options, msp_options,
                                         msp_stereo.InputError)
        self.assertIn(str(self.scratch.path / "nowhere"), message)

    def test_an_invalid_option_is_named_as_on_the_command_line(self):
        workspace = self.workspace("bad_option")
        options, msp_options = support.small_run_options()
        options.window_radius = 40
        message = self.assert_same_error(workspace, options, msp_options, ValueError)
        self.assertTrue(message.startswith(
            "invalid value 40 for --PatchMatchStereo.window_radius: must be in [1, 20]"), message)
        with self.assertRaises(msp_stereo.OptionError) as raised:
            options.check()
        self.assertEqual(str(raised.exception), message)
        msp_options = msp_stereo.MspStereoOptions(backend="gpu")
        with self.assertRaises(msp_stereo.OptionError) as raised:
            msp_options.check()
        self.assertEqual(str(raised.exception), "invalid value `gpu` for --MspStereo.backend: "
                         "must be one of {auto, cpu, cuda}")

    def test_options_take_their_names_and_types_only(self):
        with self.assertRaises(TypeError) as raised:
            msp_stereo.PatchMatchOptions(window_radus=3)
        self.assertIn("window_radus", str(raised.exception))
        options = msp_stereo.PatchMatchOptions()
        with self.assertRaises(AttributeError):
            options.window_radus = 3
        for name, value in (("window_radius", 3.5), ("geom_consistency", 1),
                            ("gpu_index", 0), ("depth_min", "1")):
            with self.assertRaises(TypeError, msg=name):
                setattr(options, name, value)
        options.depth_min = 1  # an int is a float
        self.assertEqual(options.depth_min, 1.0)
        self.assertEqual(options, msp_stereo.PatchMatchOptions(depth_min=1.0))
        self.assertNotEqual(options, msp_stereo.PatchMatchOptions())
        self.assertEqual(pickle.loads(pickle.dumps(options)), options)

    def test_options_print_as_their_constructor(self):
        options = msp_stereo.PatchMatchOptions(max_image_size=160, gpu_index="0,1")
        text = repr(options)
        self.assertTrue(text.startswith("PatchMatchOptions(max_image_size=160, gpu_index='0,1', "),
                        text)
        self.assertEqual(eval(text, vars(msp_stereo)), options)
        self.assertIn("segmenter='opencv'", repr(msp_stereo.MspStereoOptions()))
        self.assertIn("NCC", msp_stereo.PatchMatchOptions.window_radius.__doc__)

    def test_read_array_names_a_bad_file(self):
        with self.assertRaises(msp_stereo.InputError) as raised:
            msp_stereo.read_array(self.scratch.path / "none.bin")
        self.assertIn(str(self.scratch.path / "none.bin"), str(raised.exception))
        corrupt = self.scratch.path / "corrupt.bin"
        corrupt.write_bytes(b"4&3&1&" + b"\0" * 7)
        with self.assertRaises(msp_stereo.InputError) as raised:
            msp_stereo.read_array(corrupt)
        self.assertIn("does not match its header", str(raised.exception))


if __name__ == "__main__":
    unittest.main()
