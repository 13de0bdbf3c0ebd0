"""Shared fixtures: the command-line tools of the same build, run on the same seeds, and their
outputs read back exactly (shortest round-trip numbers: float(text) is the very double written)."""
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

BUILD = Path(os.environ.get("GRANULAR_BUILD_DIR", Path(__file__).resolve().parents[2] / "build")).resolve()
SOURCE = Path(os.environ.get("GRANULAR_SOURCE_DIR", Path(__file__).resolve().parents[2]))


def read_csv(path):
    """Columns of a CSV file: numeric ones as float64 arrays (exact), the others as lists of str;
    granular.plot's reader, with {} for a file of no rows."""
    from granular.plot import _io

    return _io.read_csv(path, allow_empty=True)


class Tools:
    def __init__(self, folder):
        self.folder = Path(folder)

    def run(self, tool, *args, output="out.csv"):
        """Runs build/<tool> with args and --output in a scratch folder; returns (csv columns, json)."""
        out = self.folder / output
        cmd = [str(BUILD / tool), *map(str, args), "--output", str(out)]
        done = subprocess.run(cmd, capture_output=True, text=True, cwd=self.folder)
        assert done.returncode == 0, f"{' '.join(cmd)} failed: {done.stderr}"
        csv_path = out if out.suffix == ".csv" else Path(str(out) + ".csv")
        json_path = csv_path.with_suffix(".json")
        with open(json_path) as f:
            meta = json.load(f)
        return read_csv(csv_path), meta

    def path(self, name):
        return self.folder / name


@pytest.fixture
def tools(tmp_path):
    if not (BUILD / "spectrum").exists():
        pytest.skip(f"the command-line tools are not built in {BUILD}")
    return Tools(tmp_path)


@pytest.fixture
def data_dir():
    return SOURCE / "data"


def assert_identical(a, b):
    """Exactly the same numbers (NaN equal to NaN), same shape."""
    a, b = np.asarray(a), np.asarray(b)
    assert a.shape == b.shape, (a.shape, b.shape)
    np.testing.assert_array_equal(a, b)
