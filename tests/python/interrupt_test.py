"""Stopping msp_stereo.patch_match_stereo: a KeyboardInterrupt from the
progress callback and a SIGINT (Ctrl-C) stop it as SIGINT stops the
program, between two steps; no map is half-written, no temporary file is
left, and the same call resumes to the maps of an uninterrupted run of the
program. Python's own SIGINT handler is back afterwards."""

import os
import signal
import time
import unittest

import msp_stereo
import support


class InterruptTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scratch = support.Scratch()
        cls.scene = cls.scratch.path / "scene"
        support.make_scene(cls.scene, *support.SMALL_SCENE)
        cls.reference = support.copy_workspace(cls.scene, cls.scratch.path / "reference")
        result = support.run_program(cls.reference, *support.small_run_options())
        assert result.returncode == 0, result.stderr
        assert len(support.map_files(cls.reference)) == 12

    @classmethod
    def tearDownClass(cls):
        cls.scratch.cleanup()

    def stop_and_resume(self, name, act, expected):
        """Runs until `act(done)` stops the run with the exception `expected`,
        checks what is left, resumes; returns the stopped run's exception."""
        workspace = support.copy_workspace(self.scene, self.scratch.path / name)
        options, msp_options = support.small_run_options()
        calls = []

        def progress(done, total, seconds_left):
            calls.append(done)
            act(done)

        with self.assertRaises(expected) as raised:
            msp_stereo.patch_match_stereo(workspace, options=options, msp_options=msp_options,
                                          progress=progress)
        self.assertLess(calls[-1], 12, "the run did not stop")
        self.assertEqual(support.leftovers(workspace), [])
        # What is there is final: byte-identical to the uninterrupted run's.
        self.assertEqual(support.differing_maps(workspace, self.reference), [])
        self.assertIs(signal.getsignal(signal.SIGINT), signal.default_int_handler)

        msp_stereo.patch_match_stereo(workspace, options=options, msp_options=msp_options)
        self.assertEqual(support.map_files(workspace), support.map_files(self.reference))
        self.assertEqual(support.differing_maps(workspace, self.reference), [])
        self.assertEqual(support.leftovers(workspace), [])
        return raised.exception, calls

    def test_keyboard_interrupt_from_the_callback_stops_as_sigint(self):
        def interrupt(done):
            if done == 5:
                raise KeyboardInterrupt

        stop, calls = self.stop_and_resume("callback", interrupt, KeyboardInterrupt)
        self.assertEqual(calls, [1, 2, 3, 4, 5])
        self.assertTrue(str(stop).startswith(
            "Stopped by SIGINT between two steps; nothing is half-written. "), str(stop))
        self.assertIn("run the same command again to resume", str(stop))

    def test_sigint_stops_the_run_and_python_gets_its_handler_back(self):
        def ctrl_c(done):
            if done == 6:
                os.kill(os.getpid(), signal.SIGINT)

        stop, calls = self.stop_and_resume("sigint", ctrl_c, KeyboardInterrupt)
        self.assertEqual(calls, [1, 2, 3, 4, 5, 6])
        self.assertIn("Stopped by SIGINT between two steps", str(stop))
        # Ctrl-C is Python's again.
        with self.assertRaises(KeyboardInterrupt):
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(5)  # the handler ends the sleep at once

    def test_another_exception_from_the_callback_ends_the_run_with_it(self):
        class Mine(Exception):
            pass

        def fail(done):
            if done == 3:
                raise Mine("from the callback")

        stop, calls = self.stop_and_resume("exception", fail, Mine)
        self.assertEqual(str(stop), "from the callback")
        self.assertEqual(calls, [1, 2, 3])


if __name__ == "__main__":
    unittest.main()
