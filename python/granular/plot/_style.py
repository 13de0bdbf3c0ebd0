"""One look for every figure: sizes that read on a slide, units on every axis, log axes with
decades labelled, the band edges drawn the same way everywhere."""
import contextlib
import io
import math

import matplotlib
from matplotlib.figure import Figure
from matplotlib.ticker import LogLocator, NullFormatter

STYLE = {
    "font.size": 12,
    "axes.titlesize": 12,
    "axes.labelsize": 13,
    "xtick.labelsize": 11,
    "ytick.labelsize": 11,
    "legend.fontsize": 10,
    "legend.frameon": False,
    "lines.linewidth": 1.6,
    "axes.grid": False,
    "xtick.direction": "in",
    "ytick.direction": "in",
    "xtick.top": True,
    "ytick.right": True,
    "savefig.bbox": "tight",
    "savefig.dpi": 150,
    "image.cmap": "viridis",
}

# How each band edge is written on a figure.
EDGE_LABELS = {
    "f1": r"$f_1$ (type 1)",
    "f2": r"$f_2$ (type 2)",
    "fb1": r"$f_{b1}$ (acoustic top)",
    "fb2": r"$f_{b2}$ (optical bottom)",
    "fb3": r"$f_{b3}$ (optical top)",
}
EDGE_SHORT = {"f1": r"$f_1$", "f2": r"$f_2$", "fb1": r"$f_{b1}$", "fb2": r"$f_{b2}$", "fb3": r"$f_{b3}$"}


@contextlib.contextmanager
def style():
    with matplotlib.rc_context(STYLE):
        yield


class GranularFigure(Figure):
    """A matplotlib Figure that needs no pyplot: a notebook shows it (as PNG) when a cell returns it,
    once, and it is garbage-collected when dropped (pyplot would keep every figure open)."""

    def _repr_png_(self):
        buffer = io.BytesIO()
        self.savefig(buffer, format="png", dpi=100, bbox_inches="tight")
        return buffer.getvalue()


def figure(width, height, **kwargs):
    """A new figure of width x height inches with constrained layout."""
    return GranularFigure(figsize=(width, height), layout="constrained", **kwargs)


def log_ticks(axis):
    """Decades labelled, minor ticks unlabelled (matplotlib's default crowds log axes)."""
    axis.set_major_locator(LogLocator(base=10, numticks=12))
    axis.set_minor_locator(LogLocator(base=10, subs=tuple(range(2, 10)), numticks=12))
    axis.set_minor_formatter(NullFormatter())


def mark_edges(ax, edges, orientation="horizontal", names=None, labels=True):
    """Dashed lines at the band edges [kHz], labelled outside the axis; labels of close edges are
    spread apart so they stay readable. Call after the data are drawn (the limits are final)."""
    if not edges:
        return
    names = [n for n in (names or list(edges)) if edges.get(n) is not None and math.isfinite(edges[n])]
    lo, hi = ax.get_ylim() if orientation == "horizontal" else ax.get_xlim()
    names = [n for n in names if lo <= edges[n] <= hi]
    names.sort(key=lambda n: edges[n])
    gap = 0.055 * (hi - lo)
    placed = []
    for name in names:
        value = edges[name]
        where = max(value, placed[-1] + gap) if placed else value
        placed.append(where)
        if orientation == "horizontal":
            ax.axhline(value, ls="--", lw=0.9, color="0.35", zorder=0.5)
            if labels:
                ax.annotate(EDGE_SHORT.get(name, name), (1.01, where), xycoords=("axes fraction", "data"),
                            fontsize=10, ha="left", va="center", color="0.25", annotation_clip=False)
        else:
            ax.axvline(value, ls="--", lw=0.9, color="0.35", zorder=0.5)
            if labels:
                ax.annotate(EDGE_SHORT.get(name, name), (where, 1.01), xycoords=("data", "axes fraction"),
                            fontsize=10, ha="center", va="bottom", color="0.25", annotation_clip=False)


def quasi_title(quasi, ratio=True):
    """'S1 quasiperiodic: λ = 0.5, β = 0.618034, φ = 0.4, κ = 4' from a chain description's "quasiperiodic" entry
    (every parameter that sets the chain; `ratio` False for a figure over β, the butterfly)."""
    parts = [f"$\\lambda$ = {quasi['modulation']:g}"] if "modulation" in quasi else []
    if ratio and "ratio" in quasi:
        parts.append(f"$\\beta$ = {quasi['ratio']:.6g}")
    parts.append(f"$\\varphi$ = {quasi['phase_rad']:g}" if "phase_rad" in quasi else r"$\varphi$ drawn per realization")
    if "k0_over_K" in quasi:
        parts.append(f"$\\kappa$ = {quasi['k0_over_K']:g}")
    if "k0_N_per_m" in quasi:
        parts.append(f"$k_0$ = {quasi['k0_N_per_m']:g} N/m")
    if "angle_deg" in quasi:
        parts.append(f"$\\alpha_0$ = {quasi['angle_deg']:g}°")
    kind = str(quasi.get("kind", "?"))
    return f"{kind.upper() if kind in ('s1', 's2') else kind} quasiperiodic: " + ", ".join(parts)


