#!/usr/bin/python3
"""A waviness study from Python: the 6308 of seed 003 (§4.3, examples/seed003_amplitude.toml) with
7th-order inner-race waviness of growing amplitude. Runs from the repository's root after the build:

    PYTHONPATH=build/python /usr/bin/python3 examples/notebook.py
"""
import pathlib

import bearing

case = bearing.Case.from_file(str(pathlib.Path(__file__).with_name("seed003_amplitude.toml")))
print("BPFI = %.1f Hz" % bearing.info(case)["kinematics"]["bpfi"])

# One run: NumPy views of the response, summary.json as a dict.
r = bearing.run(case)
print("one run: %d samples of %s; ay RMS %.4g %s" % (r.t.size, ", ".join(r.channels), r.summary[
    "channels"]["ay"]["rms"], r.channels["ay"]))

# The sweep: five amplitudes on the C++ sweep's threads, one row each.
rows = bearing.sweep(case, vary={"waviness.inner.0.amplitude": "0um:1um:5"}, jobs=2,
                     as_dataframe=False)
print("amplitude [um]  ay RMS [m/s^2]  largest peak")
for row in rows:
    print("%14.2f  %14.4g  %s at %.1f Hz" % (row["waviness.inner.0.amplitude"] * 1e6, row["ay.rms"],
                                          row["ay.peak_label"], row["ay.peak_frequency"]))
