"""granular.ipr_map, granular.localization and granular.correlations: keywords, defaults, docstrings and
result classes. Each fills the library's study config (granular._core.IprMapConfig, ChainRecipe,
CorrelationConfig; C++ defaults) and makes one call to granular._core, which runs the study as the
tool does and returns its arrays and the tool's JSON."""
import math

import numpy as np

from . import _core
from ._arguments import number_list
from ._dynamics import _chain, _run
from ._linear import _selection
from ._model import _quasi
from ._schema import TableKeywords, split_keywords, with_keywords

_MAX = 100000000


class IprMap:
    """The result of granular.ipr_map. Every mode: freq_khz and ipr are (len(q), len(xi), N) arrays of means
    over the realizations (mode k at index k-1). With near/count or window: one entry per selected mode of
    every realization (see rows())."""

    def __init__(self, values):
        self._cells = values.pop("cells")
        self.disorder = values["disorder"]  # h | A | RDM1 | RDM2
        self.q, self.xi, self.N = values["q"], values["xi"], values["N"]  # the q grid, the xi grid (R2/R1), beads
        self.selection = values["selection"]  # True when made with near/count or window
        self.bin_khz = values["bin_khz"]  # width of the frequency bins [kHz] (0: averaged by mode number)
        # the ipr-map tool's JSON: parameters (disorder, xi, q, N, F0_N, R1_m, material, walls, realizations,
        # seed, threads, solver), averaging and bin_khz or selection, clustered, version
        # (granular::describe_ipr_map, as the tool writes it)
        self.metadata = values["metadata"]

    def _gather(self, field):
        out = np.concatenate([c[field] for c in self._cells]) if self._cells else np.empty(0)
        return out if self.selection else out.reshape(len(self.q), len(self.xi), self.N)

    @property
    def freq_khz(self):
        """mean mode frequencies [kHz], (len(q), len(xi), N); with a selection, one per row"""
        return self._gather("freq_khz")

    @property
    def ipr(self):
        """mean displacement IPRs, (len(q), len(xi), N); with a selection, one per row"""
        return self._gather("ipr")

    def rows(self):
        """The ipr-map tool's CSV columns as arrays: q, xi, [realization,] mode, freq_khz [kHz], ipr (one row per
        (q, xi, mode), or per selected mode of each realization); with bin_khz > 0: q, xi, freq_lo_khz,
        freq_hi_khz, modes (of all realizations in the bin), ipr (their mean; NaN for an empty bin)"""
        cells = self._cells

        def join(parts, dtype=float):
            return np.concatenate(parts).astype(dtype) if parts else np.empty(0, dtype)

        if self.bin_khz > 0 and not self.selection:  # frequency bins: the tool's binned CSV
            counts = [len(c["bin_modes"]) for c in cells]
            bins = [np.arange(n, dtype=float) for n in counts]
            return {"q": join([np.full(n, c["q"]) for n, c in zip(counts, cells)]),
                    "xi": join([np.full(n, c["xi"]) for n, c in zip(counts, cells)]),
                    "freq_lo_khz": join([b * self.bin_khz for b in bins]),
                    "freq_hi_khz": join([(b + 1) * self.bin_khz for b in bins]),
                    "modes": join([c["bin_modes"] for c in cells], np.int64),
                    "ipr": join([c["bin_ipr"] for c in cells])}
        counts = [len(c["freq_khz"]) for c in cells]
        d = {"q": join([np.full(n, c["q"]) for n, c in zip(counts, cells)]),
             "xi": join([np.full(n, c["xi"]) for n, c in zip(counts, cells)])}
        if self.selection:
            d["realization"] = join([c["realization"] for c in cells], np.int64)
            d["mode"] = join([c["mode"] for c in cells], np.int64)
        else:
            d["mode"] = join([np.arange(1, n + 1) for n in counts], np.int64)
        d["freq_khz"] = join([c["freq_khz"] for c in cells])
        d["ipr"] = join([c["ipr"] for c in cells])
        return d

    def __repr__(self):
        return f"<granular.IprMap {self.disorder}, {len(self.q)} q x {len(self.xi)} xi, N={self.N}>"


# granular.ipr_map's chain keywords: the rows of the library's chain table the ipr-map tool takes (not q, xi: the
# grid's, the map's own keywords), each with the map's C++ default (chain_choices of IprMapConfig{}.chain: N 100).
_IPR_MAP_CHAIN = TableKeywords(_core._ipr_map_chain(), skip=("q", "xi", "realization", "config", "radii"))


