"""The Python module against the command-line tool, bit for bit (docs/python.md).

Run by ctest (python_module) with PYTHONPATH holding the module, FPSTEREO the fpstereo binary,
FPSTEREO_RTL the fpstereo-rtl binary and FPSTEREO_EXAMPLES the examples folder.
"""
import csv
import os
import subprocess
import tempfile
import unittest

import numpy as np

import fpstereo

FPSTEREO = os.environ["FPSTEREO"]
FPSTEREO_RTL = os.environ["FPSTEREO_RTL"]
CONES = os.path.join(os.environ["FPSTEREO_EXAMPLES"], "cones")
LEFT, RIGHT = os.path.join(CONES, "left.png"), os.path.join(CONES, "right.png")


def read_pfm(path):
    """A single-channel little-endian PFM (what fpstereo run --pfm writes), rows top to bottom."""
    with open(path, "rb") as f:
        assert f.readline() == b"Pf\n"
        width, height = map(int, f.readline().split())
        assert float(f.readline()) < 0  # little-endian
        data = np.frombuffer(f.read(), dtype="<f4")
    assert data.size == width * height
    return data.reshape(height, width)[::-1]


def run_cli(*flags):
    """fpstereo run's PFM for the Cones pair, read back."""
    with tempfile.TemporaryDirectory() as tmp:
        pfm = os.path.join(tmp, "d.pfm")
        subprocess.run([FPSTEREO, "run", LEFT, RIGHT, "--pfm", pfm, *flags], check=True, capture_output=True)
        return read_pfm(pfm)


def first_differences(expected, got, count=5):
    where = np.argwhere(expected.view(np.uint32) != got.view(np.uint32))
    return [(int(x), int(y), float(expected[y, x]), float(got[y, x])) for y, x in where[:count]]


class ComputeEqualsRun(unittest.TestCase):
    def check(self, preset, flags, **params):
        expected = run_cli("--preset", preset, *flags)
        left = fpstereo.load_gray(LEFT)
        right = fpstereo.load_gray(RIGHT)
        got = fpstereo.StereoSGM(preset=preset, **params).compute(left, right)
        self.assertEqual(got.dtype, np.float32)
        self.assertEqual(got.shape, expected.shape)
        # The PFM marks invalid pixels +inf, the module NaN; every other value bit for bit.
        self.assertTrue(np.all(np.isposinf(expected) == np.isnan(got)), "invalid pixels differ")
        self.assertFalse(np.isinf(got).any())
        expected = np.where(np.isinf(expected), np.float32(np.nan), expected).astype(np.float32)
        same = np.isnan(got) | (expected.view(np.uint32) == got.view(np.uint32))
        same &= np.isnan(got) == np.isnan(expected)
        self.assertTrue(same.all(), f"{(~same).sum()} pixels differ, first (x, y, run, module): "
                                    f"{first_differences(expected, got)}")
        return got

    def test_c2(self):
        got = self.check("C2", [])
        self.assertGreater(np.isfinite(got).mean(), 0.5)  # a real disparity map, not all invalid

    def test_a3_with_parameters(self):
        # Sub-pixel, left-right check, adaptive P2, and parameters given as keywords.
        self.check("A3", ["--uniqueness", "10", "--gap-interp", "on", "--paths", "0,45,90"],
                   uniqueness=10, gap_interp=True, paths=[0, 45, 90])

    def test_linear_gap_fill(self):
        # The linear gap fill as a keyword's text value, on the left-right check's invalid runs.
        self.check("C3", ["--gap-interp", "linear", "--subpixel-bits", "4"], gap_interp="linear", subpixel_bits=4)

    def test_colour_arrays_convert_as_files_do(self):
        # A BGR array (cv2.imread's layout) gives the gray image the file gives.
        gray = fpstereo.load_gray(LEFT)
        bgr = np.stack([gray, gray, gray], axis=2)
        sgm = fpstereo.StereoSGM(preset="C0")
        np.testing.assert_array_equal(sgm.compute_words(bgr, bgr)["disparity"],
                                      sgm.compute_words(gray, gray)["disparity"])


class Words(unittest.TestCase):
    def test_right_view_and_confidence(self):
        left, right = fpstereo.load_gray(LEFT), fpstereo.load_gray(RIGHT)
        sgm = fpstereo.StereoSGM(preset="C3", right_view=True, confidence=True)
        words = sgm.compute_words(left, right)
        self.assertEqual(sorted(words), ["confidence", "disparity", "right"])
        for a in words.values():
            self.assertEqual((a.dtype, a.shape), (np.uint16, left.shape))
        self.assertLessEqual(int(words["confidence"].max()), 255)
        with tempfile.TemporaryDirectory() as tmp:
            right_pfm = os.path.join(tmp, "r.pfm")
            subprocess.run([FPSTEREO, "run", LEFT, RIGHT, "--preset", "C3", "--right-output", right_pfm],
                           check=True, capture_output=True)
            expected = read_pfm(right_pfm)
        invalid = np.isinf(expected)
        self.assertFalse(invalid.all())
        # Whole disparities: the word is the disparity where valid, and above every one where not.
        np.testing.assert_array_equal(words["right"][~invalid].astype(np.float32), expected[~invalid])
        self.assertTrue(np.all(words["right"][invalid] > int(sgm.config()["dmax"]) - 1))

    def test_plain_configuration_has_disparity_only(self):
        gray = fpstereo.load_gray(LEFT)
        self.assertEqual(list(fpstereo.StereoSGM(preset="C0").compute_words(gray, gray)), ["disparity"])


