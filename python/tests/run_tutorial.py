#!/usr/bin/python3
"""Executes docs/tutorial.ipynb headless, as a reader's Jupyter would (jupyter nbconvert --execute),
and checks it: no cell raised, every cell tagged "figure" produced an image, the whole run stayed
under its time budget. The executed notebook is left in OUTPUT_DIR for inspection.

usage: run_tutorial.py NOTEBOOK OUTPUT_DIR [--budget SECONDS] [--kernel NAME]
(the kernel, by default Jupyter's python3, must reach granular: run_pip_install.py runs this with the
kernel of the virtual environment it installed granular into)
"""
import argparse
import os
import subprocess
import sys
import time

import nbformat


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("notebook")
    p.add_argument("output_dir")
    p.add_argument("--budget", type=float, default=120, help="seconds (the tutorial aims at < 60 on an idle machine)")
    p.add_argument("--kernel", default="python3", help="the Jupyter kernel to run it with")
    args = p.parse_args()
    os.makedirs(args.output_dir, exist_ok=True)
    env = dict(os.environ, PYDEVD_DISABLE_FILE_VALIDATION="1")
    env.pop("MPLBACKEND", None)  # the kernel's own inline backend, as in a reader's notebook
    start = time.monotonic()
    done = subprocess.run([sys.executable, "-m", "nbconvert", "--to", "notebook", "--execute",
                           "--ExecutePreprocessor.timeout=300", f"--ExecutePreprocessor.kernel_name={args.kernel}",
                           args.notebook, "--output-dir", args.output_dir, "--output", "tutorial.executed.ipynb"],
                          capture_output=True, text=True, env=env)
    seconds = time.monotonic() - start
    if done.returncode != 0:
        sys.exit(f"run_tutorial: nbconvert failed ({done.returncode}):\n{done.stderr[-4000:]}")
    nb = nbformat.read(os.path.join(args.output_dir, "tutorial.executed.ipynb"), as_version=4)
    problems, figures = [], 0
    for i, cell in enumerate(nb.cells):
        if cell.cell_type != "code":
            continue
        outputs = cell.get("outputs", [])
        for o in outputs:
            if o.output_type == "error":
                problems.append(f"cell {i}: {o.ename}: {o.evalue}")
            if o.output_type == "stream" and o.name == "stderr" and "Warning" in o.text:
                problems.append(f"cell {i}: a warning on stderr: {o.text.strip()[:200]}")
        if "figure" in cell.metadata.get("tags", []):
            images = [o for o in outputs if "image/png" in o.get("data", {})]
            if not images:
                problems.append(f"cell {i} (tagged figure) produced no image")
            figures += len(images)
    if seconds > args.budget:
        problems.append(f"took {seconds:.0f} s, over the budget of {args.budget:.0f} s")
    if problems:
        sys.exit("run_tutorial: " + "\n  ".join(problems))
    print(f"run_tutorial: {len(nb.cells)} cells, {figures} figures, {seconds:.1f} s")


if __name__ == "__main__":
    main()
