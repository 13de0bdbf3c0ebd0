"""python3 -m granular.plot <kind> FILE... [-o out.png]: the figures of granular.plot from the
files the command-line tools write. `python3 -m granular.plot <kind> --help` describes each kind."""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")


def _pair(text):
    """'a:b' (or 'a,b') -> (a, b) floats."""
    try:
        a, b = text.replace(",", ":").split(":")
        return float(a), float(b)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected START:STOP (or START,STOP), got {text!r}") from None


def _default_output(path, suffix=""):
    return os.path.splitext(os.fspath(path))[0] + suffix + ".png"


def parser(prog=None):
    # the whole docstring (argparse refills it): its first line alone stops mid-sentence
    p = argparse.ArgumentParser(prog=prog or "python3 -m granular.plot", description=__doc__)
    sub = p.add_subparsers(dest="kind", required=True, metavar="KIND")

    def kind(name, help_text):
        q = sub.add_parser(name, help=help_text, description=help_text)
        q.add_argument("-o", "--output", help="PNG (or PDF, SVG) to write; default: the input name with .png")
        q.add_argument("--dpi", type=float, help="resolution of a PNG [dots per inch] (default: matplotlib's, 100)")
        return q

    q = kind("ipr-map", "mean IPR over (xi, mode number), one panel per q, from an ipr-map CSV (paper Fig. 4)")
    q.add_argument("csv", nargs="?", default="ipr-map.csv")
    q.add_argument("--log-color", action="store_true", help="IPR on a logarithmic colour scale")
    q.add_argument("--no-band-edges", action="store_true", help="do not draw where the mean f crosses f1 and fb1")
    q = kind("ipr-averaging", "IPR against frequency averaged by mode number beside in frequency bins, for one (q, xi) "
                              "cell, from an ipr-map CSV and its --bin-khz CSV")
    q.add_argument("mode_csv", help="ipr-map CSV averaged by mode number")
    q.add_argument("binned_csv", help="ipr-map --bin-khz CSV of the same ensemble")
    q.add_argument("--q", type=float, help="the cell's q (default: the map's only one)")
    q.add_argument("--xi", type=float, help="the cell's xi (default: the map's only one)")
    q.add_argument("--gap", type=_pair, metavar="LO,HI", help="a band gap to shade [kHz], e.g. 11.95,33.81")
    q = kind("spectrum", "f versus mode number and the IPR beside it, band edges dashed, from a spectrum CSV")
    q.add_argument("csv", nargs="?", default="spectrum.csv")
    q = kind("correlations", "rho(d) with its spread and the infinite-chain formula, from correlations CSVs")
    q.add_argument("csv", nargs="*", default=["correlations.csv"])
    q.add_argument("--labels", help="comma list, one per CSV")
    q = kind("partial-spectrum-ipr", "IPR versus f - f0 of the modes nearest f0, from spectrum --near CSVs")
    q.add_argument("csv", nargs="+")
    q.add_argument("--near", type=float, help="f0 [kHz] (default: from the JSON beside the first CSV)")
    q.add_argument("--labels", help="comma list, one per CSV")
    q = kind("localization", "localization length l(f) beside the IPR of finite chains, from localization CSVs")
    q.add_argument("csv", nargs="?", default="localization.csv", help="the localization tool's CSV")
    q.add_argument("--spectrum", nargs="+", default=[], metavar="CSV", help="spectrum CSVs of finite chains")
    q.add_argument("--finite-N", type=int, help="their length (default: from the first spectrum)")
    q = kind("map", "energy map E_n(t) beside the spectral density, from spreading --energy-map/--spectrum files")
    q.add_argument("map", help="HDF5 file of spreading --energy-map")
    q.add_argument("spectrum", nargs="?", help="CSV of spreading --spectrum (optional)")
    q.add_argument("--t-window", type=_pair, metavar="T0:T1", help="time window [s], e.g. 0:2e-3")
    q.add_argument("--sites", type=_pair, metavar="N0:N1", help="bead window (from 1), e.g. 700:900")
    q.add_argument("--floor", type=float, default=-12, help="lowest log10 relative energy shown (default -12)")
    q.add_argument("--json", help="the run's JSON, for the title and band edges (default: the JSON in the map's "
                   "folder whose command line names the map)")
    q = kind("forces", "force versus t at chosen beads beside the force profile at T (spreading --forces-at --profile)")
    q.add_argument("forces", help="PREFIX-forces.csv")
    q.add_argument("profile", nargs="?", help="PREFIX-profile.csv (optional)")
    q = kind("lyapunov", "lambda_i(t) beside GALI_k(t) and SALI(t), log axes, from spreading --lyapunov-vectors")
    q.add_argument("csv", help="PREFIX-lyapunov.csv")
    q = kind("covariant", "covariant Lyapunov vectors along the chain (CLV index x bead) beside their participation "
                          "against growth rate, from spreading --covariant-vectors")
    q.add_argument("h5", help="PREFIX-clv.h5")
    q.add_argument("--sample", type=int, default=-1, help="index of the CLVs' sample shown (default -1: the last, T)")
    q = kind("spread", "m2(t) and P^-1(t), log-log, with L_d insets, from spreading CSVs")
    q.add_argument("csv", nargs="+")
    q.add_argument("--labels", help="comma list, one per CSV")
    q = kind("mode-kicks", "m2 about the centroid and P^-1 against t from linear modes beside a single-site kick, from "
                           "spreading CSVs (--ic mode, --ic velocity)")
    q.add_argument("csv", nargs="+")
    q.add_argument("--labels", help="comma list, one per CSV (default: the mode or the kick, from the JSONs)")
    q = kind("exponents", "the paper's transport panels per chain kind and F0, from an exponents run")
    q.add_argument("prefix", nargs="?", default="exponents", help="the exponents --output prefix (default exponents)")
    q.add_argument("--kick", action="append", help="displacement and/or velocity (default: every kick in the run)")
    q.add_argument("--profiles", action="store_true", help="also draw PREFIX-profiles.png")
    q.add_argument("--all", action="store_true",
                   help="also PREFIX-profiles.png, PREFIX-centres.png and (after --compare-paper) PREFIX-paper.png")
    q = kind("centres", "m2 about the kicked site beside m2 about the centroid for one chain kind, from an exponents run")
    q.add_argument("prefix", nargs="?", default="exponents")
    q.add_argument("--chain", default="A", help="chain kind: h, A, RDM1 or RDM2 (default A)")
    q = kind("paper", "our gamma (both centres) beside the paper's Table I, from exponents --compare-paper")
    q.add_argument("prefix", nargs="?", default="exponents", help="the exponents prefix, or its PREFIX-paper.csv")
    q = kind("study-comparison", "gamma and eta of an exponents run beside those of a reference run (e.g. T = 100 ms "
                                 "beside 10 ms)")
    q.add_argument("prefix", help="the exponents prefix (or its PREFIX.csv)")
    q.add_argument("reference", help="the reference run's exponents prefix (or its PREFIX.csv)")
    q = kind("profiles", "averaged energy profiles E_n(T), from an exponents run")
    q.add_argument("prefix", nargs="?", default="exponents")
    q.add_argument("--decades", type=float, default=15, help="decades shown below the largest energy")
    q = kind("spectra", "g(nu) of the displacements beside that of the velocities, from pairs of spreading --spectrum CSVs")
    q.add_argument("csv", nargs="+", help="pairs: displacement spectrum CSV, velocity spectrum CSV (--spectrum-of velocity)")
    q.add_argument("--titles", help="semicolon list, one per pair")
    q.add_argument("--fmax", type=float, default=60, help="highest frequency shown [kHz] (default 60)")
    q = kind("butterfly", "the Hofstadter butterfly coloured by IPR beside the box-counting dimension, from a "
                          "butterfly CSV")
    q.add_argument("csv", nargs="?", default="butterfly.csv")
    q = kind("dynamical-butterfly", "the butterfly from the dynamics: power against frequency and beta, from a "
                                    "butterfly --from dynamics CSV, the eigenfrequencies overlaid")
    q.add_argument("csv")
    q.add_argument("--eigen", help="the butterfly tool's eigen CSV of the same chain and ratios (overlaid)")
    q.add_argument("--ratio", type=float, help="the beta of the right panel (default 0.618 when in range)")
    q.add_argument("--floor", type=float, default=1e-6, help="lowest power shown (default 1e-6)")
    q.add_argument("--fmax", type=float, help="top of the frequency axis [kHz]")
    q.add_argument("--zoom", type=_pair, metavar="F0:F1", help="frequency range of the right panel [kHz]")
    q = kind("breathers", "a breather branch: energy against frequency with stability and the linear modes, "
                          "profiles, Floquet multipliers, from a breathers CSV (its .json and .h5 beside it)")
    q.add_argument("csv", nargs="?", default="breathers.csv")
    q.add_argument("--point", type=int, default=-1, help="the point whose multipliers are drawn: 0 = first, "
                                                         "-1 = last (default)")
    q = kind("crystal", "a 2D crystal's modes: IPR against frequency and one mode's displacements on the packing, "
                        "from a crystal CSV (PREFIX-modes.csv beside it from --vectors)")
    q.add_argument("csv", nargs="?", default="crystal.csv")
    q.add_argument("--mode", type=int, help="the mode drawn, from 1 (default: the most localized)")
    q = kind("crystal-ipr-map", "the 2D IPR map: mean IPR and <r> against frequency per disorder width, from a "
                                "crystal-ipr-map CSV")
    q.add_argument("csv", nargs="?", default="crystal-ipr-map.csv")
    q = kind("klein-gordon", "m2(t), P(t) and the finite-time mLE Lambda(t) of the disordered Klein-Gordon chain, "
                             "log-log, from a klein-gordon CSV")
    q.add_argument("csv", nargs="?", default="klein-gordon.csv")
    q = kind("cost", "integrators' cost-accuracy curves, from dynamics_benchmark --benchmark_out JSON")
    q.add_argument("bench")
    return p


