#!/usr/bin/env python3
"""Packs roofsweep_qgis/ into a zip for QGIS's Plugins > Install from ZIP.

Usage: make_zip.py OUT.zip. Entries are sorted and __pycache__ is left out;
the zip is written to a temporary name and renamed.
"""

import os
import sys
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))


def make_zip(out):
    tmp = out + ".tmp"
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as z:
        for d, dirs, files in os.walk(os.path.join(HERE, "roofsweep_qgis")):
            dirs[:] = sorted(x for x in dirs if x != "__pycache__")
            for f in sorted(files):
                if not f.endswith(".pyc"):
                    path = os.path.join(d, f)
                    z.write(path, os.path.relpath(path, HERE))
    os.replace(tmp, out)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: make_zip.py OUT.zip")
    make_zip(sys.argv[1])
