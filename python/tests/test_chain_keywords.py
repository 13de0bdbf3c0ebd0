"""The chain keywords of granular.transport, exponent_table, ipr_map and correlations are the rows of the
library's chain table (chain_parameters(), bound as granular._core.ChainChoices) with each job's own C++
defaults: a row added in lib/ reaches each signature and docstring with no line written in python/granular
and no new test here."""
import inspect
import math

import pytest

import granular as gr
from conftest import assert_identical

core = gr._core
FILES = ("config", "radii", "realization")  # one given chain, or one realization: not an ensemble's

# Each job: its defaults (a ChainChoices made in C++) and which rows its tool takes as chain keywords, by the
# rows it leaves out (so that a new row is taken), or (correlations, whose tool names them) the rows it takes.
JOBS = [
    pytest.param(gr.transport, lambda: core._kicked_chain_defaults(), dict(skip=FILES), id="transport"),
    # disorder: the kinds are `chains`; F0: the table's own list; R1: the exponents tool takes none
    pytest.param(gr.exponent_table, lambda: core.ExponentChoices().beads,
                 dict(skip=FILES + ("disorder", "F0", "R1")), id="exponent_table"),
    pytest.param(gr.ipr_map, core._ipr_map_chain, dict(skip=FILES + ("q", "xi")), id="ipr_map"),  # q, xi: grids
    pytest.param(gr.correlations, core._correlation_chain,
                 dict(only=("disorder", "q", "N", "seed", "types", "type_masses", "polydisperse")), id="correlations"),
]


def _rows(skip=(), only=None):
    """(name, keyword, help) of the chain table's rows a job takes."""
    return [row for row in core.ChainChoices._parameters
            if row[0] not in skip and (only is None or row[0] in only)]


def _python_form(value):
    """A C++ default as a keyword shows it: "" (none) and an empty optional are None."""
    return None if value is None or value == "" or (isinstance(value, float) and math.isnan(value)) else value


@pytest.mark.parametrize("function, defaults, which", JOBS)
def test_chain_keywords_are_the_chain_table_with_the_jobs_defaults(function, defaults, which):
    signature = inspect.signature(function).parameters
    made = defaults()
    assert isinstance(made, core.ChainChoices)
    rows = _rows(**which)
    assert len(rows) >= 7, "the chain table reached Python short"
    for name, keyword, help_text in rows:
        assert keyword in signature, f"{function.__name__} takes no chain keyword {keyword}"
        parameter = signature[keyword]
        assert parameter.kind == inspect.Parameter.KEYWORD_ONLY, keyword
        assert parameter.default == _python_form(getattr(made, name)), keyword
        assert f"\n    {keyword}: {help_text} (default " in function.__doc__, \
            f"{function.__name__}'s docstring does not list the row {keyword} with its help"
    # the chain keywords come first (chain, kick, dynamics, outputs, run), in the table's order
    keywords = [keyword for _, keyword, _ in rows]
    assert list(signature)[:len(keywords)] == keywords
    assert "Chain keywords (the library's chain_parameters()" in function.__doc__


@pytest.mark.parametrize("function, N", [(gr.transport, 2501), (gr.exponent_table, 2501), (gr.ipr_map, 100),
                                         (gr.correlations, 100)])
def test_each_job_has_its_own_chain_length(function, N):
    """The job's own default, made in C++ (kicked_chain_defaults, ExponentChoices, IprMapConfig, CorrelationConfig)."""
    assert inspect.signature(function).parameters["N"].default == N


def test_the_literal_chain_defaults_the_keywords_had_stand():
    """The defaults granular.transport wrote as literals before they were made from the table."""
    taken = inspect.signature(gr.transport).parameters
    before = dict(disorder="A", N=2501, q=0.5, xi=0.5, F0=10.0, R1=core.paper_r1, seed=1, walls="flat", quasi=None,
                  modulation=0.0, ratio="golden", phase=None, angle=45.0, k0=4.0, types=None, type_masses=None,
                  polydisperse=None)
    assert {k: taken[k].default for k in before} == before


