"""granular.spreading, granular.transport and granular.exponent_table: their keywords, defaults and
docstrings. Each fills the library's structs (granular._core.TransportCase, whose attributes are the rows of
transport_parameters(), ...; C++ defaults) and makes one call to granular._core, which completes the case by
the rule the tools use (case/transport_parameters.hpp), runs it and returns the library's result and
metadata; the result dicts (SpreadingRun, Transport) are shaped here."""
import math

import numpy as np

from . import _core
from ._arguments import double_vector, number_list
from ._results import ExponentTable, SpreadingRun, Transport
from ._schema import TableKeywords, split_keywords, with_keywords

# The run's keywords are the rows of the library's table over the case (transport_parameters(): alpha, centre, T,
# integrator, samples, fit_step, window_threshold, damping, mle, ...), each with the case's own C++ default and the
# table's help; those below are the ones Python takes in forms of its own.
_CASE = _core.TransportCase()
_TABLE = _core.ExponentTableConfig()  # the exponent table's C++ defaults: kinds, kicks, F0s, realizations, profiles
_OWN = ("beta", "site", "time_step", "fit", "fit_begin", "fit_end")
_OUTPUT_ROWS = tuple(_core._spreading_output_parameters)  # one run's force series, energy map and g(nu)
# One realization's tangent-space outputs: an ensemble writes no deviation vector and averages no spectrum.
_ONE_RUN_ROWS = ("deviation_samples", "lyapunov_vectors", "covariant_vectors", "covariant_transient")
_RUN = TableKeywords(_CASE, skip=_OWN + _OUTPUT_ROWS + _ONE_RUN_ROWS)
_ONE_RUN = TableKeywords(_CASE, skip=_OWN + _OUTPUT_ROWS)  # granular.spreading: with both
_OUTPUTS = TableKeywords(_CASE, only=_OUTPUT_ROWS, skip=("forces_at",))  # forces_at: a list of beads here
_MODE = TableKeywords(_core.ModeKick())  # a mode kick's mode, near, energy (mode_khz: near's former keyword)
# How an ensemble runs: the rows of the library's long_run_parameters() (threads, resume, resume_other_version,
# fresh, skip_failed, one_at_a_time), each with RunOptions' C++ default. The checkpoint is the front end's.
_LONG_RUN = TableKeywords(_core.RunOptions(), skip=("checkpoint", "progress"))
# The chains of an ensemble: the rows of the library's chain table (chain_parameters()) that the spreading tool takes
# with --realizations, each with the kicked case's C++ default (kicked_chain_defaults(): N 2501). Not the files
# (config, radii: one given chain, which an ensemble refuses) nor the realization (an ensemble runs 0..R-1).
_ENSEMBLE_SKIP = ("config", "radii", "realization")
_TRANSPORT_CHAIN = TableKeywords(_core._kicked_chain_defaults(), skip=_ENSEMBLE_SKIP)
# exponent_table's chains: the rows the exponents tool takes, each with ExponentChoices().beads's C++ default. Not
# disorder (the kinds are `chains`, the rule of k types `types_rule`), F0 (a list of the table's own) nor R1.
_TABLE_CHAIN = TableKeywords(_core.ExponentChoices().beads, skip=_ENSEMBLE_SKIP + ("disorder", "F0", "R1"))

_DYNAMICS_DOC = """\
    beta: velocity kick [m/s] (the paper's 8e-3 for every F0) or 'match' (the energy of alpha on each chain)
    site: kicked bead n0, counting from 1 as the tools do (None or 0: the centre, (N+1)/2)
    dt: time step tau [s]; None: 1 us, or 1 us/k where the stability rule tau <= h*/omega_max needs it (a dt past \
that limit is a ValueError naming the largest stable one; the rule and its numbers are in \
metadata['time_step_rule'])
    fit: (start, stop) [s] of gamma (m2 ~ t^gamma) and eta (P^-1 ~ t^-eta), sampled every fit_step [s] inside
"""

_MODE_DOC = """\
    mode, near, energy: with ic 'mode', the linear mode kicked (u = M^-1/2 w from rest, each chain's own): \
number `mode` 1..N by increasing frequency or the one nearest `near` [kHz], of total energy `energy` [J] or, \
without it, largest |u_n| = alpha (mode_khz: near's former keyword, deprecated)
"""

_MAX = 100000000


