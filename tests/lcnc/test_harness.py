#!/usr/bin/python3
"""The anchor's own logic, without LinuxCNC: the profile checks, the INI it
writes, how the cycle window is cut from samples, the limits check.
(ctest LinuxCNC.AnchorHarness; the runs themselves are LinuxCNC.CycleTimeAnchor.)"""
import json
import os
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import anchor  # noqa: E402
import lcnc_run  # noqa: E402

MOTION = {  # issue 12's linuxcnc motion object
    "max_velocity_mm_min": {"x": 10000, "y": 10000, "z": 5000},
    "max_acceleration_mm_s2": {"x": 1000, "y": 1000, "z": 500},
    "period_s": 0.001, "min_segment_periods": 1.02, "block_rate_hz": 1000,
    "lookahead_blocks": 50, "blend_tolerance_mm": 0.01,
    "tool_change_s": 0, "spindle_start_s": 0}


def profile_with(tmp, motion):
    path = os.path.join(tmp, "p.json")
    prof = {"name": "linuxcnc"}
    if motion is not None:
        prof["motion"] = motion
    with open(path, "w") as f:
        json.dump(prof, f)
    return path


class Profile(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def refused(self, motion, words):
        with self.assertRaises(lcnc_run.Refused) as cm:
            lcnc_run.motion_of(profile_with(self.tmp.name, motion))
        self.assertIn(words, str(cm.exception))

    def test_the_issue_motion_is_accepted(self):
        self.assertEqual(lcnc_run.motion_of(profile_with(self.tmp.name, MOTION)), MOTION)

    def test_no_motion_is_refused(self):
        self.refused(None, "has no 'motion' object")

    def test_what_linuxcnc_cannot_be_is_refused(self):
        self.refused(dict(MOTION, max_jerk_mm_s3={"x": 1, "y": 1, "z": 1}), "jerk")
        self.refused(dict(MOTION, min_segment_periods=2), "min_segment_periods")
        self.refused(dict(MOTION, block_rate_hz=300), "block_rate_hz")
        self.refused(dict(MOTION, tool_change_s=4), "tool_change_s")
        self.refused(dict(MOTION, max_velocity_mm_min={"x": 1, "y": 1}), "x, y, z")

    def test_main_refuses_a_profile_without_motion(self):
        if not lcnc_run.installed():
            self.skipTest("LinuxCNC not installed: anchor.py skips before reading the profile")
        self.assertEqual(anchor.main(["--profile", profile_with(self.tmp.name, None),
                                      "--lcnc-only"]), 2)


class Ini(unittest.TestCase):
    def test_limits_come_from_the_profile(self):
        ini = lcnc_run.ini_text(MOTION, "/d.py", "/h.hal")
        for line in ("SERVO_PERIOD = 1000000", "ARC_BLEND_OPTIMIZATION_DEPTH = 50",
                     "MAX_LINEAR_VELOCITY = 166.666667", "MAX_LINEAR_ACCELERATION = 1000.000000",
                     "DISPLAY = /d.py", "HALFILE = /h.hal"):
            self.assertIn(line + "\n", ini)
        z = ini[ini.index("[AXIS_Z]"):ini.index("[JOINT_2]")]
        self.assertIn("MAX_VELOCITY = 83.333333\n", z)
        self.assertIn("MAX_ACCELERATION = 500.000000\n", z)
        j0 = ini[ini.index("[JOINT_0]"):ini.index("[AXIS_Y]")]
        self.assertIn("MAX_VELOCITY = 166.666667\n", j0)


def rows_from(xs, types=None, start=100):
    """Sample rows (n, x, y, z, v, line, type) from x positions."""
    out = []
    for i, x in enumerate(xs):
        v = 0.0 if i == 0 else abs(x - xs[i - 1]) / 0.001
        out.append((start + i, x, 0.0, 0.0, v, 3, (types or [1] * len(xs))[i]))
    return out


class Window(unittest.TestCase):
    def test_from_the_last_rest_to_the_end_of_motion(self):
        xs = [0, 0, 0, 0.001, 0.003, 0.006, 0.008, 0.009, 0.009, 0.009]
        res = lcnc_run.analyse(rows_from(xs), 0.001)
        self.assertEqual(res["window"], (2, 7))
        self.assertEqual(res["periods"], 5)
        self.assertAlmostEqual(res["cycle_time_s"], 0.005)
        self.assertAlmostEqual(res["rapid_time_s"], 0.005)
        self.assertAlmostEqual(res["axis_peak_velocity_mm_s"]["x"], 3.0)

    def test_a_stop_inside_the_cycle_counts_and_is_not_feed(self):
        xs = [0, 0, 0.001, 0.002, 0.002, 0.002, 0.003, 0.004, 0.004]
        types = [0, 0, 2, 2, 2, 2, 2, 2, 2]
        res = lcnc_run.analyse(rows_from(xs, types), 0.001)
        self.assertEqual(res["periods"], 6)
        self.assertAlmostEqual(res["feed_time_s"], 0.004)
        self.assertAlmostEqual(res["other_time_s"], 0.002)

    def test_lost_samples_are_an_error(self):
        rows = rows_from([0, 0, 0.001, 0.002, 0.002])
        rows[3] = (rows[3][0] + 1,) + rows[3][1:]
        with self.assertRaisesRegex(RuntimeError, "lost samples"):
            lcnc_run.analyse(rows, 0.001)

    def test_samples_that_do_not_end_at_rest_are_an_error(self):
        with self.assertRaisesRegex(RuntimeError, "at rest"):
            lcnc_run.analyse(rows_from([0, 0, 0.001, 0.002]), 0.001)
        with self.assertRaisesRegex(RuntimeError, "did not move"):
            lcnc_run.analyse(rows_from([0, 0, 0]), 0.001)


class Limits(unittest.TestCase):
    def res(self, v, a):
        return {"axis_peak_velocity_mm_s": dict(zip("xyz", v)),
                "axis_peak_acceleration_mm_s2": dict(zip("xyz", a))}

    def test_linuxcnc_at_the_profile_limits_passes(self):
        anchor.check_limits(self.res((166.667, 166.667, 83.334), (950, 901, 451)), MOTION)

    def test_other_limits_fail(self):
        for v, a in (((166.667, 166.667, 166.667), (900, 900, 900)),   # z as fast as x
                     ((166.667, 166.667, 83.334), (1900, 1800, 900)),  # twice the acceleration
                     ((166.667, 166.667, 83.334), (900, 900, 225)),    # z at a quarter
                     ((100.0, 166.667, 83.334), (900, 900, 450))):
            with self.assertRaisesRegex(RuntimeError, "did not configure"):
                anchor.check_limits(self.res(v, a), MOTION)


if __name__ == "__main__":
    unittest.main()
