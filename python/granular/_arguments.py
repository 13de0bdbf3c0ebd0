"""Numbers from the keyword arguments: 1-D arrays of floats and number lists, each error a ValueError
naming the keyword (the library's message format, "<keyword>: <problem>").

tests/fuzz/python_arguments_fuzz.cpp runs these on arbitrary Python literals in an embedded
interpreter, with the parts of granular._core they call (python/src/support.cpp)."""
import numpy as np

from . import _core


def double_vector(values, keyword, require_finite=True):
    """A list of floats from any 1-D array-like (lists, other dtypes, non-contiguous views). ValueError
    naming `keyword` on a string, a non-numeric input, another shape or (when `require_finite`)
    NaN/infinity."""
    if isinstance(values, (str, bytes)):
        raise ValueError(f"{keyword}: expected numbers (an array or a sequence), not a string")
    try:
        array = np.asarray(values, dtype=np.float64)
    except Exception:  # whatever NumPy cannot make floats of: words, ragged lists, ints beyond a double
        raise ValueError(f"{keyword}: expected an array of numbers") from None
    if array.ndim != 1:
        raise ValueError(f"{keyword}: expected a 1-D array, got shape ({', '.join(map(str, array.shape))})")
    if require_finite:
        bad = np.flatnonzero(~np.isfinite(array))
        if bad.size:
            i = int(bad[0])
            raise ValueError(f"{keyword}: entry {i} is {_core._format_number(array[i])} (must be finite)")
    return array.tolist()


def number_list(values, keyword, default_step):
    """A list of floats: one number, a sequence / array (double_vector), or a string in the tools'
    range syntax ("0.1:1", "0.1:1:0.05", "0.2,0.5,0.8") with the tools' default step."""
    if isinstance(values, str):
        return _core._parse_numbers(values, keyword, default_step)
    if isinstance(values, (float, int)):
        try:
            value = float(values)
        except OverflowError:  # an int beyond any double (found by tests/fuzz/python_arguments_fuzz)
            raise ValueError(f"{keyword}: the integer is too large for a floating-point number") from None
        return [_core._finite(value, keyword)]
    return double_vector(values, keyword)
