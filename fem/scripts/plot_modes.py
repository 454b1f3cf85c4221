#!/usr/bin/python3
"""Draws a structure's mesh and mode shapes from `bearing-fem modes`' modes.vtu (matplotlib, no
VTK): the outer surface of the tetrahedra, grey with its edges, then each mode asked for,
deformed and coloured by the displacement's magnitude.

    /usr/bin/python3 fem/scripts/plot_modes.py DIR/modes.vtu --modes 1,2 --out picture.png

modes.vtu is deal.II's: inline base64, zlib-compressed (vtkZLibDataCompressor), one patch per cell
(its own copies of the vertices, merged here by position). The surface is every cell face that
belongs to one cell only.
"""
import argparse
import base64
import re
import struct
import zlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

DTYPES = {"Float32": np.float32, "Float64": np.float64, "Int32": np.int32, "UInt8": np.uint8}


def decode(text, dtype):
    """A binary DataArray of the zlib compressor: a UInt32 header (blocks, block size, last
    block's size, each block's compressed size), base64 apart from the data."""
    text = "".join(text.split())
    first = base64.b64decode(text[:8])
    blocks = struct.unpack("<I", first[:4])[0]
    head_len = 4 * ((12 + 4 * blocks + 2) // 3)
    head = base64.b64decode(text[:head_len])
    sizes = struct.unpack("<%dI" % (3 + blocks), head[:4 * (3 + blocks)])[3:]
    data = base64.b64decode(text[head_len:])
    out, at = b"", 0
    for s in sizes:
        out += zlib.decompress(data[at:at + s])
        at += s
    return np.frombuffer(out, dtype=DTYPES[dtype])


def read_vtu(path):
    xml = open(path, encoding="ascii", errors="replace").read()
    arrays = {}
    for m in re.finditer(r'<DataArray type="(\w+)"([^>]*)>(.*?)</DataArray>', xml, re.S):
        dtype, attrs, body = m.groups()
        name = re.search(r'Name="([^"]+)"', attrs)
        key = name.group(1) if name else "points"
        arrays[key] = decode(body, dtype)
    points = arrays.pop("points").reshape(-1, 3).astype(float)
    conn = arrays.pop("connectivity")
    offsets = arrays.pop("offsets")
    types = arrays.pop("types")
    if not np.all(types == 10):
        raise SystemExit("plot_modes.py draws meshes of linear tetrahedra (VTK type 10)")
    cells = conn.reshape(-1, 4)
    assert len(offsets) == len(cells)
    modes = {k: v.reshape(-1, 3).astype(float) for k, v in arrays.items() if k.startswith("mode_")}
    return points, cells, modes


def surface(points, cells):
    """Unique vertices (merged by position) and the boundary triangles in their numbering."""
    key = np.round(points / (np.abs(points).max() * 1e-9)).astype(np.int64)
    _, first, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
    tets = inverse.reshape(-1)[cells]
    faces = np.concatenate([tets[:, [0, 1, 2]], tets[:, [0, 1, 3]], tets[:, [0, 2, 3]],
                            tets[:, [1, 2, 3]]])
    ordered = np.sort(faces, axis=1)
    _, index, counts = np.unique(ordered, axis=0, return_index=True, return_counts=True)
    return first, faces[index[counts == 1]]


def draw(ax, xyz, tris, colour=None, title=""):
    polys = xyz[tris]
    coll = Poly3DCollection(polys, linewidths=0.1 if colour is None else 0,
                            edgecolors="0.3" if colour is None else None)
    if colour is None:
        coll.set_facecolor((0.8, 0.8, 0.82))
    else:
        coll.set_array(colour[tris].mean(axis=1))
        coll.set_cmap("viridis")
    ax.add_collection3d(coll)
    lo, hi = xyz.min(axis=0), xyz.max(axis=0)
    centre, half = (lo + hi) / 2, (hi - lo).max() / 2
    for set_lim, c in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), centre):
        set_lim(c - half, c + half)
    ax.set_box_aspect((1, 1, 1), zoom=1.3)
    ax.view_init(elev=25, azim=-125, vertical_axis="y")
    ax.set_axis_off()
    ax.set_title(title, fontsize=9)
    return coll


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("vtu")
    p.add_argument("--modes", default="1", help="mode numbers, e.g. 1,2")
    p.add_argument("--out", required=True)
    p.add_argument("--title", default="")
    p.add_argument("--scale", type=float, default=0.12,
                   help="largest displacement drawn, as a fraction of the structure's size")
    a = p.parse_args()
    points, cells, modes = read_vtu(a.vtu)
    first, tris = surface(points, cells)
    xyz = points[first] * 1e3  # mm
    names = sorted(modes)
    wanted = [int(m) for m in a.modes.split(",")]
    fig = plt.figure(figsize=(4 * (1 + len(wanted)), 4.2))
    draw(fig.add_subplot(1, 1 + len(wanted), 1, projection="3d"), xyz, tris,
         title=a.title or "mesh: %d tetrahedra" % len(cells))
    size = (xyz.max(axis=0) - xyz.min(axis=0)).max()
    for i, m in enumerate(wanted):
        name = names[m - 1]
        u = modes[name][first]
        mag = np.linalg.norm(u, axis=1)
        deformed = xyz + u * (a.scale * size / mag.max())
        freq = name.split("_")[2].replace("Hz", " Hz")
        draw(fig.add_subplot(1, 1 + len(wanted), 2 + i, projection="3d"), deformed, tris, mag,
             "mode %d: %s (|u| in colour)" % (m, freq))
    fig.tight_layout()
    fig.savefig(a.out, dpi=100)
    print("wrote", a.out)


if __name__ == "__main__":
    main()
