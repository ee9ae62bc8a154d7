#!/usr/bin/env python3
"""Oracle for tests/compiler/test_wavelet_emst.cpp: the total weight of the Euclidean minimum
spanning tree by SciPy on the complete distance matrix.

usage: scipy_mst.py IN      (IN: one point "x y z" per line; prints the total weight)
"""
import sys

import numpy as np
from scipy.sparse.csgraph import minimum_spanning_tree
from scipy.spatial import distance_matrix


def main():
    pts = np.loadtxt(sys.argv[1], ndmin=2)
    tree = minimum_spanning_tree(distance_matrix(pts, pts))
    print(repr(float(tree.sum())))


if __name__ == "__main__":
    main()
