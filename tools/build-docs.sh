#!/usr/bin/env bash
# Builds the documentation site into BUILD/docs-site/html (default BUILD: build): assembles its
# pages in BUILD/docs-site/src (docs/site/*, the docs/ pages, the tutorial, the examples, a page
# per tool from its --help, the Python reference), runs Doxygen on the public headers for the
# C++ reference, then sphinx-build with warnings as errors. Needs a built tree (tools, Python).
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$src/build}" && pwd)
site=$build/docs-site
pages=$site/src
/usr/bin/python3 "$src/tests/docs/check_tables.py" "$src"  # a broken table fails the build (MyST would show pipes)
rm -rf "$pages" "$site/html" "$site/doxygen"
mkdir -p "$pages/examples" "$site/doxygen"
cp -r "$src/docs/site/." "$pages/"
cp "$src"/docs/*.md "$src/docs/tutorial.ipynb" "$pages/"
# The tutorial with its figures when the test suite has executed it (python_pip_install_tutorial), else as stored.
executed=$build/python/pip-install/tutorial/tutorial.executed.ipynb
if [ -f "$executed" ] && [ "$executed" -nt "$src/docs/tutorial.ipynb" ]; then cp "$executed" "$pages/tutorial.ipynb"; fi
cp -r "$src/docs/figures" "$src/docs/results" "$pages/"
cp "$src"/examples/*.cpp "$pages/examples/"
GRANULAR_SOURCE_DIR=$src PYTHONPATH=$build/python /usr/bin/python3 "$pages/generate.py" "$build" "$pages"

doxygen - >"$site/doxygen/log" 2>&1 <<DOXYFILE || { cat "$site/doxygen/log"; exit 1; }
PROJECT_NAME = granular
INPUT = $src/lib/granular
STRIP_FROM_PATH = $src/lib/granular
FILE_PATTERNS = *.hpp
RECURSIVE = YES
EXCLUDE_PATTERNS = */detail/*
GENERATE_HTML = NO
GENERATE_LATEX = NO
GENERATE_XML = YES
XML_OUTPUT = $site/doxygen/xml
QUIET = YES
WARN_IF_UNDOCUMENTED = NO
EXTRACT_ALL = YES
MACRO_EXPANSION = YES
# Sphinx 5's C++ parser cannot read designated initializers (= {.N = 2501}) in defaults: those
# defaults are left out of the rendered declarations (the comments beside them state them).
INPUT_FILTER = "sed -E -e 's/ = \{\.[^}]*\}//' -e 's/([A-Za-z0-9_])\{\.[^}]*\}/\1/'"
DOXYFILE

GRANULAR_DOXYGEN_XML=$site/doxygen/xml PYTHONPATH=$build/python \
  /usr/bin/python3 -m sphinx -W --keep-going -q -b html "$pages" "$site/html"
echo "build-docs: $site/html/index.html"
