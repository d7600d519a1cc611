#!/usr/bin/python3
"""Converts one F-formation sequence as GCFF distributes it (features.mat, groundtruth.mat: MATLAB
files) into the three CSV tables the project reads (docs/data.md):

  <set>_frames.csv    frame                        every annotated frame, 1-based, in order
  <set>_features.csv  frame,person_id,x,y,theta    positions in cm, theta in radians
  <set>_groups.csv    frame,group,person_id        ground-truth groups, numbered from 0 per frame

Usage: fformation_to_csv.py FEATURES.mat GROUNDTRUTH.mat OUT_DIR SET_NAME
In the .mat files `features` is a cell array with one matrix per frame, a row per person
[id, x, y, theta, ...], and `GTgroups` a cell array with one cell of groups (arrays of ids) per
frame. Needs scipy (Debian's python3-scipy).
"""
import pathlib
import sys

import numpy
import scipy.io


def cells(value) -> list:
    """The elements of a MATLAB cell array, in order, whatever its shape."""
    return list(numpy.asarray(value, dtype=object).ravel(order="F"))


def rows_of(matrix) -> numpy.ndarray:
    rows = numpy.asarray(matrix, dtype=float)
    if rows.size == 0:
        return rows.reshape(0, 4)
    return rows.reshape(-1, rows.shape[-1]) if rows.ndim > 1 else rows.reshape(1, -1)


def ids_of(group) -> list:
    return [int(round(float(v))) for v in numpy.asarray(group, dtype=float).ravel()]


def convert(features_path: str, groundtruth_path: str, out_dir: str, name: str) -> None:
    features = cells(scipy.io.loadmat(features_path)["features"])
    groups = cells(scipy.io.loadmat(groundtruth_path)["GTgroups"])
    if len(features) != len(groups):
        raise SystemExit(f"{features_path}: {len(features)} frames of features but "
                         f"{len(groups)} of ground truth in {groundtruth_path}")
    out = pathlib.Path(out_dir)
    with open(out / f"{name}_frames.csv", "w") as frames_file, \
            open(out / f"{name}_features.csv", "w") as features_file, \
            open(out / f"{name}_groups.csv", "w") as groups_file:
        frames_file.write("frame\n")
        features_file.write("frame,person_id,x,y,theta\n")
        groups_file.write("frame,group,person_id\n")
        for frame, (people, grouping) in enumerate(zip(features, groups), start=1):
            frames_file.write(f"{frame}\n")
            for row in rows_of(people):
                features_file.write(
                    f"{frame},{int(round(row[0]))},{row[1]:.4f},{row[2]:.4f},{row[3]:.6f}\n")
            group_cells = cells(grouping) if numpy.asarray(grouping).size else []
            for index, group in enumerate(group_cells):
                for person in ids_of(group):
                    groups_file.write(f"{frame},{index},{person}\n")


if __name__ == "__main__":
    if len(sys.argv) != 5:
        raise SystemExit(__doc__)
    convert(*sys.argv[1:])
