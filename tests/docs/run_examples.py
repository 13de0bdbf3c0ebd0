"""Examples that are tests: every shell and Python block of the README and of the docs pages runs,
in page order, in a scratch folder, and every output it names exists and parses (a CSV with a
header and rows, its JSON beside it, a PNG that is a PNG).

usage: run_examples.py SOURCE_DIR BUILD_DIR WORK_DIR

What is not run, and why, is listed block by block in SKIP (a listed block that no page has any
more fails the test, so the list cannot outlive its blocks); a shell block neither run nor listed
(no line that starts like a command a reader pastes) fails it too; what runs smaller than printed (the
paper's whole study), in SMALLER — each says so on stdout. Paths: ./build/ and $B are the build tree,
tools/ and data/ the source tree, and figures a page writes into docs/figures go to the scratch folder.

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
import time

source, build, work = (pathlib.Path(p).resolve() for p in sys.argv[1:4])
PAGES = ["README.md", *sorted(str(p.relative_to(source)) for p in (source / "docs").glob("*.md")),
         *sorted(str(p.relative_to(source)) for p in (source / "docs" / "site").glob("*.md"))]
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
            "the synopsis of granular.plot's command line, over files the page does not make"}
# The paper's whole study (15,010 runs, minutes) at the same settings but a smaller N, T and ensemble.
# Likewise the longest of the rest (tens of seconds each as printed), so that the test takes a minute.
SMALLER = [(r"exponents --compare-paper(?!\S)",
            "exponents --compare-paper --N 301 --T 1e-3 --fit 4e-4:1e-3 --t-star 4e-4 --realizations 3 "
            "--profile-realizations 2 --bootstrap 50"),
           (r"(localization .*)--N 1e7", r"\1--N 1e5"),
           (r"(exponents .*)--realizations (20|50)(?!\d)", r"\1--realizations 4 --bootstrap 50"),
           (r"(spreading .*)--realizations 100(?!\d)", r"\1--realizations 10"),
           (r"--N 100000(?=.*--method slepc)", "--N 10000"),
           # the quasiperiodic chains' scans over kinds and modulations: three modulations, shorter chains
           (r"for lam in [0-9. ]+; do", "for lam in 0.1 0.5 0.9; do"),
           (r"for n in 377 1597; do", "for n in 377; do"),
           (r"(spectrum --quasi .*)--N 1597", r"\1--N 377"),
           (r"(localization --quasi .*)--N 100000", r"\1--N 10000"),
           # their transport regimes: one modulation per kind, short chains and runs
           (r"for case in s1:\S+ s2:\S+ cylinders:\S+; do", "for case in s1:0.5 s2:0.5 cylinders:0.6; do"),
           (r"(exponents --chains none --quasi .*)--F0 10,0.1,0.01", r"\1--N 301 --T 1e-3 --fit 4e-4:1e-3 --t-star 4e-4 --F0 10")]


def blocks(page):
    text = (source / page).read_text()
    # an opening fence with any info string ({toctree} included), closed by a bare fence
    for match in re.finditer(r"^```([^`\n]*)\n(.*?)^```[ \t]*$", text, re.M | re.S):
        yield match.group(1).strip(), match.group(2)


def shell_block(body):
    lines = [line for line in body.splitlines() if line.strip()]
    return any(re.match(r"\s*(\./build/|\$B/|/usr/bin/python3 (tools/plot|-m venv)|PYTHONPATH=build/|mpirun|B=|env/bin/)",
                        line) for line in lines)


def skipped(page, body):
    for (skip_page, start), reason in SKIP.items():
        if page == skip_page and body.startswith(start):
            unused_skips.discard((skip_page, start))
            return reason
    return None


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
    body = re.sub(r"(?<![\w/.-])(tools|data)/", lambda m: f"{source}/{m.group(1)}/", body)
    body = body.replace("-o docs/figures/", "-o ").replace("--output docs/", "--output ")
    for pattern, replacement in SMALLER:
        if re.search(pattern, body):
            body, n = re.subn(pattern, replacement, body)
            print(f"  smaller than printed ({n}x): {pattern} -> {replacement}")
    return body


def outputs(body):
    """(path, kind) of the files a block says it writes."""
    for line in body.splitlines():
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


work.mkdir(parents=True, exist_ok=True)
shutil.rmtree(work / "pip-clone", ignore_errors=True)  # this run's sources, not a previous run's copy
# Shell blocks run as pasted into a clean shell: no PYTHONPATH unless the block sets it (a command
# that needs granular's build tree must say so). Python blocks are a session that has granular.
shell_env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
shell_env.update(MPLBACKEND="Agg", OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMP_NUM_THREADS="2")
env = dict(shell_env, PYTHONPATH=str(build / "python"))
extension = sorted((build / "python" / "granular").glob("_core*.so"))
if not extension:
    sys.exit(f"run_examples: no granular/_core*.so under {build / 'python'}: build granular_python first")
pip_env = dict(shell_env, PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1", HOME=str(work / "home"),
               GRANULAR_PREBUILT_EXTENSION=str(extension[0]))
unused_skips = set(SKIP)
# A page's Python blocks continue each other (as in a session), after the imports they assume.
PRELUDE = "import numpy as np\nimport granular as gr\nimport granular\n"
failures, count, started = [], 0, time.monotonic()
for page in PAGES:
    python_so_far = PRELUDE
    for language, body in blocks(page):
        if language == "python":
            python_so_far += body
            command = ["/usr/bin/python3", "-c", python_so_far]
            label, run_in, run_env = "python block", work, env
        elif language in ("", "sh", "bash", "shell") and skipped(page, body):
            print(f"{page}: {body.splitlines()[0][:90]} ... not run: {skipped(page, body)}")
            continue
        elif language in ("", "sh", "bash", "shell") and not shell_block(body):
            # a shell block that would not run: every block is a command to paste, or listed in SKIP
            failures.append(f"{page}: the block starting {body.splitlines()[0][:90]!r} is not run (no ./build/, "
                            "$B/, /usr/bin/python3 tools/plot, PYTHONPATH=build/, env/bin/ …): make it a command "
                            "as a reader pastes it, or list it in SKIP with the reason")
            continue
        elif language in ("", "sh", "bash", "shell"):
            run_in, run_env = (pip_clone(), pip_env) if pip_block(body) else (work, shell_env)
            body = localize(body)
            command = ["bash", "-euo", "pipefail", "-c", body]
            label = body.strip().splitlines()[0][:90]
        else:
            continue
        count += 1
        t0 = time.monotonic()
        done = subprocess.run(command, cwd=run_in, env=run_env, capture_output=True, text=True, timeout=600)
        print(f"{page}: {label} ... exit {done.returncode} in {time.monotonic() - t0:.1f} s", flush=True)
        if done.returncode != 0:
            failures.append(f"{page}: {label}: exit {done.returncode}\n{done.stderr[-1500:]}")
            continue
        for path, kind in outputs(body):
            problem = check(path, kind)
            if problem:
                failures.append(f"{page}: {label}: {problem}")
print(f"run_examples: {count} blocks in {time.monotonic() - started:.0f} s, {len(SKIP)} listed blocks not run")
for page, start in sorted(unused_skips):
    failures.append(f"SKIP lists a block of {page} starting {start!r} that the page no longer has: remove it")
if failures:
    print("\n".join(failures), file=sys.stderr)
    sys.exit(f"run_examples: {len(failures)} failure(s)")
