"""Result types of the dynamics calls: dicts of NumPy arrays with attribute access.

granular.spreading, granular.transport and granular.exponent_table return these. Each is a dict
(``run["m2"]``) whose keys are also attributes (``run.m2``); ``run.metadata`` is the dict the
tool writes as JSON (parameters, seed, version, exponents).
"""
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


class SpreadingRun(Result):
    """One spreading run (granular.spreading).

    t [s]; m2: second moment m~2 of the site energies about their centre [beads^2]; ipr: P^-1 of the
    energy distribution; energy_error: |H(t) - H0| / H0; gamma, eta: fits on the fit window (dicts
    value, error, slopes, power_law; None when the window reaches past T); initial_energy [J];
    final_state: dict u [m], v [m/s], energy [J], force [N] per bead at T; forces: dict t [s],
    site (from 1), force [N] (sites x times) or None; energy_map: dict t [s], site (first bead of
    each column, from 1), energy [J] (times x columns) or None; spectral_density: dict freq_khz,
    g (normalized to max 1) or None; reached_walls, wall_energy, steps, seconds; metadata.
    """


class Transport(Result):
    """An ensemble of spreading runs (granular.transport): means and standard errors over realizations.

    t [s]; m2, m2_se [beads^2]; ipr, ipr_se; energy_error, energy_error_se; profile: dict energy,
    energy_se [J] per bead at T (or None); gamma, eta: fits (dicts value, error, slopes, power_law,
    worst_deviation, worst_time) or None; max_energy_error; reached_walls; realizations; metadata.
    """


class ExponentTable(Result):
    """The paper's transport study (granular.exponent_table).

    table: one dict per case with the exponents tool's CSV columns (ic, F0, disorder, gamma,
    gamma_err, eta, eta_err, power_law_m2, power_law_ipr, worst_deviation_m2, worst_deviation_ipr,
    realizations, max_energy_error, reached_walls); curves: per case t, m2, m2_se, ipr, ipr_se,
    energy_error; profiles: per profiled case energy, energy_se; metadata.
    """

    def cell(self, ic, F0, disorder):
        """The table row of one case (ic 'displacement'/'velocity', F0 [N], disorder 'h'/'A'/'RDM1'/'RDM2')."""
        for row in self["table"]:
            if row["ic"] == ic and row["F0"] == F0 and row["disorder"] == disorder:
                return row
        raise KeyError((ic, F0, disorder))

    def column(self, name):
        """One column of the table as a NumPy array (e.g. 'gamma')."""
        return np.array([row[name] for row in self["table"]])

    def markdown(self, quantity="gamma", ic="displacement"):
        """A Markdown table of gamma or eta (value ± sub-window spread; † = not a power law), F0 by chain."""
        rows = [r for r in self["table"] if r["ic"] == ic]
        chains = list(dict.fromkeys(r["disorder"] for r in rows))
        f0s = list(dict.fromkeys(r["F0"] for r in rows))
        flag = "power_law_m2" if quantity == "gamma" else "power_law_ipr"
        lines = ["| F0 [N] | " + " | ".join(chains) + " |", "|---|" + "---|" * len(chains)]
        for f0 in f0s:
            cells = []
            for chain in chains:
                r = self.cell(ic, f0, chain)
                cells.append(f"{r[quantity]:.3f} ± {r[quantity + '_err']:.3f}{'' if r[flag] else ' †'}")
            lines.append(f"| {f0:g} | " + " | ".join(cells) + " |")
        return "\n".join(lines)
