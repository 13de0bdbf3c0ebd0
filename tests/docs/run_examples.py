"""Examples that are tests: every shell and Python block of the README and of the docs pages runs,
in page order, in a scratch folder, and every output it names exists and parses (a CSV with a
header and rows, its JSON beside it, a PNG that is a PNG). A block is every code block the site
shows: fenced at the top level, fenced inside a list item (indented), or an indented code block.

usage: run_examples.py SOURCE_DIR BUILD_DIR WORK_DIR
       run_examples.py --self-test      (the extractor and the runner on a synthetic page)

What is not run, and why, is listed block by block in SKIP (a listed block that no page has any
more fails the test, so the list cannot outlive its blocks; the programs a listed block names must
exist); a fenced shell block neither run nor listed (no line that starts like a command a reader
pastes) fails it too, and so does an indented block with a line that reads as a command but is
not one to paste (`spectrum --N 100`); an indented block with no such line is a formula or a map
and is not run. What runs smaller than printed (the paper's whole study), in SMALLER — each says
so on stdout. Paths: ./build/, build/, a bare `build` argument and $B are the build tree; tools/,
tests/, data/ and lib/ the source tree; figures a page writes into docs/figures go to the
scratch folder.

The pip blocks (`python3 -m venv … env && env/bin/pip install --no-build-isolation .`, then
`env/bin/python …`) run as printed in a copy of the repository's package files, offline
(PIP_NO_INDEX=1: every dependency is a Debian package the venv sees) and with HOME in the scratch
folder (`ipykernel install --user`); pip packages this build's extension
(GRANULAR_PREBUILT_EXTENSION) instead of having CMake build one for minutes — the test
python_pip_install_build (ctest -L manual) runs that build.
"""
import json
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

import markdown_it
from mdit_py_plugins.deflist import deflist_plugin
from mdit_py_plugins.dollarmath import dollarmath_plugin

source = build = work = pathlib.Path()  # set by main() or self_test()
# The blocks not run, each by its page and first line, with the reason: they build or test the
# very tree this test runs from, which CI does by running them (.ci/run: the test command).
BUILDS_THE_TREE = "configures and builds ./build, the tree this test runs in (CI builds it so)"
IS_THE_TEST_COMMAND = "the test command, which runs this test (CI runs it)"
SKIP = {("README.md", "bash tools/install-deps.sh && cmake -S . -B build"): BUILDS_THE_TREE,
        ("README.md", "bash tools/install-deps.sh && bash tests/run-all.sh"): IS_THE_TEST_COMMAND,
        ("docs/site/install.md", "bash tools/install-deps.sh\ncmake -S . -B build"): BUILDS_THE_TREE,
        ("docs/site/install.md", "bash tools/install-deps.sh && bash tests/run-all.sh"): IS_THE_TEST_COMMAND,
        # shell blocks that are not commands to paste (first line "": every such block of the page)
        ("docs/benchmark-report.md", ""): "the benchmark script's report: every block of it is its output",
        ("docs/python.md", "python3 -m granular.plot ipr-map ipr-map.csv"):
            "the synopsis of granular.plot's command line, over files the page does not make",
        # indented blocks of measurements: their numbers need the idle machine the page names, and
        # minutes to hours (the programs they name must exist all the same)
        ("docs/beyond-the-paper.md", "bash tests/benchmarks/long-time-study.sh build long-times"):
            "the 31-run study at T = 0.1 s (hours); ctest long_time_study_quick runs both lines with --quick",
        ("docs/performance.md", "cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGRANULAR_WERROR=ON && cmake "
                                "--build build -j2\nbuild/tests/test_linear"):
            BUILDS_THE_TREE + ", then the IPR-map comparison (minutes of timings)",
        ("docs/crystals.md", "PYTHONPATH=build/python /usr/bin/python3 docs/results/crystal_finite_size.py"):
            "the finite-size study (2 min, most of it 2304-bead dense solves); it rewrites docs/results and docs/figures",
        ("docs/chaos.md", "PYTHONPATH=build/python /usr/bin/python3 docs/results/chaos_studies.py"):
            "the three chaos studies (a minute of CPU); they rewrite docs/results and docs/figures",
        ("docs/chaos.md", "c++ -std=c++20 -O2 -I lib examples/dkg_weak_chaos.cpp"):
            "the weak-chaos study (100 s of CPU); ctest install_downstream builds and runs the example",
        ("docs/performance.md", "build/benchmarks/ipr_map_benchmark"):
            "what run_ipr_map_comparison.sh runs, three times interleaved (minutes of timings)",
        ("docs/performance.md", "tests/benchmarks/crystal_scaling.sh"):
            "the crystals' scaling runs beside SciPy (10^5 beads: minutes of timings)",
        ("docs/performance.md", "tests/benchmarks/partial_spectrum_scaling.sh"):
            "the partial spectra's scaling runs (N up to 1e7: minutes and 10 GB)",
        ("docs/performance.md", "build/benchmarks/partial_spectrum_benchmark"):
            "a benchmark's command and its output (timings)",
        ("docs/performance.md", "cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DGRANULAR_WERROR=ON && cmake "
                                "--build build -j2\nnice ./build/benchmarks/dynamics_benchmark"):
            BUILDS_THE_TREE + ", then the dynamics benchmark (3 min of timings)",
        ("docs/performance.md", "build/benchmarks/dynamics_benchmark --benchmark_filter=LyapunovSpectrumCostRatio"):
            "a benchmark (timings)",
        ("docs/performance.md", "nice ./build/benchmarks/dynamics_benchmark --benchmark_filter=CostAccuracy"):
            "the cost-accuracy benchmark (minutes, with its RKF78 reference) and the figure of its output"}