_C = _core.ChainChoices()  # the chain table's C++ defaults (chain_parameters())
_DB = _core.DynamicalButterflyConfig()  # dynamical_butterfly_parameters()' C++ defaults
_B = _core.ButterflyConfig()  # butterfly_parameters()' C++ defaults (the ratios as text: _butterfly_defaults)
_RATIOS = _core._butterfly_defaults["ratios"]

def ipr_map(*, xi=_core._ipr_map_defaults["xi"], q=_core._ipr_map_defaults["q"],
            realizations=_core.IprMapConfig().realizations, solver=_core.IprMapConfig().solver, near=None, count=None, window=None,
            method=None, bin_khz=_core.IprMapConfig().bin_khz, threads=0, progress=False, **chain_keywords):
    """Mean frequency [kHz] and displacement IPR of every mode of disordered chains over realizations, on a (q, xi)
    grid: the paper's IPR map, as the ipr-map tool computes it (same numbers for the same keywords).

    xi, q: size ratios R2/R1 in (0, 1] and probabilities in [0, 1]: sequences, numbers, or the tools' range
        strings ('0.1:1:0.01' = 0.1, 0.11, ..., 1 (step 0.01 for xi, 0.1 for q by default); '0.2,0.5,0.8')
    realizations: chains averaged per cell; realization r of seed `seed` is always the same chain, and all xi of
        one q share the bead sequences
    the chains: the chain keywords below (disorder, N, F0 > 0, R1, seed, walls, as granular.random_chain's)
    solver: 'fast' (default) | 'lapack' | 'lapack-stevr' | 'lapack-stemr' | 'lapack-stevd' | 'lapack-steqr'
    near, count / window: partial spectra (every selected mode of every realization, not averaged) by
        method = 'lapack' | 'bisect' | 'arpack'
    bin_khz: W > 0 averages every mode in frequency bins [k W, (k+1) W) [kHz] instead of by mode number (see
        IprMap.rows())
    threads: worker threads (0: every core); the result does not depend on it
    progress: draw a progress bar on stderr
    quasi and its keywords: a quasiperiodic chain instead (the tools' --quasi): one cell, q = xi = NaN; phase
        None averages over phases. types, type_masses, polydisperse: k bead types, k masses or polydisperse radii
        instead (disorder is then their rule): one cell, q = xi = NaN, realizations are draws
    Returns a granular.IprMap. Releases the GIL; Ctrl-C stops it (KeyboardInterrupt) after the cell in flight."""
    (given,) = split_keywords(chain_keywords, [_IPR_MAP_CHAIN], "ipr_map")
    c = _core.IprMapConfig()
    c.xi_values = number_list(xi, "xi", 0.01)
    c.q_values = number_list(q, "q", 0.1)
    c.realizations = _core._size(realizations, "realizations", 1)
    c.bin_khz = bin_khz
    c.solver, c.method = solver, "" if method is None else method
    _core._size(threads, "threads", 0, 4096)
    # the chain (its two-type draw; walls, a quasiperiodic chain or k types: one cell) and the solver by the tool's
    # rule, in C++
    beads = _chain(_IPR_MAP_CHAIN, _core._ipr_map_chain(), given)
    if near is not None or count is not None or window is not None:
        c.selection = _selection(near, count, window, got=False)
    return IprMap(_core._ipr_map(c, beads, _run(threads, progress=progress)))


class Butterfly:
    """The result of granular.butterfly: one row per mode per ratio, as the butterfly tool's CSV (ratio, mode,
    freq_khz [kHz], ipr: 1-D arrays of equal length), and per ratio (ratios) the box-counting dimension of its
    spectrum with its standard error (dimension, dimension_error); metadata: the tool's JSON (chain, ratios,
    box_counting with the fitted box sizes)."""

    def __init__(self, values):
        columns = values.pop("columns")  # one dict per ratio: its modes become rows
        self.__dict__.update(values)
        modes = [len(c["freq_khz"]) for c in columns]
        self.ratio = np.repeat([c["ratio"] for c in columns], modes).astype(float)
        self.mode = np.concatenate([np.arange(1, k + 1, dtype=np.uint64) for k in modes] + [np.zeros(0, np.uint64)])
        for name in ("freq_khz", "ipr"):
            setattr(self, name, np.concatenate([c[name] for c in columns] + [np.zeros(0)]))
        for name in ("dimension", "dimension_error"):
            setattr(self, name, np.array([c[name] for c in columns], dtype=float))

    def __repr__(self):
        return f"<granular.Butterfly {len(self.ratios)} ratios, {len(self.freq_khz)} modes>"


