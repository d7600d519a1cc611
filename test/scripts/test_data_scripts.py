"""The data and summary scripts: the F-formation converter on MATLAB files shaped as GCFF
distributes its sequences, and the test summary's count of skipped tests."""
import importlib.util
import pathlib
import subprocess

import numpy
import pytest
import scipy.io

SCRIPTS = pathlib.Path(__file__).resolve().parents[2] / "scripts"


def load_script(path):
    """A script of the repository as a module (the scripts are programs, not an installed
    package)."""
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


fformation_to_csv = load_script(SCRIPTS / "data" / "fformation_to_csv.py")
test_summary = load_script(SCRIPTS / "test_summary.py")


def cell_row(items):
    row = numpy.empty((1, len(items)), dtype=object)
    for index, item in enumerate(items):
        row[0, index] = item
    return row


def write_sequence(folder):
    """Three frames: two people in a group and one alone; nobody; a group of three."""
    features = cell_row([
        numpy.array([[1, 100.0, 50.0, 0.0], [2, 220.0, 50.0, numpy.pi], [7, 500.0, 20.0, 1.5]]),
        numpy.zeros((0, 0)),
        numpy.array([[1, 0.0, 0.0, 0.5], [2, 10.0, 0.0, 1.0], [3, 5.0, 8.66, 4.2]]),
    ])
    groups = cell_row([cell_row([numpy.array([[1, 2]])]), cell_row([]),
                       cell_row([numpy.array([[3, 1, 2]])])])
    scipy.io.savemat(folder / "features.mat", {"features": features, "timestamp": [[1, 2, 3]]})
    scipy.io.savemat(folder / "groundtruth.mat", {"GTgroups": groups, "GTtimestamp": [[1, 2, 3]]})


def test_converter_writes_the_three_tables(tmp_path):
    write_sequence(tmp_path)
    fformation_to_csv.convert(str(tmp_path / "features.mat"), str(tmp_path / "groundtruth.mat"),
                              str(tmp_path), "Toy")
    assert (tmp_path / "Toy_frames.csv").read_text() == "frame\n1\n2\n3\n"
    assert (tmp_path / "Toy_features.csv").read_text() == (
        "frame,person_id,x,y,theta\n"
        "1,1,100.0000,50.0000,0.000000\n1,2,220.0000,50.0000,3.141593\n"
        "1,7,500.0000,20.0000,1.500000\n"
        "3,1,0.0000,0.0000,0.500000\n3,2,10.0000,0.0000,1.000000\n3,3,5.0000,8.6600,4.200000\n")
    assert (tmp_path / "Toy_groups.csv").read_text() == (
        "frame,group,person_id\n1,0,1\n1,0,2\n3,0,3\n3,0,1\n3,0,2\n")


def test_converter_refuses_sequences_of_different_lengths(tmp_path):
    write_sequence(tmp_path)
    scipy.io.savemat(tmp_path / "groundtruth.mat", {"GTgroups": cell_row([cell_row([])])})
    with pytest.raises(SystemExit, match="3 frames of features but 1 of ground truth"):
        fformation_to_csv.convert(str(tmp_path / "features.mat"),
                                  str(tmp_path / "groundtruth.mat"), str(tmp_path), "Toy")


RESULTS = """<?xml version="1.0"?>
<testsuites><testsuite name="s">
<testcase classname="A" name="passes"/>
<testcase classname="A" name="needs_data"><skipped message="data set missing: data set 'fformation' is not in /x"/></testcase>
<testcase classname="A" name="other_skip"><skipped message="no display"/></testcase>
</testsuite></testsuites>
"""


def test_summary_counts_skips_and_refuses_data_skips_when_asked(tmp_path, capsys):
    (tmp_path / "results.xml").write_text(RESULTS)
    assert test_summary.summarise(str(tmp_path), refuse_data_skips=False) == 0
    said = capsys.readouterr().out
    assert "tests: 1 passed, 0 failed, 2 skipped" in said
    assert "SKIPPED results.xml: A.needs_data: data set missing: data set 'fformation'" in said
    assert test_summary.summarise(str(tmp_path), refuse_data_skips=True) == 1
    assert "tests: 1 passed, 1 failed, 1 skipped" in capsys.readouterr().out


def test_fetch_data_checks_sets_without_fetching(tmp_path):
    missing = subprocess.run(["bash", str(SCRIPTS / "fetch_data.sh"), "--check", "mpgt"],
                             env={"ARI_DATA_DIR": str(tmp_path), "PATH": "/usr/bin:/bin"},
                             capture_output=True, text=True)
    assert missing.returncode == 1
    assert f"mpgt: missing ({tmp_path}/dialogue/mpgt)" in missing.stdout
    bad = subprocess.run(["bash", str(SCRIPTS / "fetch_data.sh"), "--nope"],
                         capture_output=True, text=True)
    assert bad.returncode == 2 and "unknown argument '--nope'" in bad.stderr


def test_fetch_data_refuses_a_set_that_does_not_match_its_checksums(tmp_path):
    corrupt = tmp_path / "dialogue" / "mpgt"
    corrupt.mkdir(parents=True)
    (corrupt / "convo1.txt").write_text("not the conversation\n")
    checked = subprocess.run(["bash", str(SCRIPTS / "fetch_data.sh"), "--check", "mpgt"],
                             env={"ARI_DATA_DIR": str(tmp_path), "PATH": "/usr/bin:/bin"},
                             capture_output=True, text=True)
    assert checked.returncode == 1
    assert "does not match scripts/data/mpgt.sha256" in checked.stderr