# The paper's whole study (15,010 runs, minutes) at the same settings but a smaller N, T and ensemble.
# Likewise the longest of the rest (tens of seconds each as printed), so that the test takes a minute.
SMALLER = [(r"exponents --compare-paper(?!\S)",
            "exponents --compare-paper --N 301 --T 1e-3 --fit 4e-4:1e-3 --t-star 4e-4 --realizations 3 "
            "--profile-realizations 2 --bootstrap 50"),
           (r"(localization .*)--N 1e7", r"\1--N 1e5"),
           (r"(exponents .*)--realizations (20|50)(?!\d)", r"\1--realizations 4 --bootstrap 50"),
           (r"(spreading .*)--realizations 100(?!\d)", r"\1--realizations 10"),
           (r"--N 100000(?=.*--method slepc)", "--N 10000"),
           # SciPy's eigsh beside bisect on the same matrix: 11 s at N = 1e6, 1 s at 1e5
           (r"(?s)--N 1000000(?=.*scipy_eigsh\.py)", "--N 100000"),
           # the quasiperiodic chains' scans over kinds and modulations: three modulations, shorter chains
           (r"for lam in [0-9. ]+; do", "for lam in 0.1 0.5 0.9; do"),
           (r"for n in 377 1597; do", "for n in 377; do"),
           (r"(spectrum --quasi .*)--N 1597", r"\1--N 377"),
           (r"(localization --quasi .*)--N 100000", r"\1--N 10000"),
           # their transport regimes: one modulation per kind, short chains and runs
           (r"for case in s1:\S+ s2:\S+ cylinders:\S+; do", "for case in s1:0.5 s2:0.5 cylinders:0.6; do"),
           (r"(exponents --chains none --quasi .*)--F0 10,0.1,0.01", r"\1--N 301 --T 1e-3 --fit 4e-4:1e-3 --t-star 4e-4 --F0 10")]


# The pages' Markdown as the site's MyST reads it (CommonMark with the site's extensions, dollarmath
# and deflist: docs/site/conf.py), so that a block is a block here exactly when it is on the site.
MARKDOWN = markdown_it.MarkdownIt("commonmark").use(dollarmath_plugin).use(deflist_plugin)
SHELL = ("", "sh", "bash", "shell")
# How a line a reader pastes into a shell starts: a program of the build or source tree, or a shell
# word that runs one. A block with such a line is a command block.
COMMAND_LINE = re.compile(r"\s*((\./)?build/|\$B/|/usr/bin/|PYTHONPATH=build/|mpirun|B=|env/bin/"
                          r"|(tests|tools)/\S+\.sh\b|(bash|nice|cmake|ctest|g\+\+|for \w+ in) )")
# A line that reads as a command but would not run as pasted: a tool's name and its options.
NOT_PASTEABLE = re.compile(r"\s*[\w.-]+ --[A-Za-z]")


