"""Reading what the figures draw: a result object of granular, or the files the tools write
(CSV with the JSON beside it, HDF5 energy maps). Nothing here needs the compiled extension."""
import csv
import json
import os

import numpy as np


def is_path(x):
    return isinstance(x, (str, bytes, os.PathLike))


def fit_window(case):
    """(start, stop) [s] of a kicked case's fit window (its JSON: fit_begin, fit_end), None when the case
    was not fitted (the window ends past its duration T). Files of granular 0.2.0 spelled it fit_s."""
    if "fit_s" in case:
        return tuple(case["fit_s"]) if case["fit_s"] else None
    if "fit_end" not in case:
        return None
    fitted = case.get("duration") is None or case["fit_end"] <= case["duration"] * (1 + 1e-12)
    return (case["fit_begin"], case["fit_end"]) if fitted else None


def read_csv(path, allow_empty=False):
    """Columns of a CSV file: numeric ones as float arrays, others as lists of str. A file of no
    rows is a ValueError, or {} with allow_empty."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        if allow_empty:
            return {}
        raise ValueError(f"{os.fspath(path)}: no rows")
    out = {}
    for key in rows[0]:
        values = [r[key] for r in rows]
        try:
            out[key] = np.array([float(v) for v in values])
        except ValueError:
            out[key] = values
    return out


def read_json_beside(path):
    """The tool's JSON beside a CSV (X.csv -> X.json), or {} when there is none."""
    json_path = os.path.splitext(os.fspath(path))[0] + ".json"
    if not os.path.exists(json_path):
        return {}
    with open(json_path) as f:
        return json.load(f)


def run_json_naming(path):
    """The metadata of the run that wrote `path` (an extra output such as an energy map, which has no
    JSON of its own): the tool JSON in the same folder whose command line names the file, or {}."""
    folder = os.path.dirname(os.path.abspath(os.fspath(path)))
    name = os.path.basename(os.fspath(path))
    for entry in sorted(os.listdir(folder)):
        if not entry.endswith(".json"):
            continue
        try:
            with open(os.path.join(folder, entry)) as f:
                meta = json.load(f)
        except (OSError, ValueError):
            continue
        command = meta.get("command") if isinstance(meta, dict) else None
        if isinstance(command, str) and any(os.path.basename(word) == name for word in command.split()):
            return meta
    return {}


def read_hdf5_map(path):
    """An energy map file of the spreading tool: (t [s], site, energy [J] times x columns)."""
    import h5py  # only for files; a granular result needs no HDF5 here

    with h5py.File(path, "r") as f:
        return np.array(f["t"]), np.array(f["site"]), np.array(f["energy"])


def band_edges_khz(xi, F0, R1=None):
    """The band edges [kHz] from the compiled core, or None without it (one home per formula)."""
    try:
        import granular

        kwargs = {} if R1 is None else {"R1": R1}
        return granular.band_edges(xi=xi, F0=F0, **kwargs).as_dict()
    except Exception:  # no extension, or no edges for these parameters (F0 = 0)
        return None


def spectrum_data(source):
    """(mode, freq_khz, ipr, metadata) of a granular.Spectrum or of the spectrum tool's CSV."""
    if is_path(source):
        rows = read_csv(source)
        meta = read_json_beside(source)
        return rows["mode"], rows["freq_khz"], rows["ipr"], meta
    return source.mode, source.freq_khz, source.ipr, source.metadata