def butterfly(kind="s1", *, ratios=_RATIOS, N=_C.N, modulation=_C.modulation, phase=None,
              angle=_C.angle, k0=_C.k0, seed=_C.seed, realization=_C.realization, F0=_C.F0, R1=_core.paper_r1,
              largest_box=_B.largest_box, smallest_box=_B.smallest_box_spacings, box_sizes=_B.box_sizes, threads=0,
              progress=False):
    """The Hofstadter butterfly of a quasiperiodic chain (docs/physics.md, "Quasiperiodic chains"): every mode's
    frequency [kHz] and displacement IPR for each incommensurate ratio of `ratios` (a sequence, a number or the
    tools' range string), one chain (one phase) per ratio, and the box-counting dimension of each spectrum fitted
    on boxes from largest_box x its extent (0: 5 %, or 8 smallest boxes if more) down to smallest_box mean level
    spacings (box_sizes sizes). kind,
    modulation, phase, angle, k0, seed, realization, N, F0, R1: as granular.quasiperiodic. The same numbers as
    the butterfly tool for the same options. Returns a granular.Butterfly."""
    c = _core.ButterflyConfig()
    c.ratios = number_list(ratios, "ratios", 0.005)
    recipe = _core.ChainRecipe()
    recipe.N = _core._size(N, "N", 2, _MAX)
    recipe.F0, recipe.R1 = F0, R1
    recipe.seed = _core._size(seed, "seed")
    recipe.quasi = _quasi(kind, modulation, None, phase, angle, k0, keyword="kind")  # each ratio of `ratios` in turn
    c.chain = recipe
    c.realization = _core._size(realization, "realization")
    c.largest_box, c.smallest_box_spacings = largest_box, smallest_box
    c.box_sizes = _core._size(box_sizes, "box_sizes", 2)
    values = _core._butterfly(c, _run(threads, progress=progress))
    return Butterfly(values)


class DynamicalButterfly:
    """The result of granular.dynamical_butterfly: ratios (the betas, in the order given), freq_khz (the
    frequencies nu_j = j / (K dt) [kHz], the same for every ratio), power (len(ratios) x len(freq_khz): the
    velocities' power summed over beads, normalized to max 1 per ratio); metadata: the butterfly tool's JSON for
    --from dynamics (chain, initial_state, integration, spectrum with resolution_khz and nyquist_khz, and per ratio
    initial_energy_J, energy_over_opening, max_energy_error). rows() gives the tool's CSV columns."""

    def __init__(self, values):
        self.__dict__.update(values)
        self.ratios = np.asarray(self.ratios, dtype=float)
        self.power = np.array(self.power, dtype=float).reshape(len(self.ratios), len(self.freq_khz))

    def rows(self):
        """The tool's CSV columns ratio, freq_khz [kHz], power as 1-D arrays (one row per frequency per ratio)"""
        n = len(self.freq_khz)
        return {"ratio": np.repeat(self.ratios, n), "freq_khz": np.tile(self.freq_khz, len(self.ratios)),
                "power": self.power.ravel()}

    def __repr__(self):
        return f"<granular.DynamicalButterfly {len(self.ratios)} ratios x {len(self.freq_khz)} frequencies>"