class Configuration(unittest.TestCase):
    def test_config_round_trips_and_matches_the_cli(self):
        sgm = fpstereo.StereoSGM(preset="A3", uniqueness=10)
        cfg = sgm.config()
        shown = subprocess.run([FPSTEREO, "config", "--preset", "A3", "--uniqueness", "10"], check=True,
                               capture_output=True, text=True).stdout
        for name, value in cfg.items():
            self.assertIn(f"{name} = {value}\n", shown)
        self.assertEqual(fpstereo.StereoSGM(**cfg).config(), cfg)

    def test_verilog_equals_fpstereo_rtl(self):
        expected = subprocess.run([FPSTEREO_RTL, "--preset", "C0", "--width", "64", "--height", "16"], check=True,
                                  capture_output=True, text=True).stdout
        self.assertEqual(fpstereo.StereoSGM(preset="C0", width=64, height=16).verilog(), expected)

    def test_bad_parameters_raise_the_cli_message(self):
        for params, flags in [({"window": 4}, ["--window", "4"]),
                              ({"preset": "C9"}, ["--preset", "C9"]),
                              ({"lr": "lr3"}, ["--lr", "lr3"]),
                              ({"right_view": True}, ["--right-view", "on"])]:
            cli = subprocess.run([FPSTEREO, "config", *flags], capture_output=True, text=True)
            self.assertEqual(cli.returncode, 2)
            message = cli.stderr.strip().removeprefix("fpstereo: ")
            with self.assertRaises(ValueError) as raised:
                fpstereo.StereoSGM(**params)
            self.assertEqual(str(raised.exception), message)

    def test_unknown_parameter(self):
        with self.assertRaisesRegex(ValueError, "windw"):
            fpstereo.StereoSGM(windw=5)


class RefusedImages(unittest.TestCase):
    sgm = fpstereo.StereoSGM(preset="C0", width=64, height=32)
    good = np.zeros((16, 32), np.uint8)

    def refused(self, left, right, message):
        with self.assertRaisesRegex(ValueError, message):
            self.sgm.compute(left, right)
        with self.assertRaisesRegex(ValueError, message):
            self.sgm.compute_words(left, right)

    def test_dtype(self):
        self.refused(self.good.astype(np.float32), self.good, r"left image: dtype float32, expected uint8")
        self.refused(self.good, self.good.astype(np.uint16), r"right image: dtype uint16, expected uint8")
        self.refused(self.good.astype(bool), self.good, "dtype bool")

    def test_shape(self):
        self.refused(np.zeros(32, np.uint8), self.good, r"left image: shape \(32,\)")
        self.refused(self.good, np.zeros((16, 32, 2), np.uint8), r"right image: shape \(16, 32, 2\)")
        self.refused(np.zeros((0, 32), np.uint8), self.good, "left image: the image is empty")

    def test_not_an_array(self):
        self.refused([[0] * 32] * 16, self.good, "left image: expected a numpy array")

    def test_sizes(self):
        self.refused(self.good, np.zeros((16, 31), np.uint8), "the two must be the same size")
        self.refused(np.zeros((16, 65), np.uint8), np.zeros((16, 65), np.uint8), "at most 64x32")

    def test_views_are_read_as_numpy_shows_them(self):
        # A strided view (every other column) is its own image, not the buffer underneath.
        wide = np.random.default_rng(1).integers(0, 256, (16, 64), dtype=np.uint8)
        view, copy = wide[:, ::2], np.ascontiguousarray(wide[:, ::2])
        np.testing.assert_array_equal(self.sgm.compute_words(view, view)["disparity"],
                                      self.sgm.compute_words(copy, copy)["disparity"])


class Evaluate(unittest.TestCase):
    def test_cones_scores_as_fpstereo_eval(self):
        result = fpstereo.StereoSGM(preset="C2").evaluate(CONES)
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "e.csv")
            subprocess.run([FPSTEREO, "eval", CONES, "--preset", "C2", "--csv", path], check=True,
                           capture_output=True)
            with open(path) as f:
                rows = list(csv.DictReader(f))
        self.assertEqual(list(result["pairs"]), ["cones"])
        metrics = ["d1_percent", "bad1_percent", "bad2_percent", "bad4_percent", "mae_px", "density_percent"]
        compared = 0
        for row in rows:
            scores = (result["all"] if row["pair"] == "overall" else result["pairs"][row["pair"]])
            region = scores[row["region"] + ("_filled" if row["fill"] == "filled" else "")]
            self.assertEqual(region["gt_pixels"], int(row["gt_pixels"]))
            for metric in metrics:
                self.assertEqual(f"{region[metric]:.6g}", row[metric], f"{row['pair']} {row['fill']} {metric}")
                compared += 1
        self.assertGreaterEqual(compared, 4 * len(metrics))  # cones and overall, valid only and filled

    def test_bad_dataset_is_a_value_error(self):
        with self.assertRaisesRegex(ValueError, "no such directory"):
            fpstereo.StereoSGM().evaluate(os.path.join(CONES, "missing"))
        with self.assertRaisesRegex(ValueError, "no pairs.csv"):
            fpstereo.StereoSGM().evaluate(os.path.dirname(CONES))


if __name__ == "__main__":
    unittest.main()