def blocks(text):
    """(language, body, line, nested) of every code block of a page: fenced ones at any depth (in a
    list item they are indented; their body comes without that indentation) and indented code
    blocks, whose language is "indented". nested: the block is not a fenced block at the top level."""
    for token in MARKDOWN.parse(text):
        if token.type == "fence":
            yield token.info.strip(), token.content, token.map[0] + 1, token.level > 0
        elif token.type == "code_block":
            yield "indented", token.content, token.map[0] + 1, True


def shell_block(body):
    return any(COMMAND_LINE.match(line) for line in body.splitlines() if line.strip())


def command_like(body):
    """A block that a reader would take for commands (an indented block is otherwise a formula or a map)."""
    return shell_block(body) or any(NOT_PASTEABLE.match(line) for line in body.splitlines())


def skipped(page, body, skip=None):
    for (skip_page, start), reason in (SKIP if skip is None else skip).items():
        if page == skip_page and body.startswith(start):
            unused_skips.discard((skip_page, start))
            return reason
    return None


def missing_programs(body):
    """The programs of the build or source tree that a block's command lines name and that do not
    exist (a part of the build tree that was not built at all, such as build/benchmarks, is not asked)."""
    missing = []
    for line in body.splitlines():
        if not COMMAND_LINE.match(line):
            continue
        words = line.split()
        while words and (re.fullmatch(r"\w+=\S*|nice|bash|-v|/usr/bin/time", words[0])):
            words.pop(0)
        if not words or "/" not in words[0] or "$" in words[0]:
            continue
        word = words[0]
        if re.match(r"(\./)?build/", word):
            path = build / re.sub(r"^(\./)?build/", "", word)
            if not path.parent.is_dir():
                continue
        elif re.match(r"(tools|tests|data|lib)/", word):
            path = source / word
        else:
            path = pathlib.Path(word)
        if not path.exists():
            missing.append(word)
    return missing


def pip_block(body):
    """A block of the pip route: it makes or uses the venv `env` of the repository's folder."""
    return re.search(r"-m venv\b|(?<![\w/])env/bin/", body) is not None