def _case(table, run, beta, site, dt, fit, c=None):
    """`c` (a new _core.TransportCase if None) with the run keywords `run` (a dict) set by `table` (a
    TableKeywords of the library's transport_parameters()) and those Python takes in forms of its own: beta a
    number or 'match', site None, dt None, fit a pair. integrator 'auto' is settled in C++ with the step."""
    c = table.set(_core.TransportCase() if c is None else c, run)
    if isinstance(beta, str):
        if beta != "match":
            raise ValueError(f"beta '{beta}': a number [m/s] or 'match'")
        c.beta = None
    else:
        c.beta = _core._finite(beta, "beta")
    c.site = 0 if site is None else _core._size(site, "site")
    c.time_step = None if dt is None else _core._finite(dt, "dt")
    window = double_vector(fit, "fit")
    if len(window) != 2:
        raise ValueError("fit: expected (start, stop) [s] with 0 < start < stop")
    c.fit_begin, c.fit_end = window
    return c


def _chain(table, out, given):
    """`out` (a _core.ChainChoices) with the chain keywords `given` set by `table` (a TableKeywords of the library's
    chain_parameters()), N and seed given checked here as sizes (N at most 1e8 beads, before a chain is drawn). The
    rest is checked in C++ by the tools' rule (one source, no keyword that would take no effect)."""
    table.set(out, given)
    if "N" in given:
        _core._size(out.N, "N", 2, _MAX)
    if "seed" in given:
        _core._size(out.seed, "seed")
    return out


def _run_options(given, checkpoint=None, progress=False):
    """The library's run options: the rows of `given` (keyword: value, _LONG_RUN's), where the run checkpoints and
    its progress bar."""
    r = _LONG_RUN.make(given)
    r.checkpoint = "" if checkpoint is None else str(checkpoint)
    r.progress = progress
    return r


def _run(threads=0, checkpoint=None, resume=False, resume_other_version=False, progress=False, fresh=False):
    """_run_options for the studies that spell their run keywords themselves."""
    return _run_options(dict(threads=threads, resume=resume, resume_other_version=resume_other_version, fresh=fresh),
                        checkpoint, progress)


def spreading(chain, *, ic=_CASE.kick, beta=_CASE.beta, site=None, dt=None, fit=(_CASE.fit_begin, _CASE.fit_end),
              forces_at=None, progress=False, **run):
    if not isinstance(chain, _core.Chain):
        raise TypeError(f"spreading: chain must be a granular.Chain, got {type(chain).__name__}")
    run, outputs, modes = split_keywords(run, [_ONE_RUN, _OUTPUTS, _MODE], "spreading")
    case = _case(_ONE_RUN, run, beta, site, dt, fit)
    _OUTPUTS.set(case, outputs)  # the optional observers: rows of the case, checked with it in C++
    beads = []
    if forces_at is not None:
        beads = double_vector(forces_at, "forces_at")
        for s in beads:
            if s != math.floor(s) or abs(s) > 2**62:
                raise ValueError(f"forces_at {_core._format_number(s)}: not a bead number (beads count from 1)")
        beads = [int(s) for s in beads]
        case.forces_at = ",".join(str(s) for s in beads)  # the row's text form: beads counting from 1
    # one realization: the chain's
    case.realizations, case.profile_realizations = 1, 0
    _MODE.set(case.mode, modes)
    case.kick = ic
    raw = _core._spreading(chain, case, _run(progress=progress))
    return _spreading_run(raw, chain.N, case, beads)


def _array_or_none(x):
    return x if len(x) else None


def _series(t, site, name, values, shape):
    """{t, site (from 1), <name>: values as a `shape` array} of a recorded series."""
    return {"t": t, "site": np.asarray(site, dtype=np.int64), name: np.asarray(values, dtype=float).reshape(shape)}


