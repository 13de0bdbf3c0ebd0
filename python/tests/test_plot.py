"""granular.plot: every figure from results and from the tools' files, every axis labelled (with
its unit where it has one), and the command-line wrappers, including the README's main job."""
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

import granular as gr  # noqa: E402
import granular.plot as gp  # noqa: E402
from conftest import BUILD, SOURCE  # noqa: E402

DIMENSIONLESS = ("IPR", "P^{-1}", "rho", "L_d", "mode number", "bead", "g(", "log_{10}", "error", "distance", "size ratio", "exponent",
                 "modes per bin", "P$^{-1}$", r"$\gamma$", r"$\eta$", r"$\mu$", "alignment index", "CLV index")


def check_axes(fig):
    """Every main axes (not colorbars, not insets) has both labels; dimensional ones carry [unit]."""
    assert isinstance(fig, Figure)
    main = [ax for ax in fig.axes if ax.get_visible() and ax.get_label() != "<colorbar>" and ax.get_xlabel()
            or ax.get_ylabel()]
    assert main
    for ax in main:
        for label in (ax.get_xlabel(), ax.get_ylabel()):
            if not label:
                continue
            assert "[" in label or any(word in label for word in DIMENSIONLESS), label
            assert "_N" not in label and "F0_N" not in label, label  # no raw JSON keys
    fig.savefig(os.devnull, format="png")


@pytest.fixture(scope="module")
def run():
    return gr.spreading(gr.anderson(N=301, F0=10), T=2e-3, fit=(5e-4, 2e-3), energy_map=True, map_samples=60,
                        spectral_density=True, spectrum_samples=200, forces_at=[140, 151], force_samples=100)


def test_linear_figures_from_results():
    c = gr.anderson(N=60)
    check_axes(gp.spectrum(gr.spectrum(c)))
    check_axes(gp.spectrum(gr.spectrum(c, near=15, count=6, method="bisect")))
    check_axes(gp.ipr_map(gr.ipr_map(xi="0.3:0.6:0.1", q=(0.2, 0.8), N=30, realizations=3)))
    check_axes(gp.ipr_map(gr.ipr_map(xi="0.3:0.6:0.1", q=0.5, N=30, realizations=3), log_color=True))
    # each panel names its chain and what it shows, with the scale of a quantity that has no unit
    titles = [ax.get_title() for ax in gp.ipr_map(gr.ipr_map(xi="0.3:0.6:0.1", q=(0.2, 0.8), N=30,
                                                              realizations=3)).axes if ax.get_title()]
    assert titles == [f"Anderson (A), q = {q}\n" r"mean IPR $\langle P^{-1}\rangle$ (no unit: 1/N to 1)"
                      for q in (0.2, 0.8)], titles
    check_axes(gp.correlations([gr.correlations(disorder="RDM2", q=0.8), gr.correlations(q=0.5)]))
    check_axes(gp.partial_spectrum_ipr([gr.spectrum(gr.anderson(N=n), near=15, count=5, method="bisect")
                                        for n in (100, 1000)]))
    check_axes(gp.localization(gr.localization(N=2000, f="0:40:0.5"), [gr.spectrum(gr.anderson(N=200))]))
    with pytest.raises(ValueError, match="partial"):
        gp.ipr_map(gr.ipr_map(xi=0.5, q=0.5, N=100, realizations=2, near=15, count=2, method="bisect"))
    by_mode = gr.ipr_map(disorder="RDM2", xi=0.5, q=(0.5, 0.8), N=30, realizations=3)
    binned = gr.ipr_map(disorder="RDM2", xi=0.5, q=(0.5, 0.8), N=30, realizations=3, bin_khz=1)
    averaging = gp.ipr_averaging(by_mode, binned, q=0.8, gap_khz=(12, 34))
    check_axes(averaging)
    assert averaging.axes[0].get_title() == "RDM2, q = 0.8, ξ = 0.5: the two averagings of ipr-map"
    with pytest.raises(ValueError, match="several values of q"):
        gp.ipr_averaging(by_mode, binned)
    with pytest.raises(ValueError, match="first"):
        gp.ipr_averaging(binned, by_mode, q=0.8)


