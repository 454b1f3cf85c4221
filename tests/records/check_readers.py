#!/usr/bin/python3
"""The measured-record readers (lumped/include/records/) against files other tools write here:
scipy.io.savemat (MATLAB 5, plain and compressed), h5py (a MATLAB 7.3 file: HDF5 behind a
512-byte userblock with MATLAB's header; and plain .h5), Python's wave (16- and 8-bit PCM),
scipy.io.wavfile (float WAV), numpy.save (.npy), csv (.csv). The samples read must equal what
Python wrote, to the last bit (floats), or exactly the documented scaling (PCM: code / 2^(bits-1);
then × --scale × the unit's factor, 9.80665 for g). Then the CWRU record in tests/data/cwru/
against its committed .npy, and every input error: exit 2, one line naming the file, the channel
and the problem. Skipped (exit 77) without numpy, scipy or h5py.

    check_readers.py RECORD_DUMP WORK_DIR SOURCE_DIR
"""
import csv
import json
import math
import pathlib
import shutil
import struct
import subprocess
import sys
import wave

try:
    import h5py
    import numpy as np
    import scipy.io
    import scipy.io.wavfile
except ImportError as e:
    print(f"SKIP: {e} (Debian: python3-numpy python3-scipy python3-h5py for {sys.executable})")
    sys.exit(77)

dump, work, source = sys.argv[1], pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
shutil.rmtree(work, ignore_errors=True)
work.mkdir(parents=True)
G = 9.80665
RPM = 2 * math.pi / 60  # rad/s per rpm
failures = []


def check(what, ok, detail=""):
    print(f"{what}: {'ok' if ok else 'FAILED'}{'' if ok else ' ' + detail}")
    if not ok:
        failures.append(what)


def read(path, *options):
    """(exit code, metadata dict or None, samples [SI] or None, stderr) of record_dump."""
    out = work / "samples.f64"
    out.unlink(missing_ok=True)
    p = subprocess.run([dump, str(path), *options, "--samples", str(out)],
                       capture_output=True, text=True)
    if p.returncode != 0:
        return p.returncode, None, None, p.stderr.strip()
    return 0, json.loads(p.stdout), np.fromfile(out, dtype="<f8"), p.stderr.strip()


def same_bits(a, b):
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))


def expect_samples(what, path, expected, *options, **meta):
    rc, m, s, err = read(path, *options)
    if rc != 0:
        check(what, False, f"exit {rc}: {err}")
        return None
    check(f"{what}: samples equal to the last bit", same_bits(s, expected),
          f"{len(s)} read, {len(expected)} written; first differences at "
          f"{np.flatnonzero(s != expected)[:5] if len(s) == len(expected) else '-'}")
    for key, value in meta.items():
        got = m[key]
        ok = math.isclose(got, value, rel_tol=1e-12) if isinstance(value, float) else got == value
        check(f"{what}: {key} = {value!r}", ok, f"got {got!r}")
    return m


def expect_error(what, path, phrases, *options):
    """Exit 2 and one line on stderr starting with the file's name and holding every phrase."""
    rc, _, _, err = read(path, *options)
    ok = rc == 2 and "\n" not in err and err.startswith(str(path) + ": ")
    ok = ok and all(p in err for p in phrases)
    check(f"error, {what}", ok, f"exit {rc}, message: {err!r}; expected {phrases}")


def available(extension):
    """Whether this build reads `extension`; if not, its refusal is the documented one."""
    probe = work / f"probe{extension}"
    rc, _, _, err = read(probe)
    if "this build cannot read" in err:
        check(f"{extension} unavailable: says which package was missing",
              "was not found at build time" in err, err)
        return False
    return True


rng = np.random.default_rng(29)


def signal(n):
    """Full-mantissa values over six decades, both signs, a zero and a negative zero."""
    v = rng.standard_normal(n) * 10.0 ** rng.uniform(-3, 3, n)
    v[3], v[4] = 0.0, -0.0
    return v