def pip_clone():
    """The folder a reader runs the pip blocks in: a copy of what `pip install .` reads (once)."""
    clone = work / "pip-clone"
    if not (clone / "pyproject.toml").exists():
        for name in ("pyproject.toml", "setup.py", "CMakeLists.txt", "README.md", "LICENSE", "python"):
            path = source / name
            if path.is_dir():
                shutil.copytree(path, clone / name, ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
            else:
                clone.mkdir(parents=True, exist_ok=True)
                shutil.copy2(path, clone / name)
        print("  pip blocks: run in a copy of the package files, offline, packaging this build's extension")
    return clone


def localize(body):
    body = re.sub(r"(?<![\w/.])\./build(?![\w.-])", str(build), body)
    body = re.sub(r"(?<![\w/.$])build/", f"{build}/", body)
    body = re.sub(r"(?<=\.sh )build(?=\s|$)", str(build), body)  # a script's BUILD_DIR argument
    body = re.sub(r"(?<![\w/.-])(tools|tests|data|lib)/", lambda m: f"{source}/{m.group(1)}/", body)
    body = re.sub(r"(?<=\s)-Ilib(?=\s)", f"-I{source}/lib", body)
    body = body.replace("-o docs/figures/", "-o ").replace("--output docs/", "--output ")
    for pattern, replacement in SMALLER:
        if re.search(pattern, body):
            body, n = re.subn(pattern, replacement, body)
            print(f"  smaller than printed ({n}x): {pattern} -> {replacement}")
    return body


def outputs(body):
    """(path, kind) of the files a block says it writes."""
    for line in body.replace("\\\n", " ").splitlines():  # a command continued with \ is one line
        words = shlex.split(line.split(" #")[0], posix=True) if line.strip() and not line.lstrip().startswith("#") else []
        for flag, value in zip(words, words[1:]):
            if flag == "--output" and "$" not in value:
                prefix = value[:-4] if value.endswith(".csv") else value
                yield prefix + ".csv", "csv"
                yield prefix + ".json", "json"
            elif flag in ("-o", "--figure") and value.endswith(".png"):
                yield os.path.basename(value), "png"


def check(path, kind):
    file = work / path
    if not file.exists():
        return f"{path} was not written"
    if kind == "csv":
        rows = file.read_text().splitlines()
        if len(rows) < 2 or "," not in rows[0]:
            return f"{path} has no header and rows"
    elif kind == "json":
        json.loads(file.read_text())
    elif kind == "png" and file.read_bytes()[:8] != b"\x89PNG\r\n\x1a\n":
        return f"{path} is not a PNG"
    return None


def environments():
    """The environments of the shell blocks, the Python blocks and the pip blocks."""
    # Shell blocks run as pasted into a clean shell: no PYTHONPATH unless the block sets it (a command
    # that needs granular's build tree must say so). Python blocks are a session that has granular.
    shell_env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    shell_env.update(MPLBACKEND="Agg", OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                     OMP_NUM_THREADS="2")
    env = dict(shell_env, PYTHONPATH=str(build / "python"))
    extension = sorted((build / "python" / "granular").glob("_core*.so"))
    pip_env = dict(shell_env, PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1", HOME=str(work / "home"),
                   GRANULAR_PREBUILT_EXTENSION=str(extension[0]) if extension else "")
    return shell_env, env, pip_env


# A page's Python blocks continue each other (as in a session), after the imports they assume.
PRELUDE = "import numpy as np\nimport granular as gr\nimport granular\n"


def run_page(page, text, skip=None):
    """Runs every block of one page in order; returns (blocks run, failures)."""
    shell_env, env, pip_env = environments()
    python_so_far, count, failures = PRELUDE, 0, []
    for language, body, line, nested in blocks(text):
        where = f"{page}:{line}"
        first = body.splitlines()[0][:90] if body.strip() else ""
        shell = language in SHELL or language == "indented"
        if language == "python":
            python_so_far += body
            command = ["/usr/bin/python3", "-c", python_so_far]
            label, run_in, run_env = "python block", work, env
        elif shell and skipped(page, body, skip):
            print(f"{where}: {first} ... not run: {skipped(page, body, skip)}")
            for program in missing_programs(body):
                failures.append(f"{where}: the listed block starting {first!r} names {program}, which does not "
                                "exist: fix the page (or SKIP)")
            continue
        elif language == "indented" and not command_like(body):
            continue  # a formula, a folder map, an output: nothing a reader pastes
        elif shell and not shell_block(body):
            # a shell block that would not run: every block is a command to paste, or listed in SKIP
            failures.append(f"{where}: the block starting {first!r} is not run (no ./build/, $B/, "
                            "/usr/bin/python3 tools/plot, PYTHONPATH=build/, env/bin/ …): make it a command "
                            "as a reader pastes it, or list it in SKIP with the reason")
            continue
        elif shell:
            run_in, run_env = (pip_clone(), pip_env) if pip_block(body) else (work, shell_env)
            body = localize(body)
            command = ["bash", "-euo", "pipefail", "-c", body]
            label = ("(indented) " if nested else "") + body.strip().splitlines()[0][:90]
        else:
            continue
        count += 1
        t0 = time.monotonic()
        done = subprocess.run(command, cwd=run_in, env=run_env, capture_output=True, text=True, timeout=600)
        print(f"{where}: {label} ... exit {done.returncode} in {time.monotonic() - t0:.1f} s", flush=True)
        if done.returncode != 0:
            failures.append(f"{where}: {label}: exit {done.returncode}\n{done.stderr[-1500:]}")
            continue
        for path, kind in outputs(body):
            problem = check(path, kind)
            if problem:
                failures.append(f"{where}: {label}: {problem}")
    return count, failures


unused_skips = set(SKIP)


def main(arguments):
    global source, build, work
    source, build, work = (pathlib.Path(p).resolve() for p in arguments)
    pages = ["README.md", *sorted(str(p.relative_to(source)) for p in (source / "docs").glob("*.md")),
             *sorted(str(p.relative_to(source)) for p in (source / "docs" / "site").glob("*.md"))]
    work.mkdir(parents=True, exist_ok=True)
    shutil.rmtree(work / "pip-clone", ignore_errors=True)  # this run's sources, not a previous run's copy
    if not sorted((build / "python" / "granular").glob("_core*.so")):
        sys.exit(f"run_examples: no granular/_core*.so under {build / 'python'}: build granular_python first")
    failures, count, started = [], 0, time.monotonic()
    for page in pages:
        ran, failed = run_page(page, (source / page).read_text())
        count += ran
        failures += failed
    print(f"run_examples: {count} blocks in {time.monotonic() - started:.0f} s, {len(SKIP)} listed blocks not run")
    for page, start in sorted(unused_skips):
        failures.append(f"SKIP lists a block of {page} starting {start!r} that the page no longer has: remove it")
    if failures:
        print("\n".join(failures), file=sys.stderr)
        sys.exit(f"run_examples: {len(failures)} failure(s)")


# The self-test's page: a command block in each place a page can put one, a failing one nested in a
# list, a formula and a map (not commands), a tool's name alone (not pasteable) and a listed block
# whose script does not exist. Each command block that runs writes its word into ran.txt.
SELF_TEST_PAGE = """# A page

```sh
./build/ok top
```

1. A step in a list, its block fenced and indented:

   ```sh
   ./build/ok list-fenced
   ```

2. A step whose command fails:

   ```bash
   ./build/fail list-fenced-failing
   ```

An indented block:

    ./build/ok indented

A formula and a map, indented, are not commands:

    A = (4/3) E* sqrt(R*),   1/E* = (1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b

and

    lib/granular/   the library

- An item with an indented block in it:

      for word in list-indented; do ./build/ok $word; done

A tool's name with options, not a command to paste:

    spectrum --N 100

~~~
./build/ok tilde
~~~

Listed, not run, but its script must exist:

    bash tests/benchmarks/no-such-script.sh build
"""


def self_test():
    global source, build, work
    with tempfile.TemporaryDirectory() as folder:
        source, build, work = (pathlib.Path(folder) / name for name in ("source", "build", "work"))
        for path in (source / "tests" / "benchmarks", build, work):
            path.mkdir(parents=True)
        for name, code in (("ok", 0), ("fail", 1)):
            (build / name).write_text(f"#!/bin/sh\necho \"$1\" >> {work}/ran.txt\nexit {code}\n")
            (build / name).chmod(0o755)
        found = [(language, body.splitlines()[0], nested) for language, body, _, nested in blocks(SELF_TEST_PAGE)]
        expected = [("sh", "./build/ok top", False), ("sh", "./build/ok list-fenced", True),
                    ("bash", "./build/fail list-fenced-failing", True), ("indented", "./build/ok indented", True),
                    ("indented", "A = (4/3) E* sqrt(R*),   1/E* = (1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b", True),
                    ("indented", "lib/granular/   the library", True),
                    ("indented", "for word in list-indented; do ./build/ok $word; done", True),
                    ("indented", "spectrum --N 100", True), ("", "./build/ok tilde", False),
                    ("indented", "bash tests/benchmarks/no-such-script.sh build", True)]
        problems = [f"blocks: found {found}, expected {expected}"] if found != expected else []
        skip = {("page.md", "bash tests/benchmarks/no-such-script.sh"): "listed"}
        count, failures = run_page("page.md", SELF_TEST_PAGE, skip)
        ran = (work / "ran.txt").read_text().split() if (work / "ran.txt").exists() else []
        if ran != ["top", "list-fenced", "list-fenced-failing", "indented", "list-indented", "tilde"]:
            problems.append(f"ran {ran}")
        if count != 6:
            problems.append(f"counted {count} blocks run, expected 6")
        wanted = [("page.md:15: (indented) ", "/build/fail list-fenced-failing: exit 1"),
                  ("page.md:37: the block starting 'spectrum --N 100' is not run", ""),
                  ("page.md:45: the listed block starting 'bash tests/benchmarks/no-such-script.sh build' names "
                   "tests/benchmarks/no-such-script.sh, which does not exist", "")]
        if len(failures) != len(wanted) or any(not f.startswith(start) or part not in f
                                               for f, (start, part) in zip(failures, wanted)):
            problems.append("failures:\n  " + "\n  ".join(failures))
    if problems:
        sys.exit("run_examples --self-test:\n" + "\n".join(problems))
    print(f"run_examples --self-test: {len(found)} blocks found, 6 run, 3 failures as expected")


if __name__ == "__main__":
    if sys.argv[1:] == ["--self-test"]:
        self_test()
    else:
        main(sys.argv[1:4])