def test_spectrum_figure_marks_the_band_edges():
    fig = gp.spectrum(gr.spectrum(gr.anderson(N=100, xi=0.5, F0=10)))
    texts = [t.get_text() for ax in fig.axes for t in ax.texts]
    assert {"$f_1$", "$f_{b1}$", "$f_{b2}$"} <= set(texts)
    edges = gr.band_edges(xi=0.5, F0=10)
    lines = [ln.get_ydata()[0] for ln in fig.axes[1].lines if ln.get_linestyle() == "--"]
    assert any(abs(y - edges.fb1) < 1e-12 for y in lines)


def test_dynamics_figures_from_results(run):
    check_axes(gp.energy_map(run))
    zoom = gp.energy_map(run, t_window=(0, 1e-3), site_window=(100, 200))
    check_axes(zoom)
    mesh = zoom.axes[0].collections[0]
    assert mesh.get_coordinates().shape[1] == 102  # beads 100..200: 101 cells
    with pytest.raises(ValueError, match="select no part"):
        gp.energy_map(run, site_window=(5000, 6000))
    check_axes(gp.forces(run))
    pair = gp.spreading([run, gr.spreading(gr.homogeneous(N=301), T=2e-3, fit=(5e-4, 2e-3))])
    check_axes(pair)
    assert pair._suptitle.get_text().startswith("energy spreading: N = 301"), pair._suptitle  # it had no title
    ensemble = gr.transport(N=201, realizations=2, T=1e-3, fit=(2e-4, 1e-3))
    one = gp.spreading(ensemble)
    check_axes(one)
    assert one._suptitle.get_text().startswith("energy spreading: Anderson (A), N = 201"), one._suptitle
    table = gr.exponent_table(chains=["h", "A"], F0=[10, 0], ic=["velocity"], N=151, realizations=2, T=1e-3,
                              fit=(2e-4, 1e-3), samples=60, profile_F0=[10], profile_realizations=2)
    check_axes(gp.exponents(table, "velocity"))
    comparison = gp.study_comparison(table, table)
    check_axes(comparison)
    assert [t.get_text() for t in comparison.axes[0].get_legend().get_texts()] == ["1 ms (fit 0.2–1 ms, 2 real.)"] * 2
    assert [t.get_text() for t in comparison.axes[1].get_xticklabels()] == ["velo. 10 N A", "velo. 0 N A"]
    prof = gp.profiles(table)
    check_axes(prof)
    low, high = prof.axes[0].get_ylim()
    assert low > 1e-30 and high / low == pytest.approx(3e15)  # no floor at 1e-30: 15 decades below the top
    with pytest.raises(ValueError, match="no 'displacement' kick"):
        gp.exponents(table, "displacement")
    centres = gp.centres(table, "A")
    check_axes(centres)
    assert len(centres.axes[0].get_lines()) == 2  # m2 about the site and about the centroid
    with pytest.raises(ValueError, match="no chain 'RDM2'"):
        gp.centres(table, "RDM2")
    with pytest.raises(ValueError, match="compare_paper"):
        gp.paper_comparison(table)
    velocity = gr.spreading(gr.anderson(N=301, F0=10), T=2e-3, fit=(5e-4, 2e-3), spectral_density=True,
                            spectrum_samples=200, spectrum_of="velocity")
    check_axes(gp.spectral_densities([(run.spectral_density, velocity.spectral_density)], ["A, F0 = 10 N"]))
    with pytest.warns(RuntimeWarning, match="walls"):  # an extended mode has energy at the walls from the start
        mode = gr.spreading(gr.anderson(N=301, F0=10), T=2e-3, ic="mode", mode=20, energy=1e-7)
    kicks = gp.mode_kicks([run, mode])
    check_axes(kicks)
    legend = [t.get_text() for t in kicks.axes[0].get_legend().get_texts()]
    assert legend[0] == "single-site displacement kick" and legend[1].startswith("mode 20 (")
    with pytest.raises(ValueError, match="pairs"):
        gp.spectral_densities([(run.spectral_density,)])


def test_paper_comparison_figure():
    table = gr.exponent_table(chains=["h", "A"], F0=[10], ic=["displacement"], N=151, realizations=2, T=1e-3,
                              fit=(2e-4, 1e-3), samples=60, profile_F0=[], compare_paper=True)
    fig = gp.paper_comparison(table)
    check_axes(fig)
    ax = fig.axes[0]
    assert [t.get_text() for t in ax.get_xticklabels()] == ["h\n10 N", "A\n10 N"]
    assert ax.containers[0].lines[0].get_ydata()[0] == pytest.approx(2.0)  # the paper's h cell: gamma = 2


