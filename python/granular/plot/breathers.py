"""The breather figure (docs/breathers.md): a branch's energy against its frequency with stability marked and the
linear modes drawn, three profiles as insets, and one point's Floquet multipliers on the unit circle."""
import os

import numpy as np

from . import _io
from ._style import chain_title, figure, style, wrapped_suptitle


def _branch_data(source):
    """(freq_khz, energy [J], stable, trusted, profiles (points x N) [m], multipliers (points x 2N), linear_khz,
    metadata) from a granular.Breathers or the breathers tool's CSV (its JSON and PREFIX.h5 beside it). trusted:
    the points' verdict_trusted (False where the verdict is the discretized map's, not the orbit's: F0 = 0); all
    True for a CSV from before that column."""
    if not _io.is_path(source):
        return (np.asarray(source.freq_khz), np.asarray(source.energy), np.asarray(source.stable, bool),
                np.asarray(source.verdict_trusted, bool), np.asarray(source.profiles),
                np.asarray(source.multipliers), np.asarray(source.linear_khz), source.metadata)
    columns = _io.read_csv(source)
    meta = _io.read_json_beside(source)
    h5 = meta.get("profiles") or os.path.splitext(os.fspath(source))[0] + ".h5"
    if not os.path.isabs(h5) and not os.path.exists(h5):
        h5 = os.path.join(os.path.dirname(os.fspath(source)), os.path.basename(h5))
    import h5py  # only for files; a granular result needs no HDF5 here

    with h5py.File(h5, "r") as f:
        profiles = np.array(f["x0"]).reshape(len(columns["freq_khz"]), -1)
        multipliers = np.array(f["multipliers_real"]) + 1j * np.array(f["multipliers_imag"])
        linear = np.array(f["linear_khz"])
    trusted = columns.get("verdict_trusted", np.ones(len(columns["freq_khz"]))).astype(bool)
    return (columns["freq_khz"], columns["energy_J"], columns["stable"].astype(bool), trusted, profiles,
            multipliers.reshape(len(profiles), -1), linear, meta)


#: The branch panel's legend entry for the points whose Floquet verdict is untrusted (verdict_trusted False).
UNTRUSTED_LABEL = "verdict untrusted at F0 = 0: the discretized map's"


def _gaps(linear):
    """The gaps of the linear frequencies [kHz] (ascending), as the library tells them (inside_linear_band): a
    spacing more than 3 times both neighbouring spacings; and the range above the highest mode."""
    f = np.asarray(linear, float)
    out = []
    for k in range(1, len(f)):
        before = f[k - 1] - f[k - 2] if k >= 2 else 0.0
        after = f[k + 1] - f[k] if k + 1 < len(f) else 0.0
        if f[k] - f[k - 1] > 3 * max(before, after):
            out.append((f[k - 1], f[k]))
    if len(f):
        out.append((f[-1], np.inf))
    return out


