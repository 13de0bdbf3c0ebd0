// libFuzzer target: the Python module's argument conversion — granular/_arguments.py (arrays and
// number lists) and granular._core's _size, with the C++ they call (python/src/support.cpp: the
// range syntax, the number format, library errors as ValueErrors naming the keyword). Any Python
// literal (lists, nested lists, strings, bytes, floats, huge ints, None, dicts …) given where the
// module expects numbers, a number list or a size must come back as a ValueError (a TypeError for
// a size that is no int) or as finite values of the right kind; never a crash, a sanitizer report
// or another exception. The input is read with ast.literal_eval in an embedded interpreter, where
// granular._core is this file's module of the same helpers (bind_errors) and granular/_arguments.py
// is imported from the source tree.
#include <cmath>
#include <cstdint>
#include <string>

#include <pybind11/embed.h>

#include "bindings.hpp"

namespace py = pybind11;

PYBIND11_EMBEDDED_MODULE(granular_fuzzed_core, m) { granular::python::bind_errors(m); }

namespace {
/// granular._arguments, its `from . import _core` answered by the embedded module.
py::module_ arguments() {
  const py::module_ sys = py::module_::import("sys");
  py::module_ package = py::module_::import("types").attr("ModuleType")("granular");
  package.attr("__path__") = py::make_tuple(GRANULAR_SOURCE_DIR "/python/granular");
  const py::module_ core = py::module_::import("granular_fuzzed_core");
  package.attr("_core") = core;
  sys.attr("modules")["granular"] = package;
  sys.attr("modules")["granular._core"] = core;
  return py::module_::import("granular._arguments");
}

/// A list of finite floats, or a ValueError (`also`: or that Python exception too); else a trap.
template <class Convert>
void expect_numbers(Convert convert, const py::object& value, PyObject* also = nullptr) {
  py::object numbers;
  try {
    numbers = convert(value);
  } catch (const py::error_already_set& e) {
    if (e.matches(PyExc_ValueError) || (also && e.matches(also))) return;
    __builtin_trap();  // another exception: the conversion has a hole
  }
  if (numbers.is_none()) return;  // _size: a valid size
  if (!py::isinstance<py::list>(numbers)) __builtin_trap();
  for (const py::handle& x : numbers)
    if (!py::isinstance<py::float_>(x) || !std::isfinite(x.cast<double>())) __builtin_trap();
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static py::scoped_interpreter interpreter;
  static const py::module_ converters = arguments();
  static const py::object literal_eval = py::module_::import("ast").attr("literal_eval");
  static const py::object numpy_array = py::module_::import("numpy").attr("array");
  static const py::object double_vector = converters.attr("double_vector");
  static const py::object number_list = converters.attr("number_list");
  static const py::object checked_size = converters.attr("_core").attr("_size");
  const std::string text(reinterpret_cast<const char*>(data), size);
  py::object value;
  try {
    value = literal_eval(py::str(py::bytes(text).attr("decode")("utf-8", "replace")));
  } catch (const py::error_already_set&) {
    return 0;  // not a Python literal: nothing reaches the converters
  }
  for (const py::object& v : {value, [&]() -> py::object {
                                try {
                                  return numpy_array(value);  // the same data as an array (any dtype)
                                } catch (const py::error_already_set&) {
                                  return py::none();
                                }
                              }()}) {
    expect_numbers([&](const py::object& x) { return double_vector(x, "x"); }, v);
    expect_numbers([&](const py::object& x) { return number_list(x, "xi", 0.01); }, v);
    // A size: an int checked against its bounds; anything else pybind11's TypeError.
    expect_numbers(
        [&](const py::object& x) {
          checked_size(x, "N", 2);
          return py::object(py::none());
        },
        v, PyExc_TypeError);
  }
  return 0;
}