def cli(*args, cwd):
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(os.path.abspath(gr.__file__))))
    return subprocess.run([sys.executable, *map(str, args)], capture_output=True, text=True, cwd=cwd, env=env)


def test_lyapunov_figure_from_a_run_and_from_the_tools_csv(tools):
    """lambda_i(t) and GALI_k(t), SALI(t) on log axes, from granular.spreading(..., lyapunov_vectors=k) or from the
    spreading tool's PREFIX-lyapunov.csv (its JSON beside it gives the title), also as `python3 -m granular.plot
    lyapunov`; a run without the spectrum is a ValueError saying how to get one."""
    keywords = dict(ic="velocity", beta=0.05, mle=True, T=1e-3, fit=(2e-4, 1e-3))
    chain = gr.anderson(N=8, F0=0.01)
    run = gr.spreading(chain, lyapunov_vectors=5, **keywords)
    fig = gp.lyapunov(run)
    check_axes(fig)
    assert fig.axes[0].get_xscale() == "log" and fig.axes[1].get_yscale() == "log"
    assert len(fig.axes[1].get_lines()) == 5  # GALI_2..GALI_5 and SALI
    check_axes(gp.lyapunov(gr.spreading(chain, lyapunov_vectors=1, **keywords)))  # no index: the left panel only
    with pytest.raises(ValueError, match="lyapunov_vectors"):
        gp.lyapunov(gr.spreading(chain, **keywords))
    tools.run("spreading", "--N", "8", "--F0", "0.01", "--ic", "velocity", "--beta", "0.05", "--T", "1e-3", "--fit",
              "2e-4:1e-3", "--mle", "--lyapunov-vectors", "4", "--quiet", output="spec")
    from_file = gp.lyapunov(tools.path("spec-lyapunov.csv"))
    check_axes(from_file)
    assert "N = 8" in from_file._suptitle.get_text(), from_file._suptitle.get_text()
    done = cli("-m", "granular.plot", "lyapunov", "spec-lyapunov.csv", cwd=tools.folder)
    assert done.returncode == 0, done.stderr
    assert (tools.folder / "spec-lyapunov.png").stat().st_size > 10000


def test_covariant_figure_from_a_run_and_from_the_tools_h5(tools):
    """The CLVs' localization map (CLV index x bead) beside participation against growth rate, from
    granular.spreading(..., covariant_vectors=k) or the spreading tool's PREFIX-clv.h5, also as `python3 -m
    granular.plot covariant`, which writes a PNG; a run without the CLVs is a ValueError saying how to get them."""
    pytest.importorskip("h5py")
    keywords = dict(ic="velocity", beta=0.05, mle=True, T=1e-3, fit=(2e-4, 1e-3))
    chain = gr.anderson(N=8, F0=0.01)
    fig = gp.covariant(gr.spreading(chain, covariant_vectors=16, **keywords))
    check_axes(fig)
    assert fig.axes[0].get_images()[0].get_array().shape == (16, 8)
    with pytest.raises(ValueError, match="covariant_vectors"):
        gp.covariant(gr.spreading(chain, **keywords))
    tools.run("spreading", "--N", "8", "--F0", "0.01", "--ic", "velocity", "--beta", "0.05", "--T", "1e-3", "--fit",
              "2e-4:1e-3", "--mle", "--covariant-vectors", "6", "--quiet", output="clv")
    from_file = gp.covariant(tools.path("clv-clv.h5"), sample=0)
    check_axes(from_file)
    assert "N = 8" in from_file._suptitle.get_text(), from_file._suptitle.get_text()
    done = cli("-m", "granular.plot", "covariant", "clv-clv.h5", cwd=tools.folder)
    assert done.returncode == 0, done.stderr
    assert (tools.folder / "clv-clv.png").stat().st_size > 10000