def _spreading_run(raw, N, case, sites):
    """The granular.SpreadingRun of _core._spreading's result (run: a _core._SpreadingResult) of `case`, its forces
    recorded at beads `sites` (counting from 1)."""
    r = raw["run"]
    out = dict(raw["exponents"])
    out["warnings"] = raw["warnings"]
    for name in ("t", "m2", "m2_centroid", "ipr", "energy_error", "initial_energy", "max_energy_error"):
        out[name] = getattr(r, name)
    out["final_state"] = {"u": r.final_state.u, "v": r.final_state.v, "energy": r.final_energy,
                          "force": r.final_force}
    # Beyond the paper: the columns `dissipated` and `mle` of the tool's CSV, and its --deviation file.
    out["dissipated"], out["mle"] = _array_or_none(r.dissipated), _array_or_none(r.mle)
    out["deviation"] = None
    if case.deviation_samples > 0:
        t = r.deviation_t
        out["deviation"] = _series(t, np.arange(1, N + 1), "share", r.deviation, (len(t), N))
    out["lyapunov"] = None
    if case.lyapunov_vectors > 0:
        s, k = r.lyapunov, case.lyapunov_vectors
        t = np.asarray(s.time, dtype=float)
        out["lyapunov"] = {"t": t, "exponents": np.asarray(s.exponents, dtype=float).reshape(len(t), k),
                           "gali": np.asarray(s.gali, dtype=float).reshape(len(t), k - 1),
                           "sali": np.asarray(s.sali, dtype=float) if k >= 2 else None}
    out["covariant"] = None
    if case.covariant_vectors > 0:  # the arrays of the tool's PREFIX-clv.h5, under its names
        c, k = r.covariant, case.covariant_vectors
        t = np.asarray(c.time, dtype=float)
        out["covariant"] = {"t": t, "vectors": np.asarray(c.rows, dtype=float).reshape(len(t), k, 2 * N),
                            "growth_rates": np.asarray(c.growth_rates, dtype=float),
                            "exponents": np.asarray(c.exponents, dtype=float),
                            "split_angles": np.asarray(c.split_angles, dtype=float).reshape(len(t), k - 1)
                            if k >= 2 else None,
                            "participation": np.asarray(c.participation, dtype=float).reshape(len(t), k),
                            "centre": np.asarray(c.centre, dtype=float).reshape(len(t), k)}
    out["forces"] = None
    if sites:
        t = r.force_t
        out["forces"] = _series(t, sites, "force", r.forces, (len(sites), len(t)))
    out["energy_map"] = None
    if case.energy_map:
        t, columns = r.map_t, r.map_columns
        out["energy_map"] = _series(t, np.arange(columns) * case.map_stride + 1, "energy", r.map_energy,
                                    (len(t), columns))
    out["spectral_density"] = None
    if case.spectral_density:
        out["spectral_density"] = {"freq_khz": r.spectrum_khz, "g": r.spectrum}
    for name in ("wall_energy", "reached_walls", "steps", "seconds"):
        out[name] = getattr(r, name)
    out["energy_guard_time"] = None if r.energy_guard_time < 0 else r.energy_guard_time
    out["metadata"] = raw["metadata"]
    return SpreadingRun(out)


spreading.__doc__ = (
    "Energy spreading after a single-site kick in one chain (docs/physics.md, 'Nonlinear dynamics'), integrated to T: the spreading "
    "tool for one realization.\n\n    chain: a granular.Chain (F0 = 0 is the sonic vacuum)\n"
    "    ic: 'displacement' (u = alpha at the site) | 'velocity' (v = beta at the site) | 'mode' (a "
    "linear mode of the chain, u = M^-1/2 w from rest: number `mode` 1..N or the one nearest `near` "
    "[kHz], total energy `energy` [J] or, without it, largest |u_n| = alpha)\n" + _DYNAMICS_DOC +
    "    forces_at: None, or beads (a list, counting from 1) whose force [N] is recorded at force_samples uniform "
    "times; the outputs' other keywords below (each count of samples >= 2 and map_stride >= 1, checked even when "
    "its output is not asked, as the tool's)\n"
    "Returns a granular.SpreadingRun: t [s], m2 and m2_centroid (second moments about the kicked bead and about "
    "the energy centroid [beads^2]), ipr (P^-1 of the energy), energy_error, gamma, eta (the shown values, as the "
    "tool's JSON) with every report under 'exponents', final_state (u [m], v [m/s], energy [J], force [N] per "
    "bead), forces, energy_map, spectral_density, dissipated (energy removed by the damping by t [J], at t; None "
    "without damping), mle (X1(t) [1/s] at t; None without mle), deviation (t [s], site (from 1), share (times x "
    "beads: the share of |w|^2 = |du|^2 + (t_unit dv)^2, t_unit = 1 us, on each bead, rows summing to 1; "
    "share.ravel() is the tool's --deviation column) or None), lyapunov (with lyapunov_vectors=k: t [s], exponents "
    "(times x k: lambda_1..lambda_k(t) [1/s]), gali (times x (k-1): GALI_2..GALI_k), sali (None for k = 1), the "
    "tool's PREFIX-lyapunov.csv; else None), covariant (with covariant_vectors=k: t [s] (the samples from "
    "covariant_transient to T), vectors (samples x k x 2N: du [dimensionless] then dv [1/s], unit norm in (du, "
    "t_unit dv)), growth_rates and exponents (k) [1/s], split_angles (samples x (k-1)) [rad] or None for k = 1, "
    "participation [beads] and centre [bead index, from 0] (samples x k), the tool's PREFIX-clv.h5; else None), "
    "warnings, metadata. Releases the GIL.")


