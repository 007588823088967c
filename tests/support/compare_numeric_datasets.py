#!/usr/bin/python3
"""Compares the numeric datasets two pbrfit result files share, bit for bit.

Usage: compare_numeric_datasets.py A.h5 B.h5 [--only-common]
Prints each dataset that differs (or exists in one file only, unless --only-common) and exits 1 if any does.
"""
import sys

import h5py
import numpy as np


def numeric_datasets(path):
    found = {}
    with h5py.File(path, "r") as f:
        def visit(name, obj):
            if isinstance(obj, h5py.Dataset) and obj.dtype.kind in "biuf":
                found[name] = obj[...]
        f.visititems(visit)
    return found


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    only_common = "--only-common" in sys.argv
    a, b = numeric_datasets(args[0]), numeric_datasets(args[1])
    bad = 0
    for name in sorted(set(a) | set(b)):
        if name not in a or name not in b:
            if not only_common:
                print(f"only in {'the first' if name in a else 'the second'}: {name}")
                bad += 1
            continue
        x, y = a[name], b[name]
        if x.shape != y.shape or x.dtype != y.dtype or x.tobytes() != y.tobytes():
            print(f"differs: {name} {x.dtype}{x.shape} vs {y.dtype}{y.shape}")
            bad += 1
    common = len(set(a) & set(b))
    print(f"{common} common numeric datasets, {bad} differences")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