def test_command_line_figures_from_the_tools_files(tools):
    folder = tools.folder
    tools.run("ipr-map", "--xi", "0.2:0.5:0.1", "--q", "0.5", "--N", "30", "--realizations", "3", "--quiet",
              output="ipr-map.csv")
    tools.run("ipr-map", "--xi", "0.2:0.5:0.1", "--q", "0.5", "--N", "30", "--realizations", "3", "--bin-khz", "1",
              "--quiet", output="ipr-bin.csv")
    tools.run("spectrum", "--N", "50", output="spectrum.csv")
    tools.run("correlations", "--q", "0.5", output="correlations.csv")
    tools.run("spreading", "--N", "201", "--T", "1e-3", "--fit", "2e-4:1e-3", "--energy-map", folder / "map.h5",
              "--map-samples", "40", "--spectrum", folder / "g.csv", "--spectrum-samples", "100", "--forces-at",
              "90,101", "--profile", output="one")
    tools.run("exponents", "--chains", "h,A", "--F0", "10", "--ic", "displacement", "--N", "151", "--T", "1e-3",
              "--fit", "2e-4:1e-3", "--realizations", "2", "--samples", "50", "--profile-F0", "10", "--quiet",
              output="exp")
    tools.run("localization", "--N", "2000", "--f", "0:40:1", "--quiet", output="loc")
    runs = [("localization", "loc.csv", "--spectrum", "spectrum.csv"), ("ipr-map", "ipr-map.csv"), ("spectrum", "spectrum.csv"), ("correlations", "correlations.csv"),
            ("map", "map.h5", "g.csv", "--t-window", "0:5e-4", "--sites", "50:150"),
            ("forces", "one-forces.csv", "one-profile.csv"), ("spread", "one.csv"), ("exponents", "exp", "--profiles"),
            ("centres", "exp"), ("spectra", "g.csv", "g.csv", "--titles", "one", "-o", "spectra.png"),
            ("ipr-averaging", "ipr-map.csv", "ipr-bin.csv", "--xi", "0.3", "--gap", "10,20", "--dpi", "150"),
            ("mode-kicks", "one.csv", "-o", "kicks.png"), ("study-comparison", "exp.csv", "exp")]
    for args in runs:
        done = cli("-m", "granular.plot", *args, cwd=folder)
        assert done.returncode == 0, (args, done.stderr)
    for png in ("loc.png", "ipr-map.png", "spectrum.png", "correlations.png", "map.png", "one-forces.png", "one.png",
                "exp-spreading-displacement.png", "exp-profiles.png", "exp-centres.png", "spectra.png",
                "ipr-map-averaging.png", "kicks.png", "exp-comparison.png"):
        assert (folder / png).stat().st_size > 10000, png
    bad = cli("-m", "granular.plot", "spectrum", "missing.csv", cwd=folder)
    assert bad.returncode == 2 and "missing.csv" in bad.stderr and "Traceback" not in bad.stderr


def test_the_readme_main_job_figure_command_keeps_working(tools):
    """`/usr/bin/python3 tools/plot/ipr_map.py ipr-map.csv` writes ipr-map.png, also without
    PYTHONPATH (the script finds the package in the tree)."""
    tools.run("ipr-map", "--xi", "0.4,0.6", "--q", "0.5", "--N", "20", "--realizations", "2", "--quiet",
              output="ipr-map.csv")
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    done = subprocess.run([sys.executable, SOURCE / "tools" / "plot" / "ipr_map.py", "ipr-map.csv"],
                          capture_output=True, text=True, cwd=tools.folder, env=env)
    assert done.returncode == 0, done.stderr
    assert (tools.folder / "ipr-map.png").stat().st_size > 10000
    for script in ("ipr_map.py", "spectrum.py", "correlations.py", "partial_spectrum_ipr.py", "localization.py",
                   "exponents.py", "spreading_figures.py", "ipr_averaging.py", "mode_kicks.py", "long_times.py"):
        helped = subprocess.run([sys.executable, SOURCE / "tools" / "plot" / script, "--help"], capture_output=True,
                                text=True, env=env)
        assert helped.returncode == 0 and "usage" in helped.stdout and not helped.stderr, script
    helped = cli("-m", "granular.plot", "exponents", "--help", cwd=tools.folder)
    assert helped.returncode == 0 and "prefix" in helped.stdout
    helped = cli("-m", "granular.plot", "--help", cwd=tools.folder)
    assert helped.returncode == 0 and "the files the command-line tools write" in " ".join(helped.stdout.split())


