"""Figures of the disorder itself: the correlations rho(d) of the bead types (ensemble means beside
the infinite-chain formula) and the infinite chain's localization length l(f) from transfer
matrices (beside the IPR of finite chains)."""
import numpy as np

from . import _io
from ._style import chain_title, figure, log_ticks, mark_edges, style, wrapped_suptitle


def correlations(sources, labels=None):
    """Ensemble-mean correlation rho(d) of bead types (error bars: the spread over realizations)
    with the infinite-chain formula. sources: one or several granular.Correlations or CSVs."""
    if not isinstance(sources, (list, tuple)):
        sources = [sources]
    with style():
        fig = figure(6.4, 4.4)
        ax = fig.subplots()
        for i, source in enumerate(sources):
            if _io.is_path(source):
                rows = _io.read_csv(source)
                p = _io.read_json_beside(source).get("parameters", {})
                d, mean, std, theory = rows["distance"], rows["rho_mean"], rows["rho_std"], rows["rho_theory"]
            else:
                p = source.metadata.get("parameters", {})
                d, mean, std, theory = source.distance, source.rho_mean, source.rho_std, source.rho_theory
            label = labels[i] if labels else (f"{p['disorder']}, q = {p['q']:g}" if p else f"set {i + 1}")
            ax.errorbar(d, mean, yerr=std, fmt="o", ms=5, capsize=3, color=f"C{i}", label=f"{label}: mean ± std")
            ax.plot(d, theory, "-", color=f"C{i}", lw=1.2, label=f"{label}: infinite chain")
        ax.axhline(0, color="0.6", lw=0.6)
        ax.set_xlabel("distance d [beads]")
        ax.set_ylabel(r"correlation $\rho(d)$")
        ax.legend()
    return fig


def localization(source, spectra=(), finite_N=None):
    """Localization length l(f) = 1/lambda of the infinite chain (transfer matrices, with its
    statistical error) beside the IPR of every mode of finite chains of the same disorder: a mode
    is extended in a finite chain where l(f) exceeds its length. Band edges dashed.

    source: a granular.Localization or the localization tool's CSV. spectra: granular.Spectrum
    results or spectrum CSVs of finite chains (optional). finite_N: their length, drawn as a line
    on the left (default: from the spectra)."""
    if _io.is_path(source):
        rows = _io.read_csv(source)
        meta = _io.read_json_beside(source)
        f, lam, err = rows["freq_khz"], rows["lyapunov"], rows["lyapunov_err"]
        resolved = rows.get("resolved")
    else:
        meta = source.metadata
        f, lam, err = source.freq_khz, source.lyapunov, source.lyapunov_err
        resolved = getattr(source, "resolved", None)
    f, lam, err = (np.asarray(x, float) for x in (f, lam, err))
    resolved = np.ones(len(f), bool) if resolved is None else np.asarray(resolved, float) != 0
    with np.errstate(divide="ignore", invalid="ignore"):
        ell = np.where(lam > 0, 1 / lam, np.nan)
        ell_lo = np.where(lam > 0, 1 / (lam + err), np.nan)
        ell_hi = np.where(lam > err, 1 / (lam - err), np.nan)
    modes = [_io.spectrum_data(s) for s in spectra]
    if finite_N is None and modes:
        finite_N = modes[0][3].get("chain", {}).get("N") or len(modes[0][0])
    with style():
        fig = figure(11, 4.6)
        left, right = fig.subplots(1, 2, sharex=True)
        left.fill_between(f, ell_lo, ell_hi, color="C0", alpha=0.35, lw=0, label="± statistical error")
        left.plot(f, np.where(resolved, ell, np.nan), color="C0", lw=1.0,
                  label=r"$\ell = 1/\lambda$ (transfer matrix)")
        if not resolved.all():
            # Rows whose l is not a measurement (metadata['resolved_rule']): drawn, but not as one.
            shown = ~resolved | np.r_[~resolved[1:], False] | np.r_[False, ~resolved[:-1]]
            left.plot(f, np.where(shown, ell, np.nan), ls="--", color="0.55", lw=1.0,
                      label="not resolved: only a bound (resolved_rule)")
        left.set_yscale("log")
        log_ticks(left.yaxis)
        left.set_xlabel("frequency f [kHz]")
        left.set_ylabel(r"localization length $\ell$ [beads]")
        if finite_N:
            left.axhline(finite_N, ls=":", color="0.3", lw=1.2, label=f"N = {finite_N} (the finite chains)")
        for _, freq, ipr, _ in modes:
            right.plot(freq, ipr, ".", ms=3, color="C3")
        right.set_yscale("log")
        log_ticks(right.yaxis)
        right.set_xlabel("frequency f [kHz]")
        right.set_ylabel(r"mode IPR $P^{-1}$")
        right.set_title(f"modes of {len(modes)} finite chain(s)" + (f" of {finite_N} beads" if finite_N else "")
                        if modes else "no finite chains given", fontsize=11)
        left.legend(loc="best", fontsize=9)  # off the curve: where it sits depends on the chain
        edges = meta.get("band_edges_khz", {})
        left.set_xlim(f.min(), f.max())
        mark_edges(left, edges, orientation="vertical")
        mark_edges(right, edges, orientation="vertical", labels=False)
        chain = dict(meta.get("chain", {}))
        length = chain.pop("N", None)  # not a finite chain's: the transfer-matrix walk's
        title = chain_title(chain)
        if title and length:
            title += rf", $\ell$ from transfer matrices over {length:,} beads"
        if title:
            wrapped_suptitle(fig, title)
    return fig
