#!/usr/bin/python3
"""The seeds of the record readers' fuzz targets (corpus/record_<format>/), written by the tools
users' files come from (csv, numpy, wave, scipy, h5py), small (< 8 kB, the fuzzers' -max_len).

    /usr/bin/python3 tests/fuzz/make_record_seeds.py tests/fuzz/corpus
"""
import pathlib
import struct
import sys
import wave

import h5py
import numpy as np
import scipy.io
import scipy.io.wavfile

root = pathlib.Path(sys.argv[1])
rng = np.random.default_rng(31)
x = rng.standard_normal(64)


def folder(name):
    d = root / f"record_{name}"
    d.mkdir(parents=True, exist_ok=True)
    return d


d = folder("csv")
(d / "time_units.csv").write_text(
    "t,DE [g],FE (m/s^2)\n" + "".join(f"{i / 12000!r},{x[i]!r},{x[-i]!r}\n" for i in range(20)))
(d / "savetxt_header.csv").write_text(
    "# t DE\n" + "".join(f"{i / 1000:.18e} {x[i]:.18e}\n" for i in range(10)))
(d / "semicolon_quoted_bom_crlf.csv").write_bytes(
    b"\xef\xbb\xbf\"Accel, DE\";\"t\"\r\n" + b"".join(f"{x[i]!r};{i * 0.001:.6f}\r\n".encode()
                                                     for i in range(10)))
(d / "headerless.csv").write_text("".join(f"{x[i]:.6g}\n" for i in range(16)))
(d / "bad_rows.csv").write_text("time,DE\n0,1\n0.1,nan\n0.2\n0.3,1,2\n")

d = folder("npy")
np.save(d / "f8_1d.npy", x)
np.save(d / "f4_big_endian.npy", x[:32].astype(">f4"))
np.save(d / "f8_fortran_2d.npy", np.asfortranarray(x[:48].reshape(16, 3)))
with open(d / "f8_version2.npy", "wb") as f:
    np.lib.format.write_array(f, x[:8].reshape(4, 2), version=(2, 0))

d = folder("wav")
with wave.open(str(d / "pcm16_stereo.wav"), "wb") as w:
    w.setnchannels(2)
    w.setsampwidth(2)
    w.setframerate(8000)
    w.writeframes((x[:64] * 8000).astype("<i2").tobytes())
with wave.open(str(d / "pcm8_mono.wav"), "wb") as w:
    w.setnchannels(1)
    w.setsampwidth(1)
    w.setframerate(11025)
    w.writeframes((x * 40 + 128).astype(np.uint8).tobytes())
scipy.io.wavfile.write(d / "float32_mono.wav", 44100, x.astype(np.float32))

d = folder("mat")
variables = {"acc": x.reshape(-1, 1), "X042RPM": np.array([[1797]], dtype=np.uint16),
             "i16": np.arange(-4, 4, dtype=np.int16), "m": np.ones((2, 3)), "txt": "hi"}
scipy.io.savemat(d / "v5.mat", variables)
scipy.io.savemat(d / "v5_compressed.mat", variables, do_compression=True)


def matlab_class(ds, name):
    t = h5py.h5t.C_S1.copy()
    t.set_size(len(name))
    t.set_strpad(h5py.h5t.STR_NULLTERM)
    a = h5py.h5a.create(ds.id, b"MATLAB_class", t, h5py.h5s.create(h5py.h5s.SCALAR))
    a.write(np.array(name.encode(), dtype=f"S{len(name)}"), mtype=t)


with h5py.File(d / "v73.mat", "w", userblock_size=512) as h:
    matlab_class(h.create_dataset("acc", data=x[:32].reshape(1, -1)), "double")
    matlab_class(h.create_dataset("XRPM", data=np.array([[1797.0]])), "double")
with open(d / "v73.mat", "r+b") as f:
    f.write(b"MATLAB 7.3 MAT-file, Platform: GLNXA64, HDF5 schema 1.00 .".ljust(116, b" ") +
            b"\0" * 8 + struct.pack("<H", 0x0200) + b"IM")

d = folder("h5")
with h5py.File(d / "vector_rate_unit.h5", "w") as h:
    v = h.create_dataset("acc", data=x[:32])
    v.attrs["rate"] = 25600.0
    v.attrs["unit"] = "g"
with h5py.File(d / "table_columns_units.h5", "w") as h:
    t = h.create_dataset("tbl", data=np.column_stack([np.arange(16) / 100.0, x[:16], x[16:32]]))
    t.attrs["columns"] = ["t", "ax", "ay"]
    t.attrs["units"] = ["s", "m/s^2", "m/s^2"]
with h5py.File(d / "int16_fs.h5", "w") as h:
    c = h.create_dataset("counts", data=np.arange(-8, 8, dtype="i2"))
    c.attrs["fs"] = np.int32(100)
    c.attrs.create("unit", np.bytes_("m"))

for f in sorted(root.glob("record_*/*")):
    print(f"{f}: {f.stat().st_size} bytes")