def test_partial_spectrum_script_runs_the_tool_and_draws(tools):
    done = subprocess.run([sys.executable, SOURCE / "tools" / "plot" / "partial_spectrum_ipr.py", "--tool",
                           BUILD / "spectrum", "--sizes", "200,2000", "--count", "6", "-o", "p.png"],
                          capture_output=True, text=True, cwd=tools.folder)
    assert done.returncode == 0, done.stderr
    assert (tools.folder / "p.png").stat().st_size > 10000


def test_figures_need_no_compiled_core_for_files(tools):
    """granular.plot draws the tools' files with only the pure-Python package (no band edges then)."""
    tools.run("spectrum", "--N", "40", output="s.csv")
    code = ("import sys; sys.modules['granular._core'] = None\n"
            "import granular.plot as gp\n"
            "gp.spectrum('s.csv').savefig('s.png')\n")
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(os.path.abspath(gr.__file__))))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=tools.folder, env=env)
    assert done.returncode == 0, done.stderr
    assert np.isfinite((tools.folder / "s.png").stat().st_size)


def test_exponents_script_draws_every_figure_of_a_compare_paper_run(tools):
    tools.run("exponents", "--chains", "h,A", "--F0", "10", "--ic", "displacement", "--N", "151", "--T", "1e-3",
              "--fit", "2e-4:1e-3", "--realizations", "2", "--samples", "50", "--profile-F0", "10", "--compare-paper",
              "--quiet", output="exp")
    done = subprocess.run([sys.executable, SOURCE / "tools" / "plot" / "exponents.py", "exp"], capture_output=True,
                          text=True, cwd=tools.folder)
    assert done.returncode == 0, done.stderr
    for png in ("exp-spreading-displacement.png", "exp-profiles.png", "exp-centres.png", "exp-paper.png"):
        assert (tools.folder / png).stat().st_size > 10000, png
    bad = subprocess.run([sys.executable, SOURCE / "tools" / "plot" / "spreading_figures.py", "nonsense"],
                         capture_output=True, text=True, cwd=tools.folder)
    assert bad.returncode == 2 and "unknown figure" in bad.stderr and "Traceback" not in bad.stderr


def _rendered(fig):
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    return canvas.get_renderer()


def _inside(artist, container, renderer):
    box, outer = artist.get_window_extent(renderer), container.get_window_extent(renderer)
    return box.x0 >= outer.x0 - 1 and box.x1 <= outer.x1 + 1 and box.y0 >= outer.y0 - 1 and box.y1 <= outer.y1 + 1


def test_figures_read_their_runs_metadata_and_keep_their_text_inside(tools):
    """The faults a talk would show: guide labels and titles clipped, insets without the fit window
    they promise, an energy map from the files without its title, band edges or a sane g(nu) axis."""
    folder = tools.folder
    tools.run("exponents", "--chains", "h,A", "--F0", "10", "--ic", "displacement", "--N", "151", "--T", "1e-3",
              "--fit", "4e-4:1e-3", "--fit-step", "1e-6", "--t-star", "4e-4", "--realizations", "2", "--samples", "50",
              "--profile-F0", "10", "--quiet", output="exp")
    fig = gp.exponents(folder / "exp")
    renderer = _rendered(fig)
    mains = [ax for ax in fig.axes if ax.get_ylabel()]
    for ax in mains:
        for text in ax.texts:
            if text.get_text().startswith("slope"):
                assert _inside(text, ax, renderer), text.get_text()
    insets = [child for ax in mains for child in ax.child_axes]
    assert insets and all(inset.patches for inset in insets)  # the shaded fit window (4e-4..1e-3 s)
    spans = insets[0].patches[0].get_path().vertices[:, 0]
    assert min(spans) == pytest.approx(4e-4) and max(spans) == pytest.approx(1e-3)
    # drawn at most ~100 points per decade, though the fit window is sampled every 1 us
    drawn = mains[0].lines[0].get_xdata()
    assert len(drawn) < 0.5 * len(gp._style.log_thinned(np.geomspace(1e-6, 1e-3, 1000), per_decade=1000))
    assert np.all(np.diff(np.log10(drawn))[:-1] >= 0.01 - 1e-12)

    centres = gp.centres(folder / "exp", chain="A")
    assert _inside(centres._suptitle, centres, _rendered(centres))
    assert all(ax.patches for ax in centres.axes if ax.get_visible())  # the run's window, not a fixed one

    tools.run("spreading", "--N", "201", "--T", "1e-3", "--fit", "2e-4:1e-3", "--energy-map", folder / "map.h5",
              "--map-samples", "40", "--spectrum", folder / "g.csv", "--spectrum-samples", "100", output="one")
    fig = gp.energy_map(folder / "map.h5", folder / "g.csv")
    assert fig._suptitle is not None and "N = 201" in fig._suptitle.get_text()
    g_panel = fig.axes[1]
    assert 46 < g_panel.get_ylim()[1] < 60  # 1.25 x the top band edge f2 = 45.6 kHz, not the kick's 250 kHz tail
    assert len([t for t in g_panel.get_xticks() if g_panel.get_xlim()[0] <= t <= g_panel.get_xlim()[1]]) <= 5