def dynamical_butterfly(kind="s1", *, ratios=_RATIOS, N=_C.N, modulation=_C.modulation, phase=None,
                        angle=_C.angle, k0=_C.k0, seed=_C.seed, realization=_C.realization, F0=_C.F0,
                        R1=_core.paper_r1, T=_DB.duration, dt=_DB.time_step, amplitude=_DB.amplitude,
                        velocity_seed=_DB.velocity_seed, spectrum_samples=_DB.spectrum_samples,
                        spectrum_of=_DB.spectrum_of, integrator=_DB.integrator, force_law=_DB.force_law,
                        max_energy_error=_DB.max_energy_error, threads=0, progress=False):
    """The Hofstadter butterfly recovered from the dynamics (docs/quasiperiodic.md, "The butterfly from the
    dynamics"): for each ratio beta of `ratios` (a sequence, a number or the tools' range string) the chain is
    started from u = 0 and velocities uniform in [-amplitude, amplitude] [m/s] on every bead (seed velocity_seed,
    the same for every beta), integrated to T [s] with step dt [s] by `integrator` under `force_law`, and the power
    of the velocities (spectrum_of='velocity'; or 'displacement') sampled at spectrum_samples uniform times spanning
    [0, T] (spectrum_samples - 1 must divide T/dt) is summed over beads: its peaks sit on the eigenfrequencies (granular.butterfly) within the resolution
    1/T. The amplitude must leave the chain linear: an energy that could open a contact is refused; so are a dt
    past the scheme's stability limit and too few samples for the highest frequency (aliasing). A run whose
    relative energy error passes max_energy_error (0: off) stops with granular.NumericalError. kind, modulation,
    phase, angle, k0, seed, realization, N, F0 [N], R1 [m]: as granular.quasiperiodic. threads: 0 = every core;
    results do not depend on it. The same numbers as `butterfly --from dynamics` for the same options. Returns a
    granular.DynamicalButterfly. Bad keywords raise ValueError naming them."""
    c = _core.DynamicalButterflyConfig()
    c.ratios = number_list(ratios, "ratios", 0.005)
    recipe = _core.ChainRecipe()
    recipe.N = _core._size(N, "N", 2, _MAX)
    recipe.F0, recipe.R1 = _core._finite(F0, "F0"), _core._finite(R1, "R1")
    recipe.seed = _core._size(seed, "seed")
    recipe.quasi = _quasi(kind, modulation, None, phase, angle, k0, keyword="kind")  # each ratio of `ratios` in turn
    c.chain = recipe
    c.realization = _core._size(realization, "realization")
    c.amplitude = _core._finite(amplitude, "amplitude")
    c.velocity_seed = _core._size(velocity_seed, "velocity_seed")
    c.spectrum_samples = _core._size(spectrum_samples, "spectrum_samples", 2, _MAX)
    c.max_energy_error = _core._finite(max_energy_error, "max_energy_error")
    c.duration, c.time_step = _core._finite(T, "T"), _core._finite(dt, "dt")
    c.integrator, c.force_law, c.spectrum_of = integrator, force_law, spectrum_of
    values = _core._dynamical_butterfly(c, _run(threads, progress=progress))
    return DynamicalButterfly(values)


class Localization:
    """The result of granular.localization: per frequency the transfer-matrix Lyapunov exponent, the localization
    length and the density of states (the localization tool's columns).

    freq_khz: frequencies f [kHz]; lyapunov: lambda = (1/N) ln ||(u_(N+1), u_N)|| [1/bead], the inverse
    localization length; lyapunov_err: its standard error from the chain's segments [1/bead]; loc_length: 1/lambda
    [beads], inf where lambda <= 0 (inside a band); resolved: True where loc_length is a measurement, False where
    it is only a bound of order N (the rule: metadata['resolved_rule']); modes_below: eigenfrequencies of the
    finite chain below f (exact node counts); idos: integrated density of states, modes below f per bead; dos:
    d idos / df [1/(bead kHz)] (one frequency: from counts at f -/+ 0.005 kHz); N: beads of the chain; metadata:
    the localization tool's JSON (chain, parameters, columns, band_edges_khz, version)."""

    def __init__(self, values):
        self.__dict__.update(values)
        self.resolved = self.resolved.astype(bool)


_LOCALIZATION_CHAIN = TableKeywords(_core._localization_chain())