@pytest.mark.parametrize("call, keywords, message", [
    (gr.transport, dict(N=31, realizations=1, T=1e-4, fit=(5e-5, 1e-4), k0_n_per_m=1e6),
     r"^k0_n_per_m: takes effect only with quasi"),
    (gr.ipr_map, dict(N=40, k0_n_per_m=1e6), r"^k0_n_per_m: takes effect only with quasi"),
    (gr.exponent_table, dict(chains="none", quasi="s2", k0_n_per_m=1e6, N=31), r"^k0_n_per_m: takes effect only"),
    (gr.transport, dict(N=2.5), r"^N 2.5: must be a whole number"),
    (gr.correlations, dict(N=1), r"^N"),
    (gr.ipr_map, dict(seed=-1), r"^seed"),
])
def test_a_row_new_to_a_job_reaches_the_library(call, keywords, message):
    """A row the tool takes and the literal keywords lacked (k0_n_per_m) reaches the library's rule; sizes are
    checked naming the keyword."""
    with pytest.raises(ValueError, match=message):
        call(**keywords)


@pytest.mark.parametrize("function", [gr.transport, gr.exponent_table, gr.ipr_map, gr.correlations])
def test_an_unknown_chain_keyword_is_a_type_error(function):
    with pytest.raises(TypeError, match="unexpected keyword argument 'Nbeads'"):
        function(Nbeads=10)


@pytest.mark.parametrize("defaults, config", [(core._ipr_map_chain, core.IprMapConfig),
                                              (core._correlation_chain, core.CorrelationConfig)])
def test_a_studys_chain_defaults_are_its_configs_recipe(defaults, config):
    """chain_choices() (chain_choices.hpp) says a study's default recipe in the chain table's words: the same
    two-type draw, so the keywords' defaults are the study's own and not a second copy."""
    choices, recipe = defaults(), config().chain
    for name in ("disorder", "q", "xi", "N", "F0", "R1", "seed", "walls"):
        assert getattr(choices, name) == getattr(recipe, name), name


@pytest.mark.parametrize("keywords, flags", [
    ({"R1": 5e-3, "types": "4.76e-3:0.6,3e-3:0.4"}, ["--R1", "5e-3", "--types", "4.76e-3:0.6,3e-3:0.4"]),
    ({"disorder": "h", "seed": 2}, ["--disorder", "h", "--seed", "2"]),
])
def test_ipr_map_takes_the_draws_numbers_as_its_tool(tools, keywords, flags):
    """The ipr-map tool sets R1 and seed in the map's recipe, beside its chain-kind options: it takes --R1 with
    --types and --seed with --disorder h, and so does ipr_map (the keywords made from the chain table are not
    refused by its overridden rule here)."""
    csv, meta = tools.run("ipr-map", "--N", "20", "--realizations", "2", "--xi", "0.5", "--q", "0.5", *flags,
                          "--quiet")
    grid = gr.ipr_map(N=20, realizations=2, xi=0.5, q=0.5, **keywords)
    for key in ("mode", "freq_khz", "ipr"):
        assert_identical(grid.rows()[key], csv[key])
    assert grid.metadata["parameters"] == meta["parameters"]


@pytest.mark.parametrize("function, landmarks", [
    (gr.transport, ["N", "realizations", "ic", "mode", "beta", "fit", "T", "profile", "threads", "progress"]),
    (gr.exponent_table, ["N", "chains", "ic", "mode", "beta", "fit", "T", "profile_F0", "threads", "progress"]),
    (gr.spreading, ["chain", "ic", "mode", "beta", "fit", "T", "forces_at", "energy_map", "progress"]),
])
def test_keywords_are_grouped_as_users_think(function, landmarks):
    """chain, kick (ic and the mode kick's), dynamics (the run table after fit), outputs, run: the tables' keywords
    sit in their group, not after the function's own."""
    names = list(inspect.signature(function).parameters)
    at = [names.index(name) for name in landmarks]
    assert at == sorted(at), [names[i] for i in sorted(at)]


@pytest.mark.parametrize("function", [gr.transport, gr.exponent_table])
def test_run_control_keywords_are_the_long_run_tables_rows(function):
    """threads, resume, ..., one_at_a_time: each row of the library's long_run_parameters() (but the checkpoint,
    the front end's) is a keyword with RunOptions' C++ default, and the docstring says so: a row added in lib/
    reaches both with no line written in python/granular."""
    signature = inspect.signature(function).parameters
    defaults = core.RunOptions()
    for name, keyword, help_text in core._RunOptions._parameters:
        assert keyword in signature, f"{function.__name__} takes no run keyword {keyword}"
        assert signature[keyword].default == getattr(defaults, name), keyword
        assert f"{keyword}: {help_text}" in function.__doc__