def test_localization_figure_marks_unresolved_lengths(tools):
    tools.run("localization", "--N", "2000", "--f", "0:40:1", "--quiet", output="loc")
    rows = np.genfromtxt(tools.folder / "loc.csv", delimiter=",", names=True)
    assert 0 < rows["resolved"].sum() < len(rows)  # f = 0 is never resolved
    fig = gp.localization(tools.folder / "loc.csv")
    labels = [line.get_label() for line in fig.axes[0].lines]
    assert any(label.startswith("not resolved") for label in labels)
    measured = fig.axes[0].lines[0].get_ydata()
    assert np.isnan(measured[rows["resolved"] == 0]).all()
    # Its N is the transfer matrices' walk, not a chain's; its legend keeps off the curve.
    title = fig._suptitle.get_text()
    assert "transfer matrices over 2,000 beads" in title and "N = 2000" not in title, title
    assert fig.axes[0].get_legend()._loc == 0  # matplotlib's "best"


def test_breather_figure_draws_the_branch_from_the_result_and_the_tools_files(tools):
    """The same points, stability and multipliers from a granular.Breathers and from the tool's CSV + JSON + H5."""
    types = [2 if i % 2 == 0 else 1 for i in range(21)]
    config = tools.folder / "diatomic.txt"
    config.write_text("\n".join(map(str, types)) + "\n")
    edge = gr.band_edges(xi=0.5).fb2
    tools.run("breathers", "--config", config, "--xi", "0.5", "--near", repr(edge), "--max-points", "3",
              "--quiet", output="br")
    b = gr.breathers(gr.from_types(types, xi=0.5), near=edge, max_points=3)
    for source in (b, tools.folder / "br.csv"):
        fig = gp.breather_branch(source, point=1)
        check_axes(fig)
        branch, circle = fig.axes[:2]
        stable, unstable = branch.lines[1], branch.lines[2]
        drawn = np.sort(np.concatenate([stable.get_xdata(), unstable.get_xdata()]))
        assert np.array_equal(drawn, np.sort(b.freq_khz))
        assert np.array_equal(stable.get_xdata(), b.freq_khz[b.stable])
        assert np.allclose(stable.get_ydata(), b.energy[b.stable] * 1e6, rtol=1e-12, atol=0)  # in µJ
        assert branch.get_ylabel() == r"energy above the static state [$\mu$J]"
        assert "gap (no linear mode)" in [t.get_text() for t in branch.get_legend().get_texts()]  # from the edge
        profiles = fig.axes[2:]  # of the first, middle and last points
        assert len(profiles) == 3
        for ax, j in zip(profiles, (0, 1, 2)):
            assert np.allclose([bar.get_height() for bar in ax.patches], b.profiles[j] * 1e6, rtol=1e-12, atol=0)
        mu = circle.lines[1]
        assert np.allclose(mu.get_xdata() + 1j * mu.get_ydata(), b.multipliers[1], rtol=0, atol=1e-12)
        # F0 > 0: every verdict trusted, nothing marked (the F0 = 0 test below marks them)
        assert not any("untrusted" in line.get_label() for line in branch.lines)
        assert not any("untrusted" in t.get_text() for t in branch.get_legend().get_texts())
        assert "untrusted" not in circle.get_title()
    done = cli("-m", "granular.plot", "breathers", "br.csv", "--point", "0", cwd=tools.folder)
    assert done.returncode == 0, done.stderr
    assert (tools.folder / "br.png").stat().st_size > 10000
    bad = cli("-m", "granular.plot", "breathers", "br.csv", "--point", "7", cwd=tools.folder)
    assert bad.returncode == 2 and "Traceback" not in bad.stderr


