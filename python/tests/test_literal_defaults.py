"""A public function of python/granular takes its defaults from the C++ library (a config's or a table's own
initializer, read through granular._core), not from a number or word written again in Python, so that a default
changed in lib/ reaches every signature. The keywords that still carry a literal are listed here, each a debt
to pay by moving its default into a C++ table; a new literal, or a listed one that is gone, fails the test, so
the list can only shrink. (threads=0, "every core", and None/True/False are conventions, not defaults of a
case.)"""
import ast
import pathlib

import granular as gr

PACKAGE = pathlib.Path(gr.__file__).parent

# module.function.keyword of each literal default left (see the module docstring)
STILL_LITERAL = {
    "_dynamics.transport.realizations",  # the ensemble's 100 (the tool: 1, the exponent table: 500)
    "_progress.run_long.interrupted",
    # the butterflies' quasiperiodic kind (the tools' --quasi, which has no default elsewhere)
    "_studies.butterfly.kind",
    "_studies.dynamical_butterfly.kind",
}


def _is_literal(node):
    """A number or word written in the source (or a list or tuple holding one); not None, True or False."""
    if isinstance(node, ast.Constant):
        return node.value is not None and not isinstance(node.value, bool)
    if isinstance(node, (ast.List, ast.Tuple)):
        return any(_is_literal(e) for e in node.elts)
    if isinstance(node, ast.UnaryOp):
        return _is_literal(node.operand)
    return False


def _literal_defaults():
    found = set()
    for path in sorted(PACKAGE.glob("*.py")):
        for node in ast.parse(path.read_text()).body:
            if not isinstance(node, ast.FunctionDef) or node.name.startswith("_"):
                continue
            a = node.args
            positional = a.posonlyargs + a.args
            pairs = list(zip(positional[len(positional) - len(a.defaults):], a.defaults))
            pairs += [(arg, d) for arg, d in zip(a.kwonlyargs, a.kw_defaults) if d is not None]
            found |= {f"{path.stem}.{node.name}.{arg.arg}" for arg, d in pairs
                      if arg.arg != "threads" and _is_literal(d)}
    return found


def test_no_new_literal_default():
    new = _literal_defaults() - STILL_LITERAL
    assert not new, f"defaults written in Python: take them from the C++ config or table instead: {sorted(new)}"


def test_the_list_of_literals_left_is_current():
    paid = STILL_LITERAL - _literal_defaults()
    assert not paid, f"no longer literal: remove from STILL_LITERAL: {sorted(paid)}"


def test_the_scan_sees_a_literal():
    tree = ast.parse("def f(a, *, b=2, c=None, d=X.y, e=(1.0, 2.0)): pass").body[0].args
    assert [_is_literal(d) for d in tree.kw_defaults] == [True, False, False, True]
