"""granular.breathers: breathers of one chain by shooting, continuation and Floquet stability (docs/breathers.md)."""

import math

import numpy as np

from . import _core
from ._schema import TableKeywords, split_keywords, with_keywords

_NUMBERS = ("omega", "freq_khz", "energy", "amplitude", "max_multiplier", "residual", "max_open_fraction")


class Breathers:
    """The result of granular.breathers: one entry per point of the branch.

    omega [rad/s], freq_khz, energy [J] above the static state, amplitude: max |x0| [m], centre: bead of it (1..N),
    max_multiplier: max |mu| without the +1 pair; stable (bool: never True from an incomplete set); complete (bool:
    False when ARPACK converged only some of the largest multipliers, whose max_multiplier is then a lower bound and
    whose verdict is unstable or unknown); verdict_trusted (bool: False where stable and max_multiplier are the
    discretized map's rather than the orbit's, at F0 = 0, where they do not converge with steps_per_period;
    verdict_untrusted_reason says why, '' when every verdict is trusted); newton_iterations, residual: the final relative
    residual |du/dt(T/2)| / (omega |x0|), max_open_fraction; profiles: points x N displacements x0 [m] at the
    turning point; open_fraction: points x (N+1) fraction of the period each bond is open; multipliers: points x 2N
    complex Floquet multipliers (with ARPACK points x k, the largest, NaN-padded to the most of a point);
    linear_khz: every linear mode [kHz] (at F0 = 0: the beads' on-site frequencies); seed_mode (0: a profile or a
    site), seed_site (F0 = 0: the bead 1..N of the on-site seed, else 0), seed_khz [kHz]; stop_reason; metadata: the
    breathers tool's JSON
    (parameters, Newton histories and GMRES iterations, which methods ran, symplectic checks)."""

    def __init__(self, values):
        points = values.pop("points")  # one dict per point, stacked here into arrays
        self.__dict__.update(values)
        n, rows = len(self.linear_khz), len(points)
        width = max((len(p["multipliers"]) for p in points), default=2 * n)
        for p in points:
            p["multipliers"] = list(p["multipliers"]) + [complex(math.nan, math.nan)] * (width - len(p["multipliers"]))
        columns = [(name, float, None) for name in _NUMBERS] + [
            ("centre", np.int64, None), ("newton_iterations", np.int64, None), ("stable", bool, None), ("complete", bool, None),
            ("verdict_trusted", bool, None),
            ("profiles", float, n), ("open_fraction", float, n + 1), ("multipliers", complex, width)]
        for name, dtype, width in columns:
            column = np.array([p[name] for p in points], dtype=dtype)
            setattr(self, name, column if width is None else column.reshape(rows, width))

    def __len__(self):
        return len(self.freq_khz)

    def __repr__(self):
        seed = f"site {self.seed_site}" if self.seed_site else f"mode {self.seed_mode}"
        return f"<granular.Breathers: {len(self)} points from {seed}; stopped: {self.stop_reason}>"


_BRANCH = TableKeywords(_core.BreatherBranchConfig())  # the library's breather_parameters(), C++ defaults


def breathers(chain, *, seed_profile=None, **keywords):
    """A branch of breathers of `chain` (a granular.Chain with F0 > 0, or at F0 = 0 a chain on on-site springs:
    granular.quasiperiodic('s1', F0=0, k0_n_per_m=...)), as the breathers tool computes it.

    Seed: linear mode number `mode` (1..N), or the mode nearest `near` [kHz], or the mode nearest `start_khz` (which
    must then lie outside the linear bands), or `seed_profile`: N displacements [m] of a state at rest, Newton's
    first guess at start_khz (then required, mode and near unset), e.g. an earlier branch's profiles[k]. The first
    point is at start_khz, by default just off the seed towards target_khz (downwards without one: the precompressed
    Hertz chain softens); the branch is continued in frequency (continuation='natural': natural parameter, secant
    predictor, step control, first step step_khz, 0: automatic; a fold in frequency ends it. continuation=
    'arclength': pseudo-arclength in (x0, omega) from the third point on, which follows the branch round folds) until
    target_khz, max_points, a Newton failure, a linear mode frequency, or (unless through_opening) the first open
    contact. The metadata records which Newton and Floquet methods ran.
    F0 = 0 (beads on on-site springs, touching without precompression, a Newton's cradle; James, Kevrekidis & Cuevas,
    Physica D 251 (2013) 39): no linear mode seeds (mode and near refused); the seed is bead `site` (1..N, 0: the
    middle one) oscillating on its spring, dressed by harmonic balance, start_offset above its on-site frequency
    (these breathers harden: the branch goes up in frequency), or seed_profile at start_khz. Every contact opens
    there, so through_opening does not matter. A chain at F0 = 0 without on-site springs raises ValueError naming F0.
    near_khz and floquet_multipliers: the former keywords of near and multipliers (deprecated).
    Returns a granular.Breathers. Releases the GIL."""
    if not isinstance(chain, _core.Chain):
        raise TypeError("chain: expected a granular.Chain")
    (given,) = split_keywords(keywords, [_BRANCH], "breathers")
    c = _BRANCH.make(given)
    if seed_profile is not None:
        c.seed_profile = [float(x) for x in seed_profile]
    return Breathers(_core._breathers(chain, c))


with_keywords(breathers, [_BRANCH], "Branch keywords (the library's breather_parameters(), with its C++ defaults)")
