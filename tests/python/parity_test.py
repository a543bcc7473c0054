"""msp_stereo.patch_match_stereo against the msp_stereo program: the bundled
scene at 160 pixels, the same options, byte-identical maps; the log through
logging, the progress callback, the GIL released during the run, a second
call that finds everything done, and read_array against COLMAP's
read_write_dense.py."""

import logging
import threading
import time
import unittest

import numpy as np

import msp_stereo
import support


def colmap_read_array(path):
    """COLMAP's scripts/python/read_write_dense.py, read_array."""
    with open(path, "rb") as fid:
        width, height, channels = np.genfromtxt(fid, delimiter="&", max_rows=1, usecols=(0, 1, 2),
                                                dtype=int)
        fid.seek(0)
        num_delimiter = 0
        byte = fid.read(1)
        while True:
            if byte == b"&":
                num_delimiter += 1
                if num_delimiter >= 3:
                    break
            byte = fid.read(1)
        array = np.fromfile(fid, np.float32)
    array = array.reshape((width, height, channels), order="F")
    return np.transpose(array, (1, 0, 2)).squeeze()


class Records(logging.Handler):
    def __init__(self):
        super().__init__(level=logging.DEBUG)
        self.records = []

    def emit(self, record):
        self.records.append(record)


class Ticker:
    """A Python thread that ticks every few milliseconds, which it can only
    do while no other thread holds the GIL."""

    PERIOD = 0.005  # seconds

    def __init__(self):
        self.ticks = 0
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run)
        self._thread.start()

    def _run(self):
        while not self._stop.wait(self.PERIOD):
            self.ticks += 1

    def stop(self):
        self._stop.set()
        self._thread.join()


class ParityTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scratch = support.Scratch()
        cls.scene = cls.scratch.path / "scene"
        support.make_scene(cls.scene)

    @classmethod
    def tearDownClass(cls):
        cls.scratch.cleanup()

    def test_maps_are_the_programs_byte_for_byte(self):
        # num_iterations is accepted and ignored: the run warns of it.
        # One thread: the ticker below has a core of its own.
        options = msp_stereo.PatchMatchOptions(max_image_size=160, num_threads=1,
                                               num_iterations=3)
        msp_options = msp_stereo.MspStereoOptions()
        # Not the default seed, so that the maps show the seed reached the run.
        seed = 3
        program_ws = support.copy_workspace(self.scene, self.scratch.path / "program")
        result = support.run_program(program_ws, options, msp_options, random_seed=seed)
        self.assertEqual(result.returncode, 0, result.stderr)

        python_ws = support.copy_workspace(self.scene, self.scratch.path / "python")
        logger = logging.getLogger(msp_stereo.LOGGER_NAME)
        records = Records()
        logger.addHandler(records)
        logger.setLevel(logging.DEBUG)
        progress = []
        ticker = Ticker()
        start = time.monotonic()
        try:
            msp_stereo.patch_match_stereo(
                str(python_ws), options=options, msp_options=msp_options, random_seed=seed,
                progress=lambda done, total, seconds_left: progress.append(
                    (done, total, seconds_left)))
        finally:
            ticker.stop()
            logger.removeHandler(records)
        possible_ticks = (time.monotonic() - start) / Ticker.PERIOD

        self.assertEqual(len(support.map_files(python_ws)), 40)
        self.assertEqual(support.map_files(python_ws), support.map_files(program_ws))
        self.assertEqual(support.differing_maps(python_ws, program_ws), [])
        self.assertEqual(support.leftovers(python_ws), [])

        # One report per image-pass: 10 images, 2 rounds of 4 passes.
        self.assertEqual([done for done, _, _ in progress], list(range(1, 81)))
        self.assertEqual({total for _, total, _ in progress}, {80})
        self.assertTrue(all(left is None or left >= 0 for _, _, left in progress))
        self.assertEqual(progress[-1][2], 0)

        # The program's log, line by line, at the levels of logging.
        messages = [record.getMessage() for record in records.records]
        program_lines = [line for line in result.stdout.splitlines() if line]
        self.assertEqual(len(messages), len(program_lines))
        self.assertIn("Reading workspace %s..." % python_ws, messages)
        by_level = lambda level: [r.getMessage() for r in records.records if r.levelno == level]
        self.assertTrue(any(m.startswith("--PatchMatchStereo.num_iterations is ignored")
                            for m in by_level(logging.WARNING)))
        self.assertTrue(any(m.startswith("Round 2/2, geometric pass 4, image 10/10")
                            for m in by_level(logging.INFO)))
        self.assertTrue(any(m.startswith("  segment planes:") for m in by_level(logging.DEBUG)))

        # The ticker ran while the stereo did, not only in the moments the
        # run took the GIL to log or to report progress: it ticked for at
        # least half the run (the run's length, not a count of its calls into
        # Python, sets the bound, so a faster machine does not fail it).
        self.assertGreater(ticker.ticks, 0.5 * possible_ticks)

        # A second call finds every image done.
        records = Records()
        logger.addHandler(records)
        try:
            msp_stereo.patch_match_stereo(python_ws, options=options, msp_options=msp_options)
        finally:
            logger.removeHandler(records)
        self.assertIn("All 10 reference images already have their outputs; nothing to do.",
                      [record.getMessage() for record in records.records])

        # read_array reads what COLMAP's script reads, C-contiguous.
        for kind, shape in (("depth_maps", (120, 160)), ("normal_maps", (120, 160, 3))):
            path = python_ws / "stereo" / kind / "img_003.png.geometric.bin"
            array = msp_stereo.read_array(path)
            self.assertEqual(array.shape, shape)
            self.assertEqual(array.dtype, np.float32)
            self.assertTrue(array.flags["C_CONTIGUOUS"])
            np.testing.assert_array_equal(array, colmap_read_array(path))
        self.assertGreater(np.count_nonzero(msp_stereo.read_array(
            python_ws / "stereo/depth_maps/img_003.png.geometric.bin")), 0.5 * 160 * 120)


if __name__ == "__main__":
    unittest.main()
