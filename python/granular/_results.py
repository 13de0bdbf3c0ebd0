"""Result types of the dynamics calls: dicts of NumPy arrays with attribute access.

granular.spreading, granular.transport and granular.exponent_table return these. Each is a dict
(``run["m2"]``) whose keys are also attributes (``run.m2``); ``run.metadata`` is the dict the
tool writes as JSON (parameters, seed, version, exponents).
"""
import csv
import io

import numpy as np


class Result(dict):
    """A dict whose keys are also attributes."""

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError:
            raise AttributeError(f"{type(self).__name__} has no {name!r} (keys: {', '.join(self)})") from None

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self))

    def __repr__(self):
        return f"<granular.{type(self).__name__}: {', '.join(k for k in self if k != 'metadata')}>"


def _value(text):
    if text in ("true", "false"):
        return text == "true"
    try:
        return float(text)
    except ValueError:
        return text


def read_csv_text(text):
    """Columns of CSV text as the library writes it: numbers as float64 arrays (exact: shortest
    round-trip decimals), true/false as bool arrays, words as lists of str."""
    rows = list(csv.reader(io.StringIO(text)))
    if not rows:
        return {}
    header, body = rows[0], rows[1:]
    columns = {}
    for j, name in enumerate(header):
        values = [_value(r[j]) for r in body]
        if all(isinstance(v, bool) for v in values) and values:
            columns[name] = np.array(values, dtype=bool)
        elif all(isinstance(v, float) for v in values):
            columns[name] = np.array(values, dtype=float)
        else:
            columns[name] = values
    return columns


def _cases(columns, fields):
    """Rows grouped by case (ic, F0, disorder), in order: one dict of arrays per case."""
    cases, index = [], {}
    if not columns:
        return cases
    keys = list(zip(columns["ic"], columns["F0"], columns["disorder"]))
    for i, key in enumerate(keys):
        if key not in index:
            index[key] = len(cases)
            cases.append({"ic": key[0], "F0": float(key[1]), "disorder": key[2], "rows": []})
        cases[index[key]]["rows"].append(i)
    for case in cases:
        rows = case.pop("rows")
        for name in fields:
            case[name] = np.asarray(columns[name])[rows]
    return cases


class SpreadingRun(Result):
    """One spreading run (granular.spreading).

    t [s]; m2: second moment m~2 of the site energies about the kicked bead [beads^2] (the paper's);
    m2_centroid: about the energy centroid; ipr: P^-1 of the energy distribution; energy_error:
    |H(t) - H0| / H0; gamma, gamma_err, eta, eta_err, power_law, m2_centre: the exponents as the
    tool's JSON shows them (None when the fit window reaches past T), every report under
    'exponents'; initial_energy [J]; final_state: dict u [m], v [m/s], energy [J], force [N] per bead
    at T; forces: dict t [s], site (from 1), force [N] (sites x times) or None; energy_map: dict t
    [s], site (first bead of each column, from 1), energy [J] (times x columns) or None;
    spectral_density: dict freq_khz, g (normalized to max 1) or None; dissipated: energy removed by
    the damping by t [J] (damping_time/kk_gamma; else None); mle: X1(t) [1/s] by the tangent map
    (mle=True; else None); deviation: dict t [s], site (from 1), share (times x beads, the share of
    the deviation vector's norm^2 on each bead; deviation_samples) or None; lyapunov: dict t [s],
    exponents (times x k, lambda_1..lambda_k [1/s]), gali (times x (k-1), GALI_2..GALI_k), sali (None
    for k = 1) of a Lyapunov spectrum on the same orbit (lyapunov_vectors=k) or None; covariant: dict t [s],
    vectors (samples x k x 2N), growth_rates, exponents [1/s], split_angles [rad], participation,
    centre of k covariant Lyapunov vectors (covariant_vectors=k, as PREFIX-clv.h5) or None; warnings; reached_walls,
    wall_energy, steps, seconds; metadata (the spreading tool's JSON).
    """


class Transport(Result):
    """An ensemble of spreading runs (granular.transport): means and standard errors over realizations.

    t [s]; m2, m2_se, m2_centroid, m2_centroid_se [beads^2]; ipr, ipr_se; energy_error,
    energy_error_se; profile: dict energy, energy_se [J] per bead at T (or None); gamma, gamma_err
    (sub-window spread), gamma_real_err (bootstrap over realizations), eta, eta_err, eta_real_err,
    power_law, every report under 'exponents'; mle, mle_se: the mean X1(t) [1/s] over realizations
    and its standard error (mle=True; else None); max_energy_error; reached_walls; realizations;
    warnings; metadata (the spreading tool's JSON).
    """


class ExponentTable(Result):
    """The paper's transport study (granular.exponent_table), as the exponents tool writes it.

    table: the columns of PREFIX.csv as arrays, one entry per case (ic, F0, disorder, centre,
    gamma, gamma_err, gamma_real_err, gamma_star, ..., eta, ..., realizations, max_energy_error,
    reached_walls; with mle=True also mle, mle_real_err, mle_sd [1/s]); curves: one dict per case
    (ic, F0, disorder and arrays t, m2, m2_se, m2_centroid, m2_centroid_se, ipr, ipr_se,
    energy_error; with mle=True also mle, mle_se: <X1(t)> [1/s] and its standard error); profiles: one dict per profiled case
    (energy, energy_se per bead); markdown: the tool's tables; paper, paper_markdown: the comparison
    with the paper's Table I (compare_paper=True); metadata (the tool's JSON).
    """

    def __init__(self, values):
        values = dict(values)
        values["table"] = read_csv_text(values.pop("table_csv"))
        curves = read_csv_text(values.pop("curves_csv"))
        fields = ["t", "m2", "m2_se", "m2_centroid", "m2_centroid_se", "ipr", "ipr_se", "energy_error"]
        if "mle" in curves:  # the tangent map ran (mle=True)
            fields += ["mle", "mle_se"]
        values["curves"] = _cases(curves, fields)
        values["profiles"] = _cases(read_csv_text(values.pop("profiles_csv")), ["energy", "energy_se"])
        if "paper_csv" in values:
            values["paper"] = read_csv_text(values.pop("paper_csv"))
        super().__init__(values)

    def cell(self, ic, F0, disorder):
        """The table row of one case (ic 'displacement'/'velocity', F0 [N], disorder 'h'/'A'/'RDM1'/'RDM2') as a dict."""
        table = self["table"]
        for i, key in enumerate(zip(table["ic"], table["F0"], table["disorder"])):
            if key == (ic, F0, disorder):
                return {name: column[i] for name, column in table.items()}
        raise KeyError((ic, F0, disorder))

    def column(self, name):
        """One column of the table as a NumPy array (e.g. 'gamma')."""
        return np.asarray(self["table"][name])
