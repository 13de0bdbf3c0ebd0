"""Finds the package granular for the figure scripts in this folder: installed, on PYTHONPATH,
or else in this source tree (build/python, with the compiled part, before python/)."""
import os
import sys


def plot_main(argv, prog):
    """Runs `python3 -m granular.plot` with argv; returns its exit code."""
    try:
        import granular.plot  # noqa: F401
    except ImportError:
        top = os.path.normpath(os.path.join(os.path.dirname(os.path.realpath(__file__)), os.pardir, os.pardir))
        for folder in (os.path.join(top, "build", "python"), os.path.join(top, "python")):
            if os.path.isfile(os.path.join(folder, "granular", "plot", "__init__.py")):
                sys.path.insert(0, folder)
                break
    from granular.plot.__main__ import main

    return main(argv, prog)
