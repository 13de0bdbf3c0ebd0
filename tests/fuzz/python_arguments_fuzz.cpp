// libFuzzer target: the Python module's argument conversion (python/src/support.cpp) — any Python
// literal (lists, nested lists, strings, bytes, floats, huge ints, None, dicts …) given where the
// module expects numbers, a number list or a size must come back as a ValueError
// (InvalidInput) or as finite values of the right kind; never a crash, a sanitizer report or a
// foreign exception. The input is read with ast.literal_eval in an embedded interpreter.
#include <cmath>
#include <cstdint>
#include <string>

#include <pybind11/embed.h>

#include "bindings.hpp"
#include "granular/error.hpp"

namespace py = pybind11;
using namespace granular::python;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static py::scoped_interpreter interpreter;
  static py::object literal_eval = py::module_::import("ast").attr("literal_eval");
  static py::object numpy_array = py::module_::import("numpy").attr("array");
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
    try {
      for (double x : double_vector(v, "x"))
        if (!std::isfinite(x)) __builtin_trap();
    } catch (const granular::InvalidInput&) {
    }
    try {
      for (double x : number_list(v, "xi", 0.01))
        if (!std::isfinite(x)) __builtin_trap();
    } catch (const granular::InvalidInput&) {
    }
    try {
      if (py::isinstance<py::int_>(v)) checked_size(v.cast<long long>(), "N", 2);
    } catch (const granular::InvalidInput&) {
    } catch (const py::cast_error&) {  // an int beyond long long: pybind11's own TypeError
    }
  }
  return 0;
}
