"""`pip install .` as a user does it: a fresh `python3 -m venv --system-site-packages`, then
`pip install --no-build-isolation` of a copy of the repository's package files, then `import granular`
from `/` in that environment, its figure command, and a wheel with the same contents.

usage: run_pip_install.py SOURCE_DIR WORK_DIR [PREBUILT_EXTENSION] [--tutorial NOTEBOOK]

With --tutorial the notebook then runs (run_tutorial.py) in a Jupyter kernel of that environment,
registered as a reader registers one (`python -m ipykernel install`), with no PYTHONPATH: the
tutorial as a user of the installed package meets it.

With PREBUILT_EXTENSION (the build tree's _core*.so; ctest label python) setup.py packages it
instead of running CMake, so the test checks the packaging in seconds; that extension still
loads libgranular.so from the build tree. Without it (ctest label long) setup.py builds the
extension with CMake, statically linked, as a user's `pip install .` does (minutes).
"""
import os
import pathlib
import shutil
import subprocess
import sys
import zipfile

arguments = sys.argv[1:]
tutorial = None
if "--tutorial" in arguments:
    at = arguments.index("--tutorial")
    tutorial = pathlib.Path(arguments[at + 1]).resolve()
    del arguments[at:at + 2]
source, work = pathlib.Path(arguments[0]).resolve(), pathlib.Path(arguments[1]).resolve()
prebuilt = arguments[2] if len(arguments) > 2 else None


def run(*command, **kwargs):
    print("+", " ".join(map(str, command)), flush=True)
    done = subprocess.run([str(c) for c in command], text=True, capture_output=True, **kwargs)
    if done.returncode != 0:
        sys.exit(f"pip install test: failed ({done.returncode}): {' '.join(map(str, command))}\n"
                 f"{done.stdout[-4000:]}\n{done.stderr[-4000:]}")
    return done.stdout


shutil.rmtree(work, ignore_errors=True)
copy = work / "granular-src"
# What a pip build reads: the package metadata, setup.py's version source and, without a prebuilt
# extension, everything CMake builds the library and the extension from.
names = ["pyproject.toml", "setup.py", "CMakeLists.txt", "README.md", "LICENSE", "python"]
if not prebuilt:
    names += ["lib", "cmake", "tools", "tests", "examples", "data", "docs", "CITATION.cff"]
for name in names:
    path = source / name
    if path.is_dir():
        shutil.copytree(path, copy / name, ignore=shutil.ignore_patterns("__pycache__", "*.egg-info"))
    elif path.exists():
        copy.mkdir(parents=True, exist_ok=True)
        shutil.copy2(path, copy / name)

env = dict(os.environ)
env.pop("PYTHONPATH", None)  # the build tree's package must not be what gets imported
if prebuilt:
    env["GRANULAR_PREBUILT_EXTENSION"] = str(pathlib.Path(prebuilt).resolve())
venv = work / "env"
run("/usr/bin/python3", "-m", "venv", "--system-site-packages", venv, env=env)
python = venv / "bin" / "python"
run(python, "-m", "pip", "install", "--no-build-isolation", "--no-index", copy, env=env, cwd=work)

check = """
import pathlib, sys
import granular, granular.plot
where = pathlib.Path(granular.__file__).resolve()
assert str(where).startswith(sys.prefix), (where, sys.prefix)
modes = granular.spectrum(granular.anderson(N=30))
assert len(modes.freq_khz) == 30 and modes.freq_khz[0] > 0
print("imported", where, "version", granular.__version__)
"""
print(run(python, "-c", check, env=env, cwd="/"))
out = run(venv / "bin" / "granular-plot", "--help", env=env, cwd="/")
assert "ipr-map" in out, out

if tutorial:
    run(python, "-m", "ipykernel", "install", "--prefix", venv, "--name", "granular-env", env=env, cwd="/")
    print(run(python, pathlib.Path(__file__).with_name("run_tutorial.py"), tutorial, work / "tutorial", "--kernel",
              "granular-env", env=env, cwd=work))

wheels = work / "wheels"
run(python, "-m", "pip", "wheel", "--no-build-isolation", "--no-index", "--no-deps", "-w", wheels, copy, env=env,
    cwd=work)
(wheel,) = wheels.glob("granular-*.whl")
contents = zipfile.ZipFile(wheel).namelist()
for needed in ("granular/__init__.py", "granular/plot/__init__.py", "granular/plot/__main__.py"):
    assert needed in contents, (needed, contents)
assert any(n.startswith("granular/_core") and n.endswith(".so") for n in contents), contents
assert not any(n.startswith("tests/") or "/tests/" in n for n in contents), contents
print(f"pip install test: installed into {venv}, imported from /, granular-plot runs, wheel {wheel.name} complete")
