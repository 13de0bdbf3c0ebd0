"""Figures of granular's results, as a physicist would show them in a talk.

Every function takes a result (what granular.spectrum, ipr_map, spreading, ... return) or the
files the command-line tools write (CSV with its JSON beside it, HDF5 energy maps), and returns a
matplotlib Figure: units on every axis, band edges marked where they matter, sizes that read on a
slide. Save with ``fig.savefig("x.png")``; in a notebook the returned figure is shown.

From a shell, ``python3 -m granular.plot <kind> FILE... [-o out.png]`` draws the same figures
(``python3 -m granular.plot --help`` lists the kinds).

One module per subject, every function imported here (granular.plot.X); _style holds the shared
look, _io the reading of results and files:

  modes: the linear modes
    ipr_map(result_or_csv)                     mean IPR over (xi, mode), one panel per q (paper Fig. 4)
    spectrum(result_or_csv)                    f versus mode and the IPR beside it (paper Fig. 3)
    partial_spectrum_ipr(spectra)              IPR versus f - f0 of the modes nearest f0, several N
    ipr_averaging(by_mode, binned)             IPR against f by mode number beside in frequency bins
  disorder: what the disorder does (bead correlations, localization length)
    correlations(results_or_csvs)              rho(d) with its spread and the infinite-chain formula
    localization(scan_or_csv, spectra)         localization length l(f) beside the IPR of finite chains
  dynamics: runs after a kick
    energy_map(run_or_h5, spectral_density)    E_n(t) beside g(nu), zoomable in t and n
    forces(run_or_csv, profile)                force versus t at chosen beads, force profile at T
    spreading(runs_or_csvs)                    m2(t) and P^-1(t), log-log, with L_d insets
    lyapunov(run_or_csv)                       lambda_i(t) beside GALI_k(t) and SALI(t), log axes
    covariant(run_or_h5, sample)               CLVs along the chain (index x bead), participation vs growth rate
    mode_kicks(runs_or_csvs)                   m2(t) and P^-1(t) from linear modes beside a site kick
    spectral_densities(pairs, titles)          g(nu) of the displacements beside that of the velocities
    cost(benchmark_json)                       integrators' cost-accuracy curves
  breathers: time-periodic localized orbits
    breather_branch(result_or_csv, point)      energy vs f_b, stability, linear modes, profiles, multipliers
  klein_gordon: the disordered Klein-Gordon chain
    klein_gordon(result_or_csv)                m2(t), P(t) and the finite-time mLE Lambda(t), log-log, with guide slopes
  crystals: two-dimensional crystals
    crystal(result_or_csv, mode)               IPR against f, <r>; one mode's displacements as arrows on the packing
    crystal_ipr_map(result)                    mean IPR and <r> against f, one curve per disorder width
  quasiperiodic: quasiperiodic chains
    butterfly(result_or_csv)                   the Hofstadter butterfly coloured by IPR, its box-counting dimension
    dynamical_butterfly(result_or_csv, eigen)  the butterfly from the dynamics: power vs f and beta, modes overlaid
  transport_exponents: the paper's transport study (an exponents run)
    exponents(table_or_prefix, kick)           the paper's transport panels per chain kind and F0
    centres(table_or_prefix, chain)            m2 about the kicked site beside m2 about the centroid
    paper_comparison(table_or_prefix)          our gamma (both centres) beside the paper's Table I
    profiles(table_or_prefix)                  averaged energy profiles E_n(T)
    study_comparison(table, reference)         gamma and eta of two runs side by side (e.g. 100 ms, 10 ms)
"""
from .breathers import breather_branch
from .crystals import crystal, crystal_ipr_map
from .disorder import correlations, localization
from .klein_gordon import klein_gordon
from .dynamics import cost, covariant, energy_map, forces, lyapunov, mode_kicks, spectral_densities, spreading
from .modes import ipr_averaging, ipr_map, partial_spectrum_ipr, spectrum
from .quasiperiodic import butterfly, dynamical_butterfly
from .transport_exponents import centres, exponents, paper_comparison, profiles, study_comparison

__all__ = ["breather_branch", "crystal", "crystal_ipr_map", "klein_gordon", "ipr_map", "spectrum", "partial_spectrum_ipr", "ipr_averaging", "correlations", "localization", "energy_map",
           "forces", "spreading", "lyapunov", "covariant", "mode_kicks", "spectral_densities", "cost", "exponents", "centres",
           "paper_comparison", "profiles", "study_comparison", "butterfly",
           "dynamical_butterfly"]