def test_breather_figure_marks_untrusted_verdicts_at_zero_precompression(tools):
    """At F0 = 0 the Floquet verdicts are the discretized map's (verdict_trusted False): the branch panel rings every
    point with its own legend entry and the multiplier panel says so, from the result and from the tool's files,
    whose HDF5 carries the flag and the reason too."""
    import h5py

    onsite = ("--quasi", "s1", "--modulation", "0", "--phase", "0", "--k0-n-per-m", "1e7", "--F0", "0", "--N", "21")
    tools.run("breathers", *onsite, "--start-offset", "1e-2", "--max-points", "3", "--quiet", output="cradle")
    b = gr.breathers(gr.quasiperiodic("s1", N=21, modulation=0.0, phase=0.0, F0=0.0, k0_n_per_m=1e7), max_points=3,
                     start_offset=1e-2)
    assert not b.verdict_trusted.any()
    with h5py.File(tools.folder / "cradle.h5", "r") as f:
        assert np.array_equal(np.array(f["verdict_trusted"]), np.zeros(3))
        assert "F0 = 0" in f.attrs["verdict_untrusted_reason"].decode()
    for source in (b, tools.folder / "cradle.csv"):
        fig = gp.breather_branch(source, point=1)
        check_axes(fig)
        branch, circle = fig.axes[:2]
        rings = branch.lines[3]  # after the branch line, the stable and the unstable points
        assert rings.get_label() == "verdict untrusted at F0 = 0: the discretized map's"
        assert rings.get_marker() == "s" and rings.get_markerfacecolor() == "none"
        assert np.array_equal(np.sort(rings.get_xdata()), np.sort(b.freq_khz))  # every point of the branch
        assert rings.get_label() in [t.get_text() for t in branch.get_legend().get_texts()]
        assert "untrusted" in circle.get_title()


def test_quasiperiodic_figures_name_their_chain():
    """A quasiperiodic chain's figure says its kind and every parameter that sets it (it said only N and F0)."""
    fly = gp.butterfly(gr.butterfly("s1", modulation=0.5, ratios="0.2,0.4", N=40, phase=0.4))
    title = fly._suptitle.get_text()
    for part in ("S1 quasiperiodic", r"$\lambda$ = 0.5", r"$\varphi$ = 0.4", r"$\kappa$ = 4", "N = 40"):
        assert part in title, (part, title)
    chain = gr.quasiperiodic("cylinders", N=30, modulation=0.3, ratio="2/7", angle=60)
    spectrum = gp.spectrum(gr.spectrum(chain))
    title = spectrum._suptitle.get_text()
    for part in ("cylinders quasiperiodic", r"$\lambda$ = 0.3", r"$\beta$ = 0.285714", r"$\alpha_0$ = 60°",
                 r"$\varphi$ drawn per realization"):
        assert part in title, (part, title)


def test_crystal_figure_from_a_result_and_from_the_tools_files(tools):
    r = gr.crystal(lattice="hexagonal", Lx=6, Ly=6, width=0.4, vectors=True)
    fig = gr.plot.crystal(r)
    assert len(fig.axes) == 2
    assert "IPR = " in fig.axes[1].get_title()
    assert len(fig.axes[1].collections[1].get_offsets()) == 36  # one arrow per bead
    tools.run("crystal", "--lattice", "hexagonal", "--Lx", "6", "--Ly", "6", "--width", "0.4", "--vectors", "--quiet",
              output="c.csv")
    fig = gr.plot.crystal(tools.path("c.csv"), mode=3)
    assert fig.axes[1].get_title().startswith("mode 3:")
    with pytest.raises(ValueError, match="mode 99"):
        gr.plot.crystal(r, mode=99)


def test_crystal_ipr_map_figure_has_a_curve_per_width():
    m = gr.crystal_ipr_map(lattice="hexagonal", Lx=6, Ly=6, widths=[0.0, 0.8], realizations=2, bin_hz=4000.0)
    fig = gr.plot.crystal_ipr_map(m)
    assert len(fig.axes) == 2
    assert len(fig.axes[0].get_lines()) == 2
    assert fig.axes[1].get_ylabel().startswith("<r>")