def transport(*, realizations=100, ic=_CASE.kick, beta=_CASE.beta, site=None, dt=None,
              fit=(_CASE.fit_begin, _CASE.fit_end), profile=False, checkpoint=None, progress=False, **keywords):
    chain, given, modes, long_run = split_keywords(keywords, [_TRANSPORT_CHAIN, _RUN, _MODE, _LONG_RUN], "transport")
    words = _core._kicked_chain_defaults()  # made one case with `case` by the spreading tool's rule, in C++
    _chain(_TRANSPORT_CHAIN, words, chain)
    realizations = _core._size(realizations, "realizations", 1)
    case = _case(_RUN, given, beta, site, dt, fit)
    case.kick, case.realizations = ic, realizations
    _MODE.set(case.mode, modes)
    run = _run_options(long_run, checkpoint, progress)
    return _transport(_core._transport(words, case, profile, run), profile)


def _transport(raw, profile):
    """The granular.Transport of _core._transport's result (summary: a _core._TransportSummary)."""
    s = raw["summary"]
    out = dict(raw["exponents"])
    out["warnings"] = raw["warnings"]
    out["t"] = s.t
    for name in ("m2", "m2_centroid", "ipr", "energy_error"):
        series = getattr(s, name)
        out[name], out[name + "_se"] = series.mean, series.standard_error
    out["profile"] = {"energy": s.profile.mean, "energy_se": s.profile.standard_error} if profile else None
    # With the tangent map: <X1(t)> [1/s] (the tool's column mle) and its standard error.
    out["mle"], out["mle_se"] = _array_or_none(s.mle.mean), _array_or_none(s.mle.standard_error)
    for name in ("max_energy_error", "reached_walls", "realizations"):
        out[name] = getattr(s, name)
    out["metadata"] = raw["metadata"]
    return Transport(out)


transport.__doc__ = (
    "An ensemble of spreading runs: realizations 0..R-1 of seed `seed` of a disordered chain, each "
    "kicked and integrated to T, averaged and fitted (the spreading tool's --realizations R).\n\n"
    "    the chains: the chain keywords below (a random two-type draw, k types, polydisperse radii or a "
    "quasiperiodic chain, as the spreading tool's chain options; None: none), realization r of seed `seed` each\n"
    "    realizations: R; ic: 'displacement' | 'velocity' | 'mode'\n" + _MODE_DOC + _DYNAMICS_DOC +
    "    profile: also average the site energies E_n(T)\n"
    "    checkpoint: a file logging each finished realization (removed once the run completes); resume=True "
    "continues an interrupted run from it and gives exactly the uninterrupted result; a checkpoint another "
    "granular version made is refused unless resume_other_version=True (both are named in metadata); a run "
    "neither resuming nor fresh=True (discard it) refuses to start over a checkpoint an interrupted run left\n"
    "    progress: draw a progress bar\n"
    "    threads, resume, ..., skip_failed (a failed realization left out: metadata['ensemble']['failed_excluded'] "
    "says which), one_at_a_time: the run-control keywords below\n"
    "Returns a granular.Transport: t [s], m2, m2_centroid, ipr, energy_error with their standard errors (_se), "
    "profile, gamma, eta (with realization errors gamma_real_err, eta_real_err from the bootstrap) and every report "
    "under 'exponents', mle and mle_se (the mean X1(t) [1/s] over realizations and its standard error; None "
    "without mle), max_energy_error, reached_walls, realizations, warnings, metadata. Releases the GIL; "
    "Ctrl-C stops it after the realizations in flight (KeyboardInterrupt), leaving the checkpoint to resume from.")


def exponent_table(*, chains=_TABLE.chains, F0=_TABLE.precompressions,
                   types_rule=None, chain_name=None, ic=_TABLE.ic, realizations=_TABLE.base.realizations,
                   beta=_CASE.beta, site=None, dt=None, fit=(_CASE.fit_begin, _CASE.fit_end),
                   profile_F0=_TABLE.profile_precompressions, profile_realizations=_TABLE.profile_realizations,
                   compare_paper=False, checkpoint=None, progress=False, **keywords):
    chain, given, modes, long_run = split_keywords(keywords, [_TABLE_CHAIN, _RUN, _MODE, _LONG_RUN],
                                                   "exponent_table")
    table = _core.ExponentTableConfig()  # the kinds and kicks read by the tool's rows, in C++
    table.chains = [] if chains is None or chains == "none" else chains
    table.ic = ic
    _MODE.set(table.base.mode, modes)
    words = _core.ExponentChoices()  # every kind's chains, and the chain of one's own: k types, polydisperse
    _chain(_TABLE_CHAIN, words.beads, chain)  # radii, or quasiperiodic (made the table's by the tool's rule)
    words.types_rule = "" if types_rule is None else str(types_rule)
    words.chain_name = "" if chain_name is None else str(chain_name)
    table.precompressions = number_list(F0, "F0", 0)
    table.profile_precompressions = [] if profile_F0 is None else number_list(profile_F0, "profile_F0", 0)
    table.profile_realizations = _core._size(profile_realizations, "profile_realizations")
    table.base.realizations = _core._size(realizations, "realizations", 1)
    _case(_RUN, given, beta, site, dt, fit, table.base)
    run = _run_options(long_run, checkpoint, progress)
    # compare_paper: the path of a table in the paper's format, or True for the paper's own ("": no comparison)
    paper = compare_paper if isinstance(compare_paper, str) else _core._paper_table if compare_paper else ""
    return ExponentTable(_core._exponent_table(words, table, paper, run))


