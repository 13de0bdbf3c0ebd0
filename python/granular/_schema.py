"""Keyword signatures made from the library's parameter tables: one row of a table is one keyword, named
as the library's front ends name it, with the C++ struct's own default and the row's help as its docstring
line. A row added to a table in lib/ reaches a Python function's signature, its help() and its checks
without a line written here."""
import inspect
import math
import numbers
import warnings


def _python_default(value):
    """A C++ default as a Python keyword shows it: an empty text or list, or a NaN (the C++ 'none'), is None."""
    return None if value == "" or value == [] or (isinstance(value, float) and math.isnan(value)) else value


class TableKeywords:
    """The keywords of a _core table class (its `_parameters`: name, keyword, help), defaults taken from
    `defaults`, an instance of that class (the job's own defaults, made in C++)."""

    def __init__(self, defaults, only=None, skip=()):
        self._cls = type(defaults)
        rows = [row for row in self._cls._parameters if hasattr(defaults, row[0])]  # rows with a field
        self._rows = [row for row in rows if (only is None or row[0] in only) and row[0] not in skip]
        self._defaults = defaults
        self.names = [keyword for _, keyword, _ in self._rows]
        # former keywords of these rows (renamed; taken for one more minor version with a FutureWarning)
        self.formerly = {old: new for old, new in getattr(self._cls, "_formerly", {}).items() if new in self.names}

    def parameters(self):
        """inspect.Parameter (keyword-only) per row, in the table's order."""
        return [inspect.Parameter(keyword, inspect.Parameter.KEYWORD_ONLY,
                                  default=_python_default(getattr(self._defaults, name)))
                for name, keyword, _ in self._rows]

    def doc(self, indent="    "):
        """One docstring line per row: 'keyword: help (default ...)'."""
        lines = []
        for name, keyword, help_text in self._rows:
            default = _python_default(getattr(self._defaults, name))
            lines.append(f"{indent}{keyword}: {help_text} (default {default!r})")
        return "\n".join(lines)

    def make(self, given):
        """A new instance of the table class: its defaults, with the rows of `given` (keyword: value) set.
        Integer fields take whole floats (N=1e6); None sets a text field to none. Raises ValueError
        naming the keyword of a value of the wrong kind."""
        out = self._cls()
        for name, keyword, _ in self._rows:
            setattr(out, name, getattr(self._defaults, name))
        return self.set(out, given)

    def set(self, out, given):
        """`out` (an instance of the table class) with the rows of `given` (keyword: value) set, as make()."""
        for name, keyword, _ in self._rows:
            if keyword not in given:
                continue
            value, current = given[keyword], getattr(self._defaults, name)
            if value is None and isinstance(current, str):
                value = ""
            elif value is None and isinstance(current, list):
                value = []  # a window or list that may be none
            elif value is None and isinstance(current, float) and math.isnan(current):
                value = math.nan  # a number that may be none
            elif isinstance(current, str) and isinstance(value, numbers.Real) and not isinstance(value, bool):
                value = repr(float(value))  # a number where the tools take a text (ratio=1.5)
            elif isinstance(current, bool):
                value = bool(value)
            elif isinstance(current, int) and isinstance(value, numbers.Real) and not isinstance(value, bool):
                if not math.isfinite(value) or value != math.floor(value):
                    raise ValueError(f"{keyword} {value!r}: must be a whole number")
                value = int(value)
            try:
                setattr(out, name, value)
            except TypeError:
                raise ValueError(f"{keyword} {value!r}: expected {type(current).__name__}") from None
        return out


def with_keywords(function, tables, doc_heading, first=False, after=None):
    """`function` (taking **keywords) given the signature of its own parameters followed by the keywords of
    `tables` (TableKeywords), and a docstring section listing them: what help() and inspect show. The keywords go
    where users look for them (chain, kick, dynamics, outputs, run): `first` before the function's keyword-only
    parameters (after its positional ones), `after` right after the parameter of that name."""
    own = [p for p in inspect.signature(function).parameters.values() if p.kind != inspect.Parameter.VAR_KEYWORD]
    made = [p for table in tables for p in table.parameters()]
    if first:
        at = len([p for p in own if p.kind != inspect.Parameter.KEYWORD_ONLY])
    elif after is not None:
        at = [p.name for p in own].index(after) + 1
    else:
        at = len(own)
    function.__signature__ = inspect.Signature(own[:at] + made + own[at:])
    function.__doc__ = (function.__doc__ or "") + f"\n\n    {doc_heading}:\n" + "\n".join(t.doc() for t in tables)
    return function


def split_keywords(keywords, tables, function):
    """`keywords` (a dict) split by table; a keyword that no table takes is a TypeError naming it, as Python
    says of any unknown keyword. A former keyword of a row is taken as the row's (a FutureWarning says so)."""
    known = {name for table in tables for name in table.names}
    formerly = {old: new for table in tables for old, new in table.formerly.items()}
    keywords = dict(keywords)
    for old in [k for k in keywords if k in formerly and k not in known]:
        new = formerly[old]
        if new in keywords:
            raise TypeError(f"{function}() got both '{old}' and '{new}' (the same keyword, renamed)")
        warnings.warn(f"{function}: keyword '{old}' is deprecated: use '{new}' (the old spelling goes in the next "
                      "minor version)", FutureWarning, stacklevel=3)
        keywords[new] = keywords.pop(old)
    for keyword in keywords:
        if keyword not in known:
            raise TypeError(f"{function}() got an unexpected keyword argument '{keyword}'")
    return [{k: v for k, v in keywords.items() if k in table.names} for table in tables]