# --- MATLAB 5 (scipy.io.savemat), plain and compressed --------------------------------------------
if available(".mat"):
    acc = signal(1000)
    mat5 = {"acc": acc.reshape(-1, 1), "single": signal(50).astype(np.float32).reshape(1, -1),
            "i16": np.array([[-32768, -1, 0, 1, 32767]], dtype=np.int16),
            "X042RPM": np.array([[1500]], dtype=np.uint16), "other": np.ones((3, 4)),
            "txt": "hello"}
    for compressed in (False, True):
        f = work / f"v5{'_z' if compressed else ''}.mat"
        scipy.io.savemat(f, mat5, do_compression=compressed)
        tag = f"MATLAB 5{' compressed' if compressed else ''}"
        expect_samples(f"{tag} double", f, acc, "--channel", "acc", "--rate", "1000", "--unit",
                       "m/s^2", channel="acc", rate=1000.0, rate_source="option",
                       shaft_speed=1500 * RPM, shaft_speed_origin="variable X042RPM (1500 rpm)")
        expect_samples(f"{tag} single", f, mat5["single"].ravel().astype(np.float64),
                       "--channel", "single", "--rate", "1000", "--unit", "m")
        expect_samples(f"{tag} int16 in g", f, mat5["i16"].ravel() * G, "--channel", "i16",
                       "--rate", "1000", "--unit", "g", quantity="acceleration")
    f = work / "v5.mat"
    expect_error(".mat, several channels and no --channel", f,
                 ["3 variables (", "acc", "single", "i16", "choose one with --channel"],
                 "--rate", "1000", "--unit", "g")
    expect_error(".mat, unknown variable (listing the ones there)", f,
                 ["channel nosuch: no such variable; the file has ", "acc", "i16", "single",
                  "not channels: ", "X042RPM (a 1×1 scalar)", "other (a 3×4 matrix"],
                 "--channel", "nosuch")
    expect_error(".mat, a scalar is not a channel", f,
                 ["channel X042RPM: the variable is a 1×1 scalar, not a channel"],
                 "--channel", "X042RPM")
    expect_error(".mat, a matrix is not a channel", f, ["channel other: the variable is a 3×4"],
                 "--channel", "other")
    expect_error(".mat, no rate", f, ["channel acc: no sampling rate", "give --rate"],
                 "--channel", "acc", "--unit", "g")
    expect_error(".mat, no unit", f, ["channel acc: no unit", "give --unit"],
                 "--channel", "acc", "--rate", "1000")
    expect_error(".mat, unknown unit", f, ["channel acc: --unit: unknown unit \"furlong\"",
                                           "allowed g, m/s^2, m/s, m"],
                 "--channel", "acc", "--rate", "1000", "--unit", "furlong")
    with_nan = acc.copy()
    with_nan[17] = np.nan
    scipy.io.savemat(work / "nan.mat", {"acc": with_nan})
    expect_error(".mat, NaN", work / "nan.mat", ["channel acc: sample 17 (from 0) is NaN"],
                 "--rate", "1000", "--unit", "g")
    # matio inflates a corrupt zlib stream without a word: the reader checks the checksum.
    z = bytearray((work / "v5_z.mat").read_bytes())
    z[len(z) // 2] ^= 0xFF
    (work / "corrupt_z.mat").write_bytes(bytes(z))
    expect_error(".mat, a corrupt compressed variable", work / "corrupt_z.mat",
                 ["corrupt: the variable at byte ", "it does not inflate (zlib: "],
                 "--channel", "acc", "--rate", "1000", "--unit", "g")
    (work / "garbage.mat").write_bytes(bytes(range(256)) * 4)
    expect_error(".mat, corrupt file", work / "garbage.mat", ["matio cannot open it"])
    expect_error(".mat, missing file", work / "missing.mat", ["matio cannot open it"])

    # --- MATLAB 7.3: HDF5 with MATLAB's 128-byte header in a 512-byte userblock (h5py) ----------
    def matlab_class(ds, name):
        # MATLAB writes MATLAB_class as a null-terminated fixed string; matio reads only that.
        t = h5py.h5t.C_S1.copy()
        t.set_size(len(name))
        t.set_strpad(h5py.h5t.STR_NULLTERM)
        a = h5py.h5a.create(ds.id, b"MATLAB_class", t, h5py.h5s.create(h5py.h5s.SCALAR))
        a.write(np.array(name.encode(), dtype=f"S{len(name)}"), mtype=t)

    f = work / "v73.mat"
    acc73 = signal(2000)
    with h5py.File(f, "w", userblock_size=512) as h:
        matlab_class(h.create_dataset("acc", data=acc73.reshape(1, -1)), "double")  # MATLAB's
        matlab_class(h.create_dataset("X7RPM", data=np.array([[1797.0]])), "double")  # n×1
    text = (b"MATLAB 7.3 MAT-file, Platform: GLNXA64, Created on: Thu Nov 26 12:00:00 2026 "
            b"HDF5 schema 1.00 .")
    with open(f, "r+b") as out:
        out.write(text.ljust(116, b" ") + b"\0" * 8 + struct.pack("<H", 0x0200) + b"IM")
    expect_samples("MATLAB 7.3 (h5py) double", f, acc73, "--rate", "2000", "--unit", "m/s",
                   channel="acc", quantity="velocity", shaft_speed=1797 * RPM)
    (work / "cut73.mat").write_bytes(f.read_bytes()[:9000])
    expect_error("a truncated MATLAB 7.3 file", work / "cut73.mat",
                 ["matio finds no variable in it (empty, truncated or corrupt)"])

# --- WAV: 16-bit and 8-bit PCM (wave), float (scipy.io.wavfile) -----------------------------------
if available(".wav"):
    codes = rng.integers(-32768, 32768, size=(3000, 2), dtype=np.int16)
    codes[0] = (-32768, 32767)
    f = work / "pcm16.wav"
    with wave.open(str(f), "wb") as w:
        w.setnchannels(2)
        w.setsampwidth(2)
        w.setframerate(8000)
        w.writeframes(codes.astype("<i2").tobytes())
    # Full scale ±50 g: code / 32768 × 50 × 9.80665.
    expect_samples("WAV 16-bit PCM, channel 1", f, codes[:, 1] / 32768.0 * 50.0 * G,
                   "--channel", "1", "--unit", "g", "--scale", "50", channel="1", rate=8000.0,
                   rate_source="file", rate_origin="the WAV header", scale=50.0)
    expect_error("WAV rate contradicted by --rate", f,
                 ["channel 0: --rate 8001 Hz contradicts the rate 8000 Hz of the WAV header"],
                 "--channel", "0", "--unit", "g", "--rate", "8001")
    expect_error("WAV, two channels and no --channel", f,
                 ["2 channels (0, 1): choose one with --channel"], "--unit", "g")
    u8 = rng.integers(0, 256, size=500, dtype=np.uint8)
    f = work / "pcm8.wav"
    with wave.open(str(f), "wb") as w:
        w.setnchannels(1)
        w.setsampwidth(1)
        w.setframerate(11025)
        w.writeframes(u8.tobytes())
    expect_samples("WAV 8-bit PCM", f, (u8.astype(np.float64) - 128) / 128.0, "--unit", "m/s^2",
                   rate=11025.0)
    fl = signal(4000).astype(np.float32)
    fl[10] = 3.5  # beyond ±1: float data is read as stored
    f = work / "float.wav"
    scipy.io.wavfile.write(f, 44100, fl)
    expect_samples("WAV float32 (scipy)", f, fl.astype(np.float64), "--unit", "m/s^2",
                   channel="0", rate=44100.0)
    fl[3] = np.inf
    scipy.io.wavfile.write(work / "inf.wav", 44100, fl)
    expect_error("WAV with +Inf", work / "inf.wav", ["channel 0: sample 3 (from 0) is +Inf"],
                 "--unit", "g")
    (work / "garbage.wav").write_bytes(b"RIFF\x10\x00\x00\x00WAVEjunk" + bytes(100))
    expect_error("WAV, corrupt file", work / "garbage.wav", ["libsndfile cannot read it"])

# --- NPY (numpy.save) -----------------------------------------------------------------------------
v = signal(777)
for name, array, options, expected in [
        ("1-D float64", v, [], v),
        ("1-D float32", v.astype(np.float32), [], v.astype(np.float32).astype(np.float64)),
        ("1-D big-endian float64", v.astype(">f8"), [], v),
        ("(n, 3) C order, column 2", v[:777 // 3 * 3].reshape(-1, 3), ["--channel", "2"],
         v[:777 // 3 * 3].reshape(-1, 3)[:, 2]),
        ("(n, 3) Fortran order, column 1", np.asfortranarray(v[:777 // 3 * 3].reshape(-1, 3)),
         ["--channel", "1"], v[:777 // 3 * 3].reshape(-1, 3)[:, 1]),
        ("(1, n)", v.reshape(1, -1), [], v)]:
    f = work / f"{name.split(',')[0].replace(' ', '_').replace('(', '').replace(')', '')}.npy"
    np.save(f, array)
    expect_samples(f"NPY {name}", f, expected * G, *options, "--rate", "5000", "--unit", "g",
                   rate=5000.0, unit="g", unit_source="option")
f = work / "plain.npy"
np.save(f, v)
expect_error("NPY, no rate", f, ["channel 0: no sampling rate: the file does not state one"],
             "--unit", "g")
expect_error("NPY, a rate that is no rate", f, ["channel 0: --rate 0 Hz: must be a finite rate"],
             "--unit", "g", "--rate", "0")
np.save(work / "empty.npy", np.zeros(0))
expect_error("NPY, no samples", work / "empty.npy", ["channel 0: no samples"],
             "--unit", "g", "--rate", "1")
with_nan = v.copy()
with_nan[5] = np.nan
np.save(work / "nan.npy", with_nan)
expect_error("NPY, NaN", work / "nan.npy", ["channel 0: sample 5 (from 0) is NaN"],
             "--unit", "g", "--rate", "1")
np.save(work / "int.npy", np.arange(5, dtype=np.int16))
expect_error("NPY, integer dtype", work / "int.npy", ["dtype '<i2': allowed float32 or float64"])
(work / "cut.npy").write_bytes((work / "plain.npy").read_bytes()[:-3])
expect_error("NPY, truncated", work / "cut.npy", ["the data is cut short"])
expect_error("NPY, --dataset on a non-HDF5 file", f,
             ["--dataset /x applies to HDF5 files only, not .npy"], "--dataset", "/x")

# --- CSV (csv module; repr() writes each float so that it reads back exactly) ---------------------
de, fe = signal(600), signal(600)
rate = 5000
f = work / "rec.csv"
with open(f, "w", newline="") as out:
    w = csv.writer(out)
    w.writerow(["t", "DE [g]", "FE"])
    for i in range(600):
        w.writerow([repr(i / rate), repr(de[i]), repr(fe[i])])
m = expect_samples("CSV, column DE in g (the header's unit), time column", f, de * G,
                   "--channel", "DE", channel="DE", unit="g", unit_source="file",
                   unit_origin="the header of column DE", rate_source="file",
                   rate_origin="time column t")
if m:
    check("CSV: the time column's rate", abs(m["rate"] - rate) <= 1e-9 * rate, str(m["rate"]))
expect_samples("CSV, column FE, --rate agreeing with the time column", f, fe, "--channel", "FE",
               "--unit", "m/s^2", "--rate", "5000", rate=5000.0, rate_source="option")
expect_error("CSV, --rate contradicting the time column", f,
             ["channel FE: --rate 5100 Hz contradicts the rate 5000", "of time column t"],
             "--channel", "FE", "--unit", "g", "--rate", "5100")
expect_error("CSV, no unit", f, ["channel FE: no unit"], "--channel", "FE")
expect_error("CSV, --unit contradicting the header", f,
             ["channel DE: --unit m/s contradicts the file's unit g (the header of column DE)"],
             "--channel", "DE", "--unit", "m/s")
expect_error("CSV, two columns and no --channel", f,
             ["2 columns (DE, FE): choose one with --channel"])
expect_error("CSV, unknown column", f, ["channel AE: no such column; the file has DE, FE"],
             "--channel", "AE")
rows = [["time", "acc [V]"]] + [[repr(i / rate), "1.0"] for i in range(10)]
rows[5][0] = repr(4.3 / rate)  # "0.00086": 0.7 of a step early
with open(work / "jitter.csv", "w", newline="") as out:
    csv.writer(out).writerows(rows)
expect_error("CSV, time column not uniform", work / "jitter.csv",
             ["channel acc: time column time: not uniform at sample 4 (from 0)"], "--unit", "g")
rows[5][0] = repr(5 / rate)
with open(work / "volts.csv", "w", newline="") as out:
    csv.writer(out).writerows(rows)
expect_error("CSV, a unit in the header the reader cannot convert", work / "volts.csv",
             ["channel acc: the header of column acc: unknown unit \"V\""])
(work / "header_only.csv").write_text("DE\n")
expect_error("CSV, no samples", work / "header_only.csv", ["channel DE: no samples"],
             "--rate", "1", "--unit", "g")
(work / "nan.csv").write_text("DE\n1\n2\nnan\n")
expect_error("CSV, NaN", work / "nan.csv",
             ["channel DE: line 4, column DE: \"nan\" is not a finite number"],
             "--rate", "1", "--unit", "g")
np.savetxt(work / "savetxt.csv", de)
expect_samples("CSV without header (numpy.savetxt, %.18e)", work / "savetxt.csv", de,
               "--rate", "5000", "--unit", "m", channel="0", quantity="displacement")
expect_error("CSV, missing file", work / "missing.csv", ["cannot open: No such file"])

# --- HDF5 (h5py) ----------------------------------------------------------------------------------
if available(".h5"):
    f = work / "rec.h5"
    acc, table, counts = signal(900), np.column_stack([np.arange(400) / 2000.0, signal(400),
                                                        signal(400)]), np.arange(-5, 5, dtype="i2")
    with h5py.File(f, "w") as h:
        d = h.create_dataset("acc", data=acc)
        d.attrs["rate"] = 25600.0
        d.attrs["unit"] = "g"  # h5py: a variable-length UTF-8 string
        t = h.create_group("run").create_dataset("tbl", data=table)
        t.attrs["columns"] = ["t", "ax", "ay"]
        t.attrs["units"] = ["s", "m/s^2", "m/s^2"]
        c = h.create_dataset("counts", data=counts)
        c.attrs.create("unit", np.bytes_("m"))  # a fixed-length string
        c.attrs["fs"] = np.int32(100)
    expect_samples(".h5 1-D with rate and unit attributes", f, acc * G, "--dataset", "/acc",
                   channel="/acc", rate=25600.0, rate_source="file",
                   rate_origin="attribute rate of /acc", unit_source="file")
    m = expect_samples(".h5 table, column ay by the columns attribute", f, table[:, 2],
                       "--dataset", "run/tbl", "--channel", "ay", channel="ay",
                       rate_origin="time column t of /run/tbl", unit="m/s^2")
    if m:
        check(".h5: the time column's rate", abs(m["rate"] - 2000) <= 1e-9 * 2000, str(m["rate"]))
    expect_samples(".h5 int16 with a fixed-length unit string and fs", f,
                   counts.astype(np.float64), "--dataset", "/counts", rate=100.0, unit="m")
    expect_error(".h5, several datasets and no --dataset", f,
                 ["3 datasets (/acc, /counts, /run/tbl): choose one with --dataset"])
    expect_error(".h5, unknown dataset", f,
                 ["no numeric dataset /nope of rank 1 or 2; the file has /acc, /counts, /run/tbl"],
                 "--dataset", "/nope")
    expect_error(".h5, --rate contradicting the rate attribute", f,
                 ["channel /acc: --rate 1000 Hz contradicts the rate 25600 Hz of attribute rate "
                  "of /acc"], "--dataset", "/acc", "--rate", "1000")
    (work / "garbage.h5").write_bytes(bytes(range(256)) * 4)
    expect_error(".h5, not HDF5", work / "garbage.h5", ["not an HDF5 file"])
    (work / "cut.h5").write_bytes(f.read_bytes()[:3000])
    expect_error(".h5, truncated", work / "cut.h5", ["HDF5 cannot open it (corrupt file?)"])

# --- Unsupported extension ------------------------------------------------------------------------
(work / "rec.txt").write_text("1\n2\n")
expect_error("unsupported extension", work / "rec.txt",
             ["unsupported extension \".txt\"; supported: .csv, .npy, .wav, .mat, .h5, .hdf5"])

# --- The CWRU record in the repository: the .mat read equals the committed float32 .npy ----------
cwru = source / "tests" / "data" / "cwru"
lengths = {"97_normal_0hp": 243938, "105_IR007_0hp": 121265, "118_B007_0hp": 122571,
           "130_OR007at6_0hp": 121991}  # the data set's README
for stem, n in lengths.items():
    npy = np.load(cwru / f"{stem}_DE.npy")
    check(f"CWRU {stem}_DE.npy: 1-D float32 of {n} samples",
          npy.dtype == np.dtype("<f4") and npy.shape == (n,), f"{npy.dtype} {npy.shape}")
mat = cwru / "130_OR007at6_0hp.mat"
npy = np.load(cwru / "130_OR007at6_0hp_DE.npy")
stored = scipy.io.loadmat(mat)["X130_DE_time"].ravel()
check("CWRU 130: the committed .npy is the .mat's X130_DE_time rounded to float32",
      same_bits(stored.astype(np.float32).astype(np.float64), npy.astype(np.float64)))
if available(".mat"):
    m = expect_samples("CWRU 130 .mat, X130_DE_time", mat, stored * G, "--channel", "X130_DE_time",
                       "--rate", "12000", "--unit", "g", samples=121991,
                       shaft_speed=1796 * RPM, shaft_speed_origin="variable X130RPM (1796 rpm)")
    rc, _, s, _ = read(mat, "--channel", "X130_DE_time", "--rate", "12000", "--unit", "g")
    if rc == 0:
        check("CWRU 130 .mat: rounded to float32 in g, equal to the committed .npy",
              same_bits((s / G).astype(np.float32).astype(np.float64), npy.astype(np.float64)))
    expect_error("CWRU 130 .mat without --channel: the three channels, not X130RPM", mat,
                 ["3 variables (X130_DE_time, X130_FE_time, X130_BA_time): choose one"],
                 "--rate", "12000", "--unit", "g")
    (work / "cut.mat").write_bytes(mat.read_bytes()[:200000])
    expect_error("a truncated MATLAB 5 file", work / "cut.mat",
                 ["truncated: the variable at byte 128 claims 975992 bytes"],
                 "--channel", "X130_DE_time", "--rate", "12000", "--unit", "g")
expect_samples("CWRU 130 committed .npy", cwru / "130_OR007at6_0hp_DE.npy",
               npy.astype(np.float64) * G, "--rate", "12000", "--unit", "g", samples=121991)

print(f"{len(failures)} failed" + (": " + ", ".join(failures) if failures else ""))
sys.exit(1 if failures else 0)