def main(argv=None, prog=None):
    args = parser(prog).parse_args(argv)
    from granular import plot

    def save(fig, out):
        fig.savefig(out, dpi=args.dpi)
        print(f"wrote {out}")

    labels = getattr(args, "labels", None)
    labels = labels.split(",") if labels else None
    try:
        if args.kind == "ipr-map":
            save(plot.ipr_map(args.csv, band_edges=not args.no_band_edges, log_color=args.log_color),
                 args.output or _default_output(args.csv))
        elif args.kind == "ipr-averaging":
            save(plot.ipr_averaging(args.mode_csv, args.binned_csv, q=args.q, xi=args.xi, gap_khz=args.gap),
                 args.output or _default_output(args.mode_csv, "-averaging"))
        elif args.kind == "spectrum":
            save(plot.spectrum(args.csv), args.output or _default_output(args.csv))
        elif args.kind == "correlations":
            save(plot.correlations(args.csv, labels), args.output or _default_output(args.csv[0]))
        elif args.kind == "partial-spectrum-ipr":
            save(plot.partial_spectrum_ipr(args.csv, near=args.near, labels=labels),
                 args.output or _default_output(args.csv[0]))
        elif args.kind == "localization":
            save(plot.localization(args.csv, args.spectrum, args.finite_N), args.output or _default_output(args.csv))
        elif args.kind == "map":
            save(plot.energy_map(args.map, args.spectrum, t_window=args.t_window, site_window=args.sites,
                                 floor=args.floor, metadata=args.json), args.output or _default_output(args.map))
        elif args.kind == "forces":
            save(plot.forces(args.forces, args.profile), args.output or _default_output(args.forces))
        elif args.kind == "lyapunov":
            save(plot.lyapunov(args.csv), args.output or _default_output(args.csv))
        elif args.kind == "covariant":
            save(plot.covariant(args.h5, sample=args.sample), args.output or _default_output(args.h5))
        elif args.kind == "spread":
            save(plot.spreading(args.csv, labels), args.output or _default_output(args.csv[0]))
        elif args.kind == "mode-kicks":
            save(plot.mode_kicks(args.csv, labels), args.output or _default_output(args.csv[0]))
        elif args.kind == "exponents":
            import csv

            kicks = args.kick
            if not kicks:
                with open(args.prefix + "-curves.csv", newline="") as f:
                    kicks = list(dict.fromkeys(r["ic"] for r in csv.DictReader(f)))
            for kick in kicks:
                out = args.output if args.output and len(kicks) == 1 else f"{args.prefix}-spreading-{kick}.png"
                save(plot.exponents(args.prefix, kick), out)
            if args.profiles or args.all:
                save(plot.profiles(args.prefix), f"{args.prefix}-profiles.png")
            if args.all:
                save(plot.centres(args.prefix), f"{args.prefix}-centres.png")
                if os.path.exists(args.prefix + "-paper.csv"):
                    save(plot.paper_comparison(args.prefix), f"{args.prefix}-paper.png")
        elif args.kind == "centres":
            save(plot.centres(args.prefix, chain=args.chain), args.output or f"{args.prefix}-centres.png")
        elif args.kind == "paper":
            out = args.output or (_default_output(args.prefix) if args.prefix.endswith(".csv")
                                  else f"{args.prefix}-paper.png")
            save(plot.paper_comparison(args.prefix), out)
        elif args.kind == "study-comparison":
            base = args.prefix[:-4] if args.prefix.endswith(".csv") else args.prefix
            save(plot.study_comparison(args.prefix, args.reference), args.output or f"{base}-comparison.png")
        elif args.kind == "spectra":
            if len(args.csv) % 2:
                raise ValueError("spectra: give pairs of files: displacement spectrum, velocity spectrum")
            pairs = [args.csv[i:i + 2] for i in range(0, len(args.csv), 2)]
            titles = args.titles.split(";") if args.titles else None
            save(plot.spectral_densities(pairs, titles, fmax_khz=args.fmax), args.output or _default_output(args.csv[0]))
        elif args.kind == "profiles":
            save(plot.profiles(args.prefix, decades=args.decades), args.output or f"{args.prefix}-profiles.png")
        elif args.kind == "butterfly":
            save(plot.butterfly(args.csv), args.output or _default_output(args.csv))
        elif args.kind == "dynamical-butterfly":
            fig = plot.dynamical_butterfly(args.csv, args.eigen, ratio=args.ratio, floor=args.floor,
                                           fmax_khz=args.fmax, zoom_khz=args.zoom)
            save(fig, args.output or _default_output(args.csv))
        elif args.kind == "breathers":
            save(plot.breather_branch(args.csv, args.point), args.output or _default_output(args.csv))
        elif args.kind == "crystal":
            save(plot.crystal(args.csv, args.mode), args.output or _default_output(args.csv))
        elif args.kind == "crystal-ipr-map":
            save(plot.crystal_ipr_map(args.csv), args.output or _default_output(args.csv))
        elif args.kind == "klein-gordon":
            save(plot.klein_gordon(args.csv), args.output or _default_output(args.csv))
        elif args.kind == "cost":
            save(plot.cost(args.bench), args.output or _default_output(args.bench))
    except (OSError, ValueError, KeyError, IndexError) as error:  # a missing or wrong file: one line, exit code 2
        name = prog or "granular.plot"
        print(f"{name}: error: {error}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main())
