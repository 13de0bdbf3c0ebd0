"""Examples that are tests: every shell and Python block of the README and of the docs pages runs,
in page order, in a scratch folder, and every output it names exists and parses (a CSV with a
header and rows, its JSON beside it, a PNG that is a PNG).

usage: run_examples.py SOURCE_DIR BUILD_DIR WORK_DIR

What is not run, and why, is listed in SKIP; what runs smaller than printed (the paper's whole
study), in SMALLER — each says so on stdout. Paths: ./build/ and $B are the build tree, tools/ and
data/ the source tree, and figures a page writes into docs/figures go to the scratch folder.
"""
import json
import os
import pathlib
import re
import shlex
import subprocess
import sys
import time

source, build, work = (pathlib.Path(p).resolve() for p in sys.argv[1:4])
PAGES = ["README.md", *sorted(str(p.relative_to(source)) for p in (source / "docs").glob("*.md")),
         *sorted(str(p.relative_to(source)) for p in (source / "docs" / "site").glob("*.md"))]
# Blocks that set up or test the toolkit itself: covered by CI running them (install-deps, the test
# command), by python_pip_install_tutorial (pip), or not meant to be run as written (performance scripts).
SKIP = ("install-deps.sh", "pip install", "tests/run-all.sh", "run-benchmarks.sh", "python_vs_cpp.sh", "cmake ",
        "jupyter", "ipykernel", "valgrind", "perf ", "/usr/bin/time", "mpirun -np 4", "git ")
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
    for match in re.finditer(r"^```([a-z]*)\n(.*?)^```", text, re.M | re.S):
        yield match.group(1), match.group(2)


def shell_block(body):
    lines = [line for line in body.splitlines() if line.strip()]
    runnable = any(re.match(r"\s*(\./build/|\$B/|/usr/bin/python3 tools/plot|PYTHONPATH=build/|mpirun|B=)", line)
                   for line in lines)
    return runnable and not any(word in body for word in SKIP)


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
# Shell blocks run as pasted into a clean shell: no PYTHONPATH unless the block sets it (a command
# that needs granular's build tree must say so). Python blocks are a session that has granular.
shell_env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
shell_env.update(MPLBACKEND="Agg", OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMP_NUM_THREADS="2")
env = dict(shell_env, PYTHONPATH=str(build / "python"))
# A page's Python blocks continue each other (as in a session), after the imports they assume.
PRELUDE = "import numpy as np\nimport granular as gr\nimport granular\n"
failures, count, started = [], 0, time.monotonic()
for page in PAGES:
    python_so_far = PRELUDE
    for language, body in blocks(page):
        if language == "python":
            python_so_far += body
            command = ["/usr/bin/python3", "-c", python_so_far]
            label = "python block"
        elif language in ("", "sh", "bash", "shell") and shell_block(body):
            body = localize(body)
            command = ["bash", "-euo", "pipefail", "-c", body]
            label = body.strip().splitlines()[0][:90]
        else:
            continue
        count += 1
        t0 = time.monotonic()
        done = subprocess.run(command, cwd=work, env=env if language == "python" else shell_env, capture_output=True,
                              text=True, timeout=600)
        print(f"{page}: {label} ... exit {done.returncode} in {time.monotonic() - t0:.1f} s", flush=True)
        if done.returncode != 0:
            failures.append(f"{page}: {label}: exit {done.returncode}\n{done.stderr[-1500:]}")
            continue
        for path, kind in outputs(body):
            problem = check(path, kind)
            if problem:
                failures.append(f"{page}: {label}: {problem}")
print(f"run_examples: {count} blocks in {time.monotonic() - started:.0f} s")
if failures:
    print("\n".join(failures), file=sys.stderr)
    sys.exit(f"run_examples: {len(failures)} failure(s)")
