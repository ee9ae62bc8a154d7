#!/usr/bin/env python3
"""Oracle for tests/compiler/test_wavelet_haar.cpp: the 3D Haar transform by PyWavelets.

usage: pywt_haar3d.py IN OUT standard|nonstandard

IN holds the side n on its first line and then n^3 values, x fastest (index x + n*(y + n*z)).
OUT receives the orthonormal Haar coefficients ("haar", periodization) in the layout of
infer/wavelet/haar.h, in the same order, one per line.
"""
import sys

import numpy as np
import pywt


def main():
    src, dst, kind = sys.argv[1], sys.argv[2], sys.argv[3]
    with open(src) as f:
        n = int(f.readline())
        vals = np.array([float(x) for x in f.read().split()])
    levels = n.bit_length() - 1
    # numpy index [z, y, x] for the layout x + n*(y + n*z)
    a = vals.reshape(n, n, n)
    if kind == "standard":
        out = a
        for axis in range(3):
            parts = pywt.wavedec(out, "haar", mode="periodization", level=levels, axis=axis)
            out = np.concatenate(parts, axis=axis)
    else:
        coeffs = pywt.wavedecn(a, "haar", mode="periodization", level=levels)
        out = np.zeros_like(a)
        out[0, 0, 0] = coeffs[0].item()
        for j, details in enumerate(coeffs[1:]):
            s = 1 << j
            for key, c in details.items():
                oz, oy, ox = (s if ch == "d" else 0 for ch in key)
                out[oz:oz + s, oy:oy + s, ox:ox + s] = c
    with open(dst, "w") as f:
        f.write("\n".join(repr(float(v)) for v in out.reshape(-1)))
        f.write("\n")


if __name__ == "__main__":
    main()
