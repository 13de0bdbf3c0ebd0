"""granular.klein_gordon: spreading and weak chaos in the disordered Klein-Gordon chain (docs/chaos.md), the
klein-gordon tool as a call. Its keywords are the rows of the library's klein_gordon_parameters() with
KleinGordonCase's C++ defaults (_schema.py): nothing here repeats a default or a help line."""
import numpy as np

from . import _core
from ._results import Result
from ._schema import TableKeywords, split_keywords, with_keywords

_CASE = TableKeywords(_core.KleinGordonCase())


class KleinGordon(Result):
    """A DKG run (granular.klein_gordon), as the klein-gordon tool writes it.

    t [1/omega0]: the sample times; m2 [sites^2] (about the energy's centroid), P [sites] (participation number) and
    mle [omega0] (the finite-time maximal Lyapunov exponent Lambda; None with mle=False): one realization's curves,
    or their means over the realizations; mean_log10_mle: <log10 Lambda> (NaN where a Lambda <= 0); runs_m2, runs_P,
    runs_mle: each realization's, shape (realizations, samples); max_energy_error: the largest |H - H(0)| / H(0);
    exponents: with fit=(t0, t1), the dict the tool's JSON holds under "exponents" (alpha, alpha_P, alpha_Lambda: the
    log-log slopes of the mean curves over the window; with realizations >= 2 also each one's realization mean and
    standard error, alpha_mean, alpha_error, ...), else None; energy_map: with energy_map=True, realization 0's site
    energies E_l (in units of H), shape (samples, N), each row summing to H (the tool's PREFIX-energy.h5), else None;
    metadata: the tool's JSON.
    """


def klein_gordon(**keywords):
    """The disordered Klein-Gordon chain H = sum p^2/2 + e_l x^2/2 + x^4/4 + (x_{l+1} - x_l)^2/(2W), e_l uniform
    in [1/2, 3/2], in its dimensionless units (time 1/omega0, energy in units of H): one central site of energy E
    (block=0) or `block` central sites at energy density h, integrated by SABA2C to T, with m2, P and Lambda at
    log-spaced times. A bad value is a ValueError naming its keyword. Returns a granular.KleinGordon."""
    (given,) = split_keywords(keywords, [_CASE], "klein_gordon")
    raw = _core._klein_gordon(_CASE.make(given))
    samples = len(raw["t"])
    for key in ("runs_m2", "runs_P", "runs_mle"):
        raw[key] = np.asarray(raw[key], dtype=float).reshape(-1, samples) if len(raw[key]) else None
    for key in ("mle", "mean_log10_mle"):
        raw[key] = raw[key] if len(raw[key]) else None
    raw["energy_map"] = np.asarray(raw["energy_map"], dtype=float).reshape(samples, -1) if len(raw["energy_map"]) \
        else None
    raw["exponents"] = raw["metadata"].get("exponents")  # the library's describe(), as the tool writes it
    return KleinGordon(raw)


with_keywords(klein_gordon, [_CASE], "Keywords (the library's klein_gordon_parameters(), with KleinGordonCase's C++ "
              "defaults)")
