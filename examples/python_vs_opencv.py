"""OpenCV's StereoSGBM next to fpstereo's pipeline (the FPGA's exact output) on a dataset pair.

    PYTHONPATH=build/python /usr/bin/python3 examples/python_vs_opencv.py examples/cones [PRESET]

Reads the first pair of DATASET_DIR/pairs.csv, runs both, and prints each one's density and
KITTI D1 (|error| > 3 px and > 5 %) on its valid pixels against the ground truth. docs/python.md.
"""
import csv
import os
import sys
import time

import cv2
import numpy as np

import fpstereo


def d1_and_density(disparity, gt):
    """D1 over pixels with ground truth and a valid estimate, and that estimate's density, in %."""
    known = np.isfinite(gt)
    valid = known & np.isfinite(disparity)
    err = np.abs(disparity[valid] - gt[valid])
    d1 = np.mean((err > 3) & (err > 0.05 * gt[valid])) * 100
    return d1, valid.sum() / known.sum() * 100


def main(dataset, preset="C2"):
    with open(os.path.join(dataset, "pairs.csv")) as f:
        pair = next(csv.DictReader(f))
    left = cv2.imread(os.path.join(dataset, pair["left"]))  # BGR; both convert it to gray the same way
    right = cv2.imread(os.path.join(dataset, pair["right"]))
    stored = cv2.imread(os.path.join(dataset, pair["gt_occ"]), cv2.IMREAD_UNCHANGED).astype(np.float32)
    gt = stored / float(pair["gt_scale"])
    if pair["gt_invalid"] == "0":
        gt[stored == 0] = np.nan

    sgm = fpstereo.StereoSGM(preset=preset)
    dmax = int(sgm.config()["dmax"])
    block = 5
    sgbm = cv2.StereoSGBM_create(minDisparity=0, numDisparities=(dmax + 15) // 16 * 16, blockSize=block,
                                 P1=8 * block * block, P2=32 * block * block, uniquenessRatio=10,
                                 mode=cv2.STEREO_SGBM_MODE_HH4)

    gray_left, gray_right = cv2.cvtColor(left, cv2.COLOR_BGR2GRAY), cv2.cvtColor(right, cv2.COLOR_BGR2GRAY)
    start = time.perf_counter()
    fixed = sgbm.compute(gray_left, gray_right)  # disparity x 16, negative where invalid
    opencv_seconds = time.perf_counter() - start
    opencv = np.where(fixed < 0, np.nan, fixed / 16.0).astype(np.float32)

    start = time.perf_counter()
    ours = sgm.compute(left, right)  # float32, NaN where invalid: fpstereo run --pfm's values
    ours_seconds = time.perf_counter() - start

    print(f"{pair['pair']}: {left.shape[1]}x{left.shape[0]}, dmax {dmax}")
    for name, disparity, seconds in [("OpenCV StereoSGBM (HH4, 5x5)", opencv, opencv_seconds),
                                     (f"fpstereo {preset} (the FPGA's output)", ours, ours_seconds)]:
        d1, density = d1_and_density(disparity, gt)
        print(f"  {name:<34} D1 {d1:5.2f} % on {density:5.1f} % of the pixels ({seconds * 1e3:.0f} ms)")


if __name__ == "__main__":
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    main(*sys.argv[1:])