def chain_title(chain):
    """'A, N = 100, ξ = 0.5, q = 0.5, F0 = 10 N, seed 1 (realization 0)' from a chain description (a quasiperiodic
    chain: its kind and parameters, quasi_title)."""
    if not chain:
        return ""
    if "quasiperiodic" in chain:
        parts = [quasi_title(chain["quasiperiodic"])]
        if "N" in chain:
            parts.append(f"N = {chain['N']}")
        if "F0_N" in chain:
            parts.append(f"$F_0$ = {chain['F0_N']:g} N")
        return ", ".join(parts)
    parts = []
    kind = chain.get("disorder")
    if kind:
        parts.append({"h": "homogeneous", "A": "Anderson (A)"}.get(kind, kind))
    if "N" in chain:
        parts.append(f"N = {chain['N']}")
    if "xi" in chain:
        parts.append(rf"$\xi$ = {chain['xi']:g}")
    if "q" in chain and kind not in (None, "h", "diatomic"):
        parts.append(f"q = {chain['q']:g}")
    if "F0_N" in chain:
        parts.append(f"$F_0$ = {chain['F0_N']:g} N")
    if "seed" in chain and kind not in (None, "h", "diatomic"):
        parts.append(f"seed {chain['seed']}, realization {chain.get('realization', 0)}")
    return ", ".join(parts)


def log_derivative(t, y, step=0.1):
    """L_d = Δ ln y / Δ ln t over steps of at least `step` in ln t (as the library's criterion)."""
    import numpy as np

    t, y = np.asarray(t, float), np.asarray(y, float)
    out_t, out_s, j = [], [], 0
    for i in range(len(t)):
        if t[i] <= 0 or y[i] <= 0:
            continue
        j = max(j, i + 1)
        while j < len(t) and math.log(t[j] / t[i]) < step:
            j += 1
        if j == len(t):
            break
        if y[j] > 0:
            out_t.append(math.sqrt(t[i] * t[j]))
            out_s.append(math.log(y[j] / y[i]) / math.log(t[j] / t[i]))
    return np.array(out_t), np.array(out_s)


def wrapped_suptitle(fig, text, fontsize=11):
    """fig.suptitle with each line wrapped to the figure's width (a narrow figure, e.g. one panel,
    would clip a long title on both sides): about 0.55 em per character."""
    import textwrap

    width = max(20, int(fig.get_figwidth() * 72 / (0.55 * fontsize)) - 2)
    lines = [textwrap.fill(line, width) for line in text.split("\n")]
    return fig.suptitle("\n".join(lines), fontsize=fontsize)


def log_thinned(t, per_decade=100):
    """Indices of t (increasing, > 0) at most per_decade to a decade: the runs sample the fit window
    ~60x more densely than the rest, and drawn at full density the oscillations of P^-1 there turn
    into a solid band. Only the drawing is thinned; fits and insets use every sample."""
    import numpy as np

    t = np.asarray(t, float)
    keep, last = [], -np.inf
    step = math.log(10) / per_decade
    for i, value in enumerate(t):
        if value > 0 and math.log(value) - last >= step:
            keep.append(i)
            last = math.log(value)
    if len(t) and (not keep or keep[-1] != len(t) - 1) and t[-1] > 0:
        keep.append(len(t) - 1)  # the run's end, where the guides are anchored
    return np.array(keep, dtype=int)


def guide(ax, t0, t1, y0, slope, text, above=True):
    """A dashed guide line y0 (t/t0)^slope from t0 to t1 on log-log axes, labelled on the side away
    from the data (above an upper guide, below a lower one) at the line's outer end, so that the
    text runs along the side the line leaves free."""
    if not (t1 > t0 > 0 and y0 > 0):
        return
    y1 = y0 * (t1 / t0) ** slope
    ax.plot([t0, t1], [y0, y1], ls="--", lw=1.0, color="0.2")
    at_end = slope >= 0 if above else slope <= 0  # the higher end of an upper guide, the lower of a lower
    point = (t1, y1) if at_end else (t0, y0)
    ax.annotate(text, point, fontsize=10, ha="right" if at_end else "left", va="bottom" if above else "top",
                color="0.2", xytext=(0, 3 if above else -3), textcoords="offset points")


def guides(ax, curves, slopes, fit=None):
    """Guide slopes over the late part of the run (the fit window when known), anchored on the
    curves there: the first slope above them all, the second below them all. The y range grows by
    a tenth of its decades on each side so that the labels stay inside the axes."""
    import numpy as np

    t_end = max(t[-1] for t, _, _ in curves)
    t_start = min(fit[0], t_end / 3) if fit else t_end / 10
    values = [np.interp(math.log(t_start), np.log(t), y) for t, y, _ in curves]
    top, bottom = max(values), min(values)
    guide(ax, t_start, t_end, top * 2.5, slopes[0], f"slope {slopes[0]:g}".replace("-", "−"))
    if len(slopes) > 1:
        guide(ax, t_start, t_end, bottom / 2.5, slopes[1], f"slope {slopes[1]:g}".replace("-", "−"), above=False)
    lo, hi = ax.get_ylim()
    if lo > 0 and hi > lo:
        pad = (hi / lo) ** 0.1
        ax.set_ylim(lo / (pad if len(slopes) > 1 else 1), hi * pad)


def inset_log_derivative(ax, curves, where, fit=None, ylim=None):
    """The log derivative L_d(t) of each curve in an inset (the paper's insets). curves: (t [s], y,
    colour) triples; where: the inset's [x0, y0, width, height] in axes fractions; fit: (t0, t1) [s]
    shaded; ylim: the inset's L_d range."""
    inset = ax.inset_axes(where)
    for t, y, colour in curves:
        lt, ls = log_derivative(t, y)
        if len(lt):
            inset.semilogx(lt, ls, color=colour, lw=1.0)
    if fit:
        inset.axvspan(fit[0], fit[1], color="0.85", zorder=0)
    if ylim:
        inset.set_ylim(*ylim)
    inset.set_xlabel("t [s]", fontsize=8, labelpad=1)
    inset.set_ylabel(r"$L_d$", fontsize=9, labelpad=1)
    inset.tick_params(labelsize=7, pad=1)
    return inset
