"""The dynamics as the library has it: an initial state, granular.spread() -- which owns time and the integrator
-- and observers that measure the run. The classes are granular._core's; their docstrings and the keywords of
spread() and the kicks are here. Beads are 0-based, as in granular.Chain's arrays."""
import inspect
import operator

from . import _core
from ._arguments import double_vector
from ._core import FinalState, Observer, RunPlan, Snapshot, State
from ._model import _document


_state = State.__init__


def _state_init(self, u, v):
    u, v = double_vector(u, "u"), double_vector(v, "v")
    if len(u) != len(v):
        raise ValueError("v: needs as many entries as u")
    _state(self, u, v)


State.__init__ = _state_init


def _site(site, keyword):
    """A bead index (0-based), ValueError naming `keyword` when negative."""
    site = operator.index(site)
    if site < 0:
        raise ValueError(f"{keyword} {site}: a bead index (0-based) is >= 0")
    return site


# The library's defaults, written once in C++: the observer's settings, and a run's (its fit grid's step, the
# active window's threshold and the reference integrator's largest step: TransportCase's, IntegrationConfig's).
_SETTINGS = _core.EnergySpreadSettings()
_RUN = _core.TransportCase()


class EnergySpread(_core.EnergySpread):
    def __init__(self, *, samples=_SETTINGS.samples, sampling="log", site=None, fit=None, fit_step=_RUN.fit_step,
                 max_energy_error=_SETTINGS.max_energy_error, energy_guard="stop",
                 wall_warning=_SETTINGS.wall_warning):
        s = _core.EnergySpreadSettings()
        s.samples = _core._size(samples, "samples", 2)
        s.sampling = sampling
        if site is not None:
            s.site = _site(site, "site")
        if fit is not None:
            window = double_vector(fit, "fit")
            if len(window) != 2:
                raise ValueError("fit: expected (start, stop) [s]")
            s.dense.begin, s.dense.end, s.dense.step = window[0], window[1], fit_step
        s.max_energy_error = _core._finite(max_energy_error, "max_energy_error")
        if energy_guard not in ("stop", "warn"):
            raise ValueError(f"energy_guard '{energy_guard}': stop or warn")
        s.stop_on_energy_error, s.wall_warning = energy_guard == "stop", wall_warning
        super().__init__(s)

    @property
    def energy_guard_time(self):
        """first sample time [s] past the energy guard (energy_guard='warn'), or None"""
        t = _core.EnergySpread.energy_guard_time.fget(self)  # the library's -1: never
        return None if t < 0 else t


class Forces(_core.Forces):
    def __init__(self, at, *, samples=1000):
        s = _core.ForcesSettings()
        s.sites = [_site(site, "at") for site in at]
        s.samples = _core._size(samples, "samples", 2)
        super().__init__(s)


class EnergyMap(_core.EnergyMap):
    def __init__(self, *, samples=500, stride=1):
        s = _core.EnergyMapSettings()
        s.samples, s.stride = _core._size(samples, "samples", 2), _core._size(stride, "stride", 1)
        super().__init__(s)


class SpectralDensity(_core.SpectralDensity):
    def __init__(self, *, samples=2000, of="displacement"):
        s = _core.SpectralDensitySettings()
        s.samples, s.of = _core._size(samples, "samples", 2), of
        super().__init__(s)


_document(State, "A phase-space state: u [m] and v [m/s] of every bead (0-based), walls excluded.")
_document(RunPlan, "What an observer learns before the run.", total_steps="T / dt", time_step="dt [s]",
          duration="T [s]")
_document(Snapshot, "The chain at one observed time (a copy: it may be kept).", t="[s]", u="displacements [m] (a copy)",
          v="velocities [m/s] (a copy)", energy="site energies E_n [J] (a copy)", initial_energy="H(0) [J]")
_document(Observer, "Derive from it to measure a run: schedule(plan) returns the steps (0..plan.total_steps) to look "
          "at, observe(snapshot) is called at each, finish(snapshot) once at T. Call super().__init__().")
_document(EnergySpread, "m2 about the kicked bead (the paper's) and about the energy centroid [beads^2], P^-1 and the "
          "relative energy error at log-spaced (or uniform) times, with a dense grid `fit` = (start, stop) [s] every "
          "fit_step; the energy guard stops the run (energy_guard='stop') or records it ('warn').\n\n"
          f"EnergySpread{str(inspect.signature(EnergySpread.__init__)).replace('self, ', '')}")
_document(Forces, "The force [N] on beads `at` (0-based) at `samples` uniform times 0..T.\n\n"
          "Forces(at, *, samples=1000)", force="[site][sample] [N]")
_document(EnergyMap, "E_n(t) [J] at `samples` uniform times, `stride` beads summed per column.\n\n"
          "EnergyMap(*, samples=500, stride=1)", energy="[time][column] [J]")
_document(SpectralDensity, "g(nu) of u_n(t) (of_='displacement', the paper's) or v_n(t) at `samples` uniform times."
          "\n\nSpectralDensity(*, samples=2000, of='displacement')")
_document(FinalState, "The state at T with its site energies and bead forces.")


def displacement_kick(chain, site, alpha=_RUN.alpha):
    """u_n = alpha at bead `site` (0-based), the rest at rest: the paper's displacement kick [m]."""
    return _core._displacement_kick(chain, _site(site, "site"), alpha)


def velocity_kick(chain, site, beta=_core.paper_beta):
    """v_n = beta at bead `site` (0-based), the rest at rest: the paper's velocity kick [m/s]."""
    return _core._velocity_kick(chain, _site(site, "site"), beta)


def spread(chain, initial, observers=[], *, T=_RUN.duration, dt=_core._preferred_time_step, integrator=_RUN.integrator,  # noqa: B006
           force_law=_RUN.force_law, active_window=True, window_threshold=_RUN.window_threshold,
           reference_max_step=_RUN.reference_max_step):
    """Integrates `chain` from `initial` (a granular.State, e.g. granular.velocity_kick(chain, site, 8e-3)) to T [s]
    with steps dt [s], calling each observer at the steps it scheduled; the observers keep what they measured.
        integrator: 'saba2c' | 'saba2' | 'aba864' | 'srkn14a' | 'reference'; force_law: 'hertz' | 'fpu' | 'linear'
    Returns a dict: initial_energy [J], steps, bond_updates, window (final active beads [begin, end)), seconds.
    Releases the GIL (Python observers take it when called)."""
    return _core._spread(chain, initial, observers, T, dt, integrator, force_law, active_window, window_threshold,
                         reference_max_step)
