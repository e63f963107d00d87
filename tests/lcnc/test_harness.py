#!/usr/bin/python3
"""The anchor's own logic, without LinuxCNC: the profile checks, the INI it
writes, how the cycle window is cut from samples, the limits check.
(ctest LinuxCNC.AnchorHarness; the runs themselves are LinuxCNC.CycleTimeAnchor.)"""
import contextlib
import io
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


class LateServo(unittest.TestCase):
    def test_late_invocations_and_the_periods_they_missed(self):
        rows = [r + (1000,) for r in rows_from([0, 0, 0.001, 0.002, 0.003, 0.004, 0.004])]
        rows[3] = rows[3][:7] + (3000,)  # two periods missed before sample 3
        rows[4] = rows[4][:7] + (1400,)  # late, but less than 1.5 periods: on time
        res = lcnc_run.analyse(rows, 0.001)
        self.assertEqual(res["late_servo_invocations"], 1)
        self.assertEqual(res["missed_servo_periods"], 2)

    def test_samples_without_the_servo_period_count_none(self):
        res = lcnc_run.analyse(rows_from([0, 0, 0.001, 0.002, 0.002]), 0.001)
        self.assertEqual(res["missed_servo_periods"], 0)


class Repeat(unittest.TestCase):
    """anchor.measure(): a program runs until two runs agree."""

    def runs(self, periods):
        it = iter(periods)
        self.count = 0

        def run_once():
            self.count += 1
            p = next(it)
            return {"periods": p, "cycle_time_s": p / 1000.0}
        return run_once

    def test_two_runs_that_agree_are_enough(self):
        kept, runs = anchor.measure(self.runs([1233, 1231]))
        self.assertEqual((kept["periods"], len(runs)), (1231, 2))

    def test_a_disturbed_run_is_repeated_and_left_out(self):
        # the busy machine of the issue: a run 10 % slow
        kept, runs = anchor.measure(self.runs([1354, 1231, 1232, 1500]))
        self.assertEqual((kept["periods"], len(runs)), (1231, 3))

    def test_runs_that_never_agree_give_no_time(self):
        kept, runs = anchor.measure(self.runs([1231, 1300, 1400, 1500, 1231]))
        self.assertIsNone(kept)
        self.assertEqual(len(runs), anchor.MAX_RUNS)


FAKE_BEZCAM = """#!/usr/bin/python3
import json, sys
a = sys.argv
with open(a[a.index("--report") + 1], "w") as f:
    json.dump({"cycle_time_s": %r}, f)
"""


class Check(unittest.TestCase):
    """anchor.py --check: bezcam against the reference, no LinuxCNC."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.profile = profile_with(self.tmp.name, MOTION)
        self.program = os.path.join(self.tmp.name, "square-F3000.ngc")
        with open(self.program, "w") as f:
            f.write("G0 X0 Y0 Z0\nG1 X10 F3000\nM2\n")

    def tearDown(self):
        self.tmp.cleanup()

    def bezcam(self, cycle):
        path = os.path.join(self.tmp.name, "bezcam")
        with open(path, "w") as f:
            f.write(FAKE_BEZCAM % cycle)
        os.chmod(path, 0o755)
        return path

    def reference(self, cycle, sha=None, motion=MOTION):
        path = os.path.join(self.tmp.name, "reference.tsv")
        anchor.write_reference(path, "2.9-test", anchor.fingerprint(motion), {
            "square-F3000": {"program_sha256": sha or anchor.program_fingerprint(self.program),
                             "cycle_time_s": cycle, "feed_time_s": cycle, "rapid_time_s": 0,
                             "other_time_s": 0}})
        return path

    def check(self, bezcam_s, reference):
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            rc = anchor.main(["--check", "--bezcam", self.bezcam(bezcam_s), "--profile",
                              self.profile, "--reference", reference, "--programs", self.tmp.name])
        return rc, out.getvalue()

    def test_the_reference_reads_back(self):
        version, motion_fp, rows = anchor.read_reference(self.reference(3.442))
        self.assertEqual(version, "2.9-test")
        self.assertEqual(motion_fp, anchor.fingerprint(MOTION))
        self.assertEqual(rows["square-F3000"]["cycle_time_s"], 3.442)

    def test_within_three_per_cent_passes(self):
        rc, out = self.check(3.40, self.reference(3.442))
        self.assertEqual(rc, 0, out)
        self.assertIn("1 of 1 within 2 %", out)

    def test_off_by_more_fails(self):
        rc, out = self.check(3.33, self.reference(3.442))  # 3.3 % short
        self.assertEqual(rc, 1, out)
        self.assertIn("OFF BY MORE THAN 3 %", out)

    def test_a_program_not_the_one_linuxcnc_timed_fails(self):
        rc, out = self.check(3.442, self.reference(3.442, sha="0123456789abcdef"))
        self.assertEqual(rc, 1, out)
        self.assertIn("not the one LinuxCNC timed", out)

    def test_another_motion_object_fails(self):
        rc, out = self.check(3.442, self.reference(3.442, motion=dict(MOTION, lookahead_blocks=40)))
        self.assertEqual(rc, 1, out)
        self.assertIn("another motion object", out)


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
