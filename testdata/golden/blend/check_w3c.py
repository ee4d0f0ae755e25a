"""Checks the goldens of this folder against the W3C Compositing and Blending Level 1 formulas, computed with numpy
on the tint and hillshade pictures they were made from. Called by make_goldens.sh with its temporary folder."""
import sys
import numpy as np
from osgeo import gdal


def read(path):
    a = gdal.Open(path).ReadAsArray().astype(float)
    return np.moveaxis(a, 0, -1) if a.ndim == 3 else a


def soft_light_d(c):
    return np.where(c <= 0.25, ((16 * c - 12) * c + 4) * c, np.sqrt(c))


def w3c(op, cb, cs):
    return {
        "multiply": cb * cs,
        "screen": cb + cs - cb * cs,
        "overlay": np.where(cb <= 0.5, 2 * cb * cs, cs + (2 * cb - 1) - cs * (2 * cb - 1)),
        "soft-light": np.where(cs <= 0.5, cb - (1 - 2 * cs) * cb * (1 - cb), cb + (2 * cs - 1) * (soft_light_d(cb) - cb)),
    }[op]


tmp = sys.argv[1]
for case, ops in (("a", ["multiply", "screen", "overlay", "soft-light"]), ("b", ["multiply", "soft-light"])):
    cb = read(f"{tmp}/{case}-tint.png")[..., :3] / 255
    cs = (read(f"{tmp}/{case}-hill.png") / 255)[..., None]
    for op in ops:
        d = read(f"bt_{case}_{op}.png")[..., :3] - 255 * w3c(op, cb, cs)
        print(f"bt_{case}_{op}.png - W3C: min {d.min():.4f}, max {d.max():.4f} levels")
        assert d.min() > -1 and d.max() < 0.01, op