exponent_table.__doc__ = (
    "The paper's transport study (the exponents tool): gamma (m2 ~ t^gamma) and eta (P^-1 ~ t^-eta) "
    "for every chain kind x F0 x kick, each an ensemble of `realizations` (h runs one: it is "
    "deterministic).\n\n"
    "    chains: kinds among 'h', 'A', 'RDM1', 'RDM2' ('none' or []: only the quasiperiodic chain); F0: "
    "precompressions [N] (0: sonic vacuum); ic: kicks among 'displacement', 'velocity', 'mode'\n" + _MODE_DOC +
    "    realizations: R per disordered case; the chains: the chain keywords below (N, xi, q, seed, walls of "
    "every kind; quasi, or one of types, type_masses, polydisperse: one more chain after the kinds, as the tool's "
    "chain options)\n"
    "    types_rule: how types are drawn, 'A' (each bead, the default), 'RDM1' (each dimer) or 'RDM2' "
    "(two types: dimers 12 or 21)\n"
    "    chain_name: the name of that chain in the table (default 'types', 'polydisperse' or 'quasi-KIND')\n" +
    _DYNAMICS_DOC +
    "    profile_F0, profile_realizations: F0s whose E_n(T) is averaged, over how many realizations (None: none)\n"
    "    compare_paper: True (or the path of a table in its format) to compare gamma with the paper's Table I "
    "(z-scores with both error sources)\n"
    "    checkpoint: a prefix, case i logs to <prefix>.<i> (removed once done); resume=True continues an "
    "interrupted table (the run-control keywords below; a failed realization skipped with skip_failed is named "
    "by the case's failed_excluded in metadata); progress: a progress bar\n"
    "Returns a granular.ExponentTable: table (the tool's CSV columns as arrays; with mle also mle, mle_real_err, "
    "mle_sd: the mean X1(T) [1/s], its standard error over realizations, their standard deviation), curves (with "
    "mle also mle, mle_se: <X1(t)> [1/s] and its standard error), profiles, markdown, paper (the comparison, with "
    "compare_paper), metadata (with mle, X1(T) under each case's 'mle_at_T'). Releases the GIL; Ctrl-C stops it "
    "resumably (KeyboardInterrupt).")


_RUN_HEADING = "Run keywords (the library's transport_parameters(), with the case's C++ defaults)"
_MODE_HEADING = "Mode kick keywords (the library's mode_kick_parameters(), with ModeKick's C++ defaults)"
_CHAIN_HEADING = "Chain keywords (the library's chain_parameters(), with the C++ defaults of {})"
# Each signature as users think: the chain, the kick (ic, then the mode kick's), the dynamics (the run table after
# fit), the outputs, how the run goes (threads, checkpoint, progress).
for _job in (spreading, transport, exponent_table):
    with_keywords(_job, [_MODE], _MODE_HEADING, after="ic")
    with_keywords(_job, [_ONE_RUN if _job is spreading else _RUN], _RUN_HEADING, after="fit")
with_keywords(spreading, [_OUTPUTS], "Output keywords (the library's spreading_output_parameters(), with the "
              "observers' C++ defaults)", after="forces_at")
_LONG_RUN_HEADING = "Run-control keywords (the library's long_run_parameters(), with RunOptions' C++ defaults)"
for _job in (transport, exponent_table):
    with_keywords(_job, [_LONG_RUN], _LONG_RUN_HEADING, after="checkpoint")
with_keywords(transport, [_TRANSPORT_CHAIN], _CHAIN_HEADING.format("the spreading tool's chains, "
              "kicked_chain_defaults()"), first=True)
with_keywords(exponent_table, [_TABLE_CHAIN], _CHAIN_HEADING.format("the exponents tool's chains, "
              "ExponentChoices().beads"), first=True)
