"""Figures of the disordered Klein-Gordon chain: m2(t), P(t) and the finite-time mLE Lambda(t) on log-log axes,
with the literature's weak-chaos slopes as guides."""
import numpy as np

from . import _io
from ._style import figure, log_ticks, style, wrapped_suptitle


def _kg_data(source):
    """(t, m2, P, Lambda or None, metadata) of a granular.KleinGordon or the klein-gordon tool's CSV; Lambda is
    10^<log10 Lambda> (the field's average over realizations; one realization: its own Lambda)."""
    if _io.is_path(source):
        rows, meta = _io.read_csv(source), _io.read_json_beside(source)
        mean_log = rows.get("mean_log10_mle")
        return rows["t"], rows["m2"], rows["P"], None if mean_log is None else 10 ** mean_log, meta
    mean_log = source.mean_log10_mle
    return (source.t, source.m2, source.P, None if mean_log is None else 10 ** np.asarray(mean_log),
            source.metadata)


def _guide(ax, t, y, slope, label, ls="--"):
    """A grey power law t^slope through the last point of the curve (t, y)."""
    ok = np.isfinite(y) & (y > 0) & (t > 0)
    if ok.sum() < 2:
        return
    t, y = t[ok], y[ok]
    ts = np.array([t[len(t) // 3], t[-1]])
    ax.loglog(ts, y[-1] * (ts / t[-1]) ** slope, ls=ls, color="0.5", lw=1, label=label)


def klein_gordon(source):
    """A DKG run: the second moment m2(t), the participation number P(t) and, when computed, the finite-time
    maximal Lyapunov exponent Lambda(t), each on log-log axes, with guide slopes through each curve's last point: m2 ~ t^(1/3) and
    Lambda ~ t^(-1/4) dashed (weak chaos: Flach, Krimer & Skokos 2009; Senyange, Many Manda & Skokos 2018),
    Lambda ~ 1/t dotted (a regular orbit).

    source: a granular.KleinGordon or the klein-gordon tool's CSV (its JSON beside it for the title).
    """
    t, m2, P, lam, meta = _kg_data(source)
    t, m2, P = map(np.asarray, (t, m2, P))
    panels = 3 if lam is not None else 2
    with style():
        fig = figure(4.2 * panels, 4.2)
        axes = fig.subplots(1, panels)
        axes[0].loglog(t, m2, color="C0")
        _guide(axes[0], t, m2, 1 / 3, r"$t^{1/3}$")
        axes[0].set_ylabel(r"second moment $m_2$ [sites$^2$]")
        axes[1].loglog(t, P, color="C1")
        axes[1].set_ylabel("participation number P [sites]")
        if lam is not None:
            keep = np.isfinite(lam) & (lam > 0)
            axes[2].loglog(t[keep], lam[keep], color="C3")
            _guide(axes[2], t, lam, -0.25, r"$t^{-1/4}$")
            _guide(axes[2], t, lam, -1.0, r"$t^{-1}$ (regular)", ls=":")
            several = meta.get("parameters", {}).get("realizations", 1) > 1
            axes[2].set_ylabel(r"$10^{\langle \log_{10} \Lambda \rangle}$ [$\omega_0$]" if several
                               else r"finite-time mLE $\Lambda$ [$\omega_0$]")
        for ax in axes:
            log_ticks(ax.xaxis)
            log_ticks(ax.yaxis)
            ax.set_xlabel(r"time t [$1/\omega_0$]")
            if ax.get_legend_handles_labels()[0]:
                ax.legend(loc="best", frameon=False)
        p = meta.get("parameters", {})
        if p:
            kick = f"E = {p['energy']:g} on one site" if p.get("block", 0) == 0 else \
                f"h = {p['energy']:g} on {p['block']} sites"
            count = p.get("realizations", 1)
            wrapped_suptitle(fig, f"DKG chain: N = {p.get('N')}, W = {p.get('W'):g}, {kick}, seed {p.get('seed')}"
                             + (f", mean of {count} realizations" if count > 1 else ""))
    return fig