def localization(chain=None, *, f=_core._localization_frequencies, segments=_core.LocalizationScanConfig().segments,
                 threads=0, progress=False, **chain_keywords):
    """Localization length and density of states of one long chain by transfer matrices (docs/physics.md, 'Infinite
    chains'): the localization tool.

    chain: a granular.Chain; or None and the chain the chain keywords below pick, as the tool's chain options
        do (a random two-type draw, a types or radii file, k types, polydisperse radii or a quasiperiodic
        chain); a random two-type draw between flat walls is drawn a piece at a time, so N = 1e8 needs no
        more memory than N = 100 (the others are stored: N <= 1e8)
    f: frequencies [kHz], increasing: a sequence or the tools' range string ('0:50:0.01')
    segments: chain pieces whose exponents give lyapunov_err (2 ... 1e6)
    threads: workers over blocks of frequencies (0: every core); results do not depend on it
    Returns a granular.Localization (freq_khz, lyapunov [1/bead], lyapunov_err, loc_length [beads], modes_below,
    idos, dos, metadata). Releases the GIL; Ctrl-C stops it."""
    if chain is not None and not isinstance(chain, _core.Chain):
        raise TypeError("chain: expected a granular.Chain or None")
    if chain is not None and chain_keywords:
        raise ValueError(f"{next(iter(chain_keywords))}: not with a given chain (it is the chain's own)")
    if chain is not None and not chain.F0 > 0:
        raise ValueError("F0 0: the sonic vacuum has no linear limit (needs F0 > 0)")
    (given,) = split_keywords(chain_keywords, [_LOCALIZATION_CHAIN], "localization")
    choices = _LOCALIZATION_CHAIN.make(given)
    config = _core.LocalizationScanConfig()
    config.frequency_khz = number_list(f, "f", 0.01)
    config.segments = _core._size(segments, "segments")
    _core._validate_localization(config)  # the tool's check of f and segments, in C++
    return Localization(_core._localization(chain, choices, config, f, _run(threads, progress=progress)))


with_keywords(localization, [_LOCALIZATION_CHAIN], "Chain keywords (with chain None; the localization tool's "
              "chain options, made from the library's table)")


class Correlations:
    """The result of granular.correlations: rho(d) for d = 0..max_distance over realizations, with the
    infinite-chain formula.

    distance: d = 0..max_distance [beads]; rho_mean: ensemble mean of rho(d); rho_std: sample standard deviation
    of rho(d) over the realizations; rho_theory: infinite-chain rho(d) (NaN where undefined); used: realizations
    with both bead types (one-type chains have no rho and are skipped); metadata: the correlations tool's JSON
    (parameters, correlated, realizations_used, version)."""

    def __init__(self, values):
        self.__dict__.update(values)
        self.distance = np.arange(len(self.rho_mean), dtype=np.int64)


# granular.correlations' chain keywords: the rows of the library's chain table the correlations tool takes, each
# with the study's C++ default (chain_choices of CorrelationConfig{}.chain: N 100).
_CORRELATIONS = _core.CorrelationConfig()  # its C++ defaults: realizations, max_distance
_CORRELATION_CHAIN = TableKeywords(_core._correlation_chain(),
                                   only=("disorder", "q", "N", "seed", "types", "type_masses", "polydisperse"))


def correlations(*, realizations=_CORRELATIONS.realizations, max_distance=_CORRELATIONS.max_distance, threads=0,
                 progress=False, **chain_keywords):
    """Ensemble mean and spread of the Pearson coefficient rho(d) of bead types (type 1 -> 0, type 2 -> 1) with
    their cyclic shift by d, beside the infinite-chain formula: the correlations tool.

    realizations; max_distance < N
    the chains: the chain keywords below (disorder 'A' | 'RDM1' | 'RDM2', q, N, seed; or k bead types, k masses
        or polydisperse radii instead, the tool's --types, --type-masses, --polydisperse, disorder their rule:
        rho(d) of the bead masses)
    threads: worker threads (0: every core); progress: draw a progress bar
    Returns a granular.Correlations (distance, rho_mean, rho_std, rho_theory, used, metadata)."""
    (given,) = split_keywords(chain_keywords, [_CORRELATION_CHAIN], "correlations")
    c = _core.CorrelationConfig()
    c.realizations = _core._size(realizations, "realizations", 1)
    c.max_distance = _core._size(max_distance, "max_distance")
    beads = _chain(_CORRELATION_CHAIN, _core._correlation_chain(), given)
    return Correlations(_core._correlations(c, beads, _run(threads, progress=progress)))


_CHAIN_HEADING = "Chain keywords (the library's chain_parameters(), with the C++ defaults of {})"
with_keywords(ipr_map, [_IPR_MAP_CHAIN], _CHAIN_HEADING.format("the ipr-map tool's chains, IprMapConfig().chain"),
              first=True)
with_keywords(correlations, [_CORRELATION_CHAIN], _CHAIN_HEADING.format("the correlations tool's chains, "
              "CorrelationConfig().chain"), first=True)