def breather_branch(source, point=-1):
    """Top left: energy above the static state [µJ] against the breather frequency, filled where the orbit is stable
    (every Floquet multiplier on the unit circle), open where not, with the chain's linear mode frequencies as thin
    lines and the band gaps shaded; points whose verdict is untrusted (verdict_trusted False: at F0 = 0 the
    verdict is the discretized map's, not the orbit's) are ringed by a grey square with their own legend entry
    (UNTRUSTED_LABEL), and the multiplier panel's title says so. Below it: the turning-point profiles x0 of the
    first, middle and last points. Right: the Floquet multipliers of point `point` (default: the last) in the
    complex plane with the unit circle. Axes, in order: branch, multipliers, then the profiles.
    source: a granular.Breathers or the breathers tool's CSV (PREFIX.json and PREFIX.h5 beside it)."""
    freq, energy, stable, trusted, profiles, multipliers, linear, meta = _branch_data(source)
    if len(freq) == 0:
        raise ValueError("the branch has no points to draw")
    point = range(len(freq))[point]  # IndexError names a point the branch does not have
    with style():
        fig = figure(12, 6.4)
        grid = fig.add_gridspec(2, 4, height_ratios=[2, 1], width_ratios=[1, 1, 1, 1.5])
        left, right = fig.add_subplot(grid[0, :3]), fig.add_subplot(grid[:, 3])
        micro = energy * 1e6  # µJ: a J axis of 1e-5-sized values wore an offset label
        left.plot(freq, micro, "-", color="0.6", lw=0.8, zorder=1)
        left.plot(freq[stable], micro[stable], "o", ms=4, color="C0", label="stable", zorder=2)
        left.plot(freq[~stable], micro[~stable], "o", ms=4, mfc="none", color="C3", label="unstable", zorder=2)
        if not trusted.all():  # drawn only then: a trusted branch's figure is unchanged
            left.plot(freq[~trusted], micro[~trusted], "s", ms=9, mfc="none", mec="0.35", mew=0.9, ls="none",
                      label=UNTRUSTED_LABEL, zorder=3)
        lo, hi = np.min(freq), np.max(freq)
        pad = max(0.15 * (hi - lo), 0.02 * max(abs(hi), 1e-9))
        left.set_xlim(lo - pad, hi + pad)
        for f in linear[(linear >= lo - pad) & (linear <= hi + pad)]:
            left.axvline(f, color="0.75", lw=0.6, zorder=0)
        left.plot([], [], color="0.75", lw=0.6, label="linear modes")
        for a, b in _gaps(linear):  # the band gaps (and above the spectrum) the branch lies in, shaded
            if b > lo - pad and a < hi + pad:
                left.axvspan(max(a, lo - pad), min(b, hi + pad), color="C2", alpha=0.08, lw=0, zorder=0)
        if any(b > lo - pad and a < hi + pad for a, b in _gaps(linear)):
            left.fill_between([], [], color="C2", alpha=0.15, label="gap (no linear mode)")
        left.set_yscale("log" if np.all(energy > 0) and np.max(energy) > 20 * np.min(energy) else "linear")
        left.set_xlabel("breather frequency f$_b$ [kHz]")
        left.set_ylabel(r"energy above the static state [$\mu$J]")
        left.legend(loc="best", fontsize=9)
        for k, j in enumerate(dict.fromkeys([0, len(freq) // 2, len(freq) - 1])):
            profile = fig.add_subplot(grid[1, k])
            profile.bar(np.arange(1, profiles.shape[1] + 1), profiles[j] * 1e6, width=1.0,
                        color="C0" if stable[j] else "C3")
            profile.axhline(0, color="0.4", lw=0.5)
            profile.set_title(f"profile at {freq[j]:.5g} kHz", fontsize=9)
            profile.set_xlabel("bead")
            profile.set_ylabel(r"$x_0$ [$\mu$m]" if k == 0 else "")
        theta = np.linspace(0, 2 * np.pi, 400)
        right.plot(np.cos(theta), np.sin(theta), color="0.5", lw=0.8)
        mu = multipliers[point]
        right.plot(mu.real, mu.imag, "x" if stable[point] else "o", color="C0" if stable[point] else "C3", ms=5)
        reach = max(1.15, 1.05 * float(np.max(np.abs(mu))))
        right.set_xlim(-reach, reach)
        right.set_ylim(-reach, reach)
        right.set_aspect("equal")
        right.set_xlabel(r"Re $\mu$")
        right.set_ylabel(r"Im $\mu$")
        right.set_title(f"Floquet multipliers at {freq[point]:.5g} kHz ({'stable' if stable[point] else 'unstable'})"
                        + ("" if trusted[point] else "\nverdict untrusted: the discretized map's"), fontsize=10)
        wrapped_suptitle(fig, "breathers: " + chain_title(meta.get("chain", {})))
    return fig
