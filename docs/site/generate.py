"""Assembles the pages of the documentation site that come from the code: one page per tool
(its --help, the same text as `man TOOL`) and the Python reference (every public name of
granular and granular.plot). Run by tools/build-docs.sh: generate.py BUILD_DIR PAGES_DIR."""
import inspect
import os
import re
import subprocess
import sys

build, pages = sys.argv[1], sys.argv[2]
# One home for the tools' one-line summaries: the man pages' (cmake/man_pages.cmake).
SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
with open(os.path.join(os.environ.get("GRANULAR_SOURCE_DIR", SOURCE), "cmake", "man_pages.cmake")) as f:
    TOOLS = dict(re.findall(r'^set\(GRANULAR_MAN_SUMMARY_([\w-]+) "([^"]+)"\)', f.read(), re.M))
if not TOOLS:
    sys.exit("generate.py: no tool summaries in cmake/man_pages.cmake")

os.makedirs(os.path.join(pages, "tools"), exist_ok=True)
index = ["# The command-line tools", "",
         "Every tool takes `--help` and `--version`, works in SI units, reports frequencies in kHz",
         "(`klein-gordon`: the DKG chain's dimensionless units) and writes `PREFIX.csv` with",
         "`PREFIX.json` beside it (every parameter, the seed, the version, the command line). Bad input:",
         "a one-line message naming the option, exit code 2, no file written; an unwritable folder: 1; a",
         "numerical failure: 3. After `cmake --install`, `man TOOL` shows the page below.", "", "| tool | what it computes |", "|---|---|"]
toc = []
for tool, summary in TOOLS.items():
    exe = os.path.join(build, tool)
    if not os.path.exists(exe):
        sys.exit(f"generate.py: {exe} is not built")
    helptext = subprocess.run([exe, "--help"], capture_output=True, text=True, check=True).stdout
    # In a container of class tool-help, whose code wraps (_static/granular.css): --help lines are
    # wider than the page's text column, and a reader should not scroll sideways through them.
    with open(os.path.join(pages, "tools", f"{tool}.md"), "w") as f:
        f.write(f"# {tool}\n\n{summary[0].upper() + summary[1:]}.\n\n"
                f"````{{container}} tool-help\n```text\n$ {tool} --help\n{helptext}```\n````\n")
    index.append(f"| [{tool}]({tool}.md) | {summary} |")
    toc.append(tool)
index += ["", "```{toctree}", ":hidden:", "", *toc, "```", ""]
with open(os.path.join(pages, "tools", "index.md"), "w") as f:
    f.write("\n".join(index))

import granular  # noqa: E402  (from PYTHONPATH: the build tree's package)

lines = ["# Python reference", "",
         "Every public name of `import granular`, then the figures of `granular.plot`. Keywords and",
         "units are the tools' options; [python.md](python.md) is the API at a glance and",
         "[the tutorial](tutorial.ipynb) a guided tour.", "", "## Functions", "", "```{eval-rst}"]
names = sorted(n for n in dir(granular) if not n.startswith("_") and n != "plot")
objects = {n: getattr(granular, n) for n in names}
for n in names:
    if callable(objects[n]) and not inspect.isclass(objects[n]):
        lines.append(f".. autofunction:: granular.{n}")
lines += ["```", "", "## Classes", "", "```{eval-rst}"]
for n in names:
    if inspect.isclass(objects[n]):
        lines += [f".. autoclass:: granular.{n}", "   :members:", ""]
lines += ["```", "", "## Figures: granular.plot", "", "```{eval-rst}"]
for module in ("modes", "disorder", "dynamics", "transport_exponents"):
    lines += [f".. automodule:: granular.plot.{module}", "   :members:", ""]
lines += ["```", ""]
with open(os.path.join(pages, "python-reference.md"), "w") as f:
    f.write("\n".join(lines))
