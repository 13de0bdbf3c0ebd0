# Sphinx configuration of granular's documentation site. Built by tools/build-docs.sh, which
# assembles the sources in the build tree (these pages, the docs/ pages, a page per tool from its
# --help, Doxygen's XML of the public headers) and runs sphinx-build -W (warnings are errors).
import os
import sys

project = "granular"
author = "the granular developers"
copyright = "2026, the granular developers"
version = release = __import__("granular").__version__  # the package autodoc documents

extensions = ["myst_parser", "breathe", "sphinx.ext.autodoc", "sphinx.ext.napoleon", "sphinx.ext.mathjax",
              "nbsphinx"]
source_suffix = {".md": "markdown", ".rst": "restructuredtext"}
myst_enable_extensions = ["dollarmath", "deflist"]
myst_heading_anchors = 3
exclude_patterns = ["_build", "**.ipynb_checkpoints", "results/**", "figures/**"]

# The C++ reference: Doxygen XML of lib/granular (public headers), rendered by Breathe.
breathe_projects = {"granular": os.environ.get("GRANULAR_DOXYGEN_XML", "doxygen/xml")}
breathe_default_project = "granular"
breathe_default_members = ("members",)
cpp_index_common_prefix = ["granular::"]

# The Python reference: the package of the build tree (PYTHONPATH set by build-docs.sh).
autodoc_member_order = "bysource"
autodoc_default_options = {"members": True, "undoc-members": False}

# The tutorial is executed by the test suite (python_pip_install_tutorial); here it is rendered as stored.
nbsphinx_execute = "never"

html_theme = "sphinx_rtd_theme" if __import__("importlib").util.find_spec("sphinx_rtd_theme") else "alabaster"
html_title = "granular — disordered granular chains"
html_show_sourcelink = False
# The tools' --help blocks wrap instead of scrolling sideways (generate.py puts them in .tool-help).
html_static_path = ["_static"]
html_css_files = ["granular.css"]


def _plain_docstring(app, what, name, obj, options, lines):
    """The docstrings are plain text (keyword: meaning [unit] lines, indented continuations), written
    for help(); shown as such rather than parsed as reStructuredText."""
    if lines and not any(line.startswith(".. ") for line in lines):
        text = [line.rstrip() for line in lines]
        lines[:] = ["::", ""] + ["   " + line if line else "" for line in text] + [""]


def setup(app):
    app.connect("autodoc-process-docstring", _plain_docstring)
