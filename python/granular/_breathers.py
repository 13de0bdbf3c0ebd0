"""granular.breathers: breathers of one chain by shooting, continuation and Floquet stability (docs/breathers.md)."""

import math

import numpy as np

from . import _core

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


def _nan(value):
    return math.nan if value is None else float(value)


def breathers(chain, *, mode=0, near_khz=None, start_khz=None, target_khz=None, step_khz=0.0, max_points=100,
              law="hertz", scheme="saba2c", steps_per_period=0, tolerance=1e-10, stability_tolerance=1e-6,
              through_opening=False, continuation="natural", seed_profile=None, newton="auto", floquet="auto",
              floquet_multipliers=16, site=0, start_offset=1e-3):
    """A branch of breathers of `chain` (a granular.Chain with F0 > 0, or at F0 = 0 a chain on on-site springs:
    granular.quasiperiodic('s1', F0=0, k0_n_per_m=...)), as the breathers tool computes it.

    Seed: linear mode number `mode` (1..N), or the mode nearest `near_khz`, or the mode nearest `start_khz` (which
    must then lie outside the linear bands), or `seed_profile`: N displacements [m] of a state at rest, Newton's
    first guess at start_khz (then required, mode and near_khz unset), e.g. an earlier branch's profiles[k]. The first point is at start_khz, by default just off the seed towards
    target_khz (downwards without one: the precompressed Hertz chain softens); the branch is continued in frequency
    (continuation='natural': natural parameter, secant predictor, step control, first step step_khz, 0: automatic;
    a fold in frequency ends it. continuation='arclength': pseudo-arclength in (x0, omega) from the third point on,
    which follows the branch round folds) until target_khz, max_points, a Newton failure, a linear mode frequency, or
    (unless through_opening) the first open contact.
    law: 'hertz' | 'fpu'; scheme: the splitting scheme of shooting and monodromy; steps_per_period: 0 chooses;
    tolerance: Newton's relative residual; stability_tolerance: stable when max |mu| <= 1 + it.
    newton: 'dense' (the N x N Jacobian) | 'krylov' (matrix-free preconditioned GMRES) | 'auto' (dense up to 1000
    beads); floquet: 'dense' (all 2N multipliers) | 'arpack' (the floquet_multipliers of largest modulus) | 'auto'
    (dense up to 1000 beads, then ARPACK; up to 3000 beads ARPACK within the dense method's cost, then dense unless
    every multiplier converged). The metadata records which ran.
    start_offset: the first frequency's relative distance from the seed's (from a mode: below it, at most a quarter
    of the way to the next mode; from a site: above it).
    F0 = 0 (beads on on-site springs, touching without precompression, a Newton's cradle; James, Kevrekidis & Cuevas,
    Physica D 251 (2013) 39): no linear mode seeds (mode and near_khz refused); the seed is bead `site` (1..N, 0: the
    middle one) oscillating on its spring, dressed by harmonic balance, start_offset above its on-site frequency
    (these breathers harden: the branch goes up in frequency), or seed_profile at start_khz. Every contact opens
    there, so through_opening does not matter. A chain at F0 = 0 without on-site springs raises ValueError naming F0.
    Returns a granular.Breathers. Releases the GIL."""
    c = _core.BreatherBranchConfig()
    c.mode = int(mode)
    c.near_khz, c.start_khz, c.target_khz = _nan(near_khz), _nan(start_khz), _nan(target_khz)
    c.step_khz = float(step_khz)
    if not isinstance(chain, _core.Chain):
        raise TypeError("chain: expected a granular.Chain")
    c.max_points = _core._size(max_points, "max_points", 1, 1000000)
    c.law = law
    if c.law == "linear":
        raise ValueError("law linear: every amplitude is a periodic orbit; use hertz or fpu")
    c.shooting.scheme = scheme
    c.shooting.steps_per_period = _core._size(steps_per_period, "steps_per_period", 0, 100000000)
    c.shooting.tolerance = _core._finite(tolerance, "tolerance")
    c.stability_tolerance = _core._finite(stability_tolerance, "stability_tolerance")
    c.shooting.newton = newton
    c.floquet_method = floquet
    c.floquet_multipliers = _core._size(floquet_multipliers, "floquet_multipliers", 1, 1000000)
    c.stop_at_opening = not through_opening
    c.site = int(site)
    c.start_offset = _core._finite(start_offset, "start_offset")
    c.continuation = continuation
    if seed_profile is not None:
        c.seed_profile = [float(x) for x in seed_profile]
    return Breathers(_core._breathers(chain, c))
