#!/usr/bin/python3
"""The drive-end channel of each CWRU record as float32 .npy, for tests that need the measured
signals without the original files (README.md in this folder).

    /usr/bin/python3 tests/data/cwru/make_npy.py MAT_FOLDER tests/data/cwru

For each NNN_*.mat in SOURCE: the variable XNNN_DE_time (drive-end accelerometer, g; a column
vector of float64 in the file) flattened to 1-D and rounded to float32 by numpy's astype (IEEE
754 round to nearest, ties to even), saved with numpy.save as SOURCE's file name with _DE.npy for
.mat. Prints each file's name, length and the largest rounding error relative to the sample.
"""
import pathlib
import sys

import numpy as np
import scipy.io

source, target = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
for mat in sorted(source.glob("*.mat")):
    number = int(mat.name.split("_")[0])
    variables = scipy.io.loadmat(mat)
    de = variables[f"X{number:03d}_DE_time"].ravel()  # float64, as stored
    de32 = de.astype(np.float32)
    out = target / (mat.stem + "_DE.npy")
    np.save(out, de32)
    nonzero = de != 0
    rel = np.max(np.abs(de32[nonzero].astype(np.float64) - de[nonzero]) / np.abs(de[nonzero]))
    print(f"{out.name}: {de.size} samples, float32 rounding at most {rel:.2e} of a sample")
