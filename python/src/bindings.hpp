#pragma once
// What every binding source shares: NumPy arrays in and out, library errors as Python exceptions
// naming the keyword, JSON metadata as dicts, and long runs that release the GIL, show progress
// and stop on Ctrl-C. The binding layer is thin: it converts, checks shapes, calls the library.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <nlohmann/json.hpp>

#include "granular/ensemble/resumed_checkpoint.hpp"
#include "granular/model/chain.hpp"
#include "granular/model/chain_recipe.hpp"
#include "granular/model/disorder.hpp"
#include "granular/model/quasiperiodic.hpp"
#include "granular/model/selected_chain.hpp"
#include "granular/parameter_table.hpp"

namespace granular::python {

namespace py = pybind11;

/// A library config struct as Python fills it: default-constructed (its C++ defaults), with a
/// read-write attribute per member, named by the space-separated `names` in order.
template <class C, class... M>
py::class_<C> config_class(py::module_& m, const char* name, const char* names, M C::*... members) {
  py::class_<C> c(m, name);
  c.def(py::init<>());
  std::istringstream words(names);
  std::string field;
  ((words >> field, c.def_readwrite(field.c_str(), members)), ...);
  return c;
}

/// A config struct whose parameters the library describes in a table (parameter_table.hpp): an
/// attribute per parameter that sets a field, named as the library names it, and `_parameters`:
/// (name, keyword, help) of every row, other parameters in the help told as keywords.
template <class C>
py::class_<C> table_class(py::module_& m, const char* name, const ParameterTable<C>& table) {
  py::class_<C> c(m, name);
  c.def(py::init<>());
  py::list described;
  py::dict formerly;  // a former keyword: the one it now is (deprecated)
  for (const Parameter<C>& p : table) {
    for (const std::string& word : p.former_words) formerly[py::str(word)] = word_of(p);
    std::visit(
        [&]<class Field>(const Field& field) {
          if constexpr (!std::is_same_v<Field, std::monostate>) {
            using T = std::remove_cvref_t<decltype(field(std::declval<C&>()))>;
            c.def_property(
                p.name.c_str(), [field](C& o) { return field(o); }, [field](C& o, const T& v) { field(o) = v; });
          } else if (p.text && p.python_text) {  // a word form over a typed field (an enum): a str attribute
            c.def_property(
                p.name.c_str(), [write = p.text->write](const C& o) { return write(o); },
                [read = p.text->read](C& o, const std::string& v) { read(o, v); });
          }
        },
        p.field);
    described.append(py::make_tuple(p.name, word_of(p), tell_parameters(p.help, front_end_word)));
  }
  c.attr("_parameters") = described;
  c.attr("_formerly") = formerly;
  return c;
}

/// The text form of every row of `table` that has one, written from C's defaults: {name: text}
/// (what the tools' --help shows as the default, Python's keyword default in the same form).
template <class C>
py::dict text_defaults(const ParameterTable<C>& table) {
  py::dict out;
  const C defaults{};
  for (const Parameter<C>& p : table)
    if (p.text && p.text->write) out[py::str(p.name)] = p.text->write(defaults);
  return out;
}

/// A getter and a setter of an enum member spelled as the tools' word (to_string / `parse`).
template <class C, class T>
auto word_getter(T C::*member) {
  return [member](const C& c) { return std::string(to_string(c.*member)); };
}
template <class C, class T, class Parse>
auto word_setter(T C::*member, Parse parse) {
  return [member, parse](C& c, const std::string& word) { c.*member = parse(word); };
}
// --- the binding sources, one per library area -------------------------------------------
void bind_errors(py::module_& m);
void bind_model(py::module_& m);
void bind_linear(py::module_& m);
void bind_studies(py::module_& m);
void bind_dynamics(py::module_& m);
void bind_observers(py::module_& m);
void bind_breathers(py::module_& m);
void bind_crystal(py::module_& m);
void bind_klein_gordon(py::module_& m);

// --- a chain as Python holds it ------------------------------------------------------------
/// A chain with what made it: the bead types (when it has them) and the description the tools
/// write as the "chain" entry of their JSON.
struct PyChain : SelectedChain {
  Configuration types;  ///< empty when built from radii
};

// --- errors ----------------------------------------------------------------------------------
/// Throws InvalidInput(keyword, " <value>: <rule>") — the message format of the library.
[[noreturn]] void bad_value(const std::string& keyword, const std::string& problem);

/// Each warning of the library as a Python RuntimeWarning (the tools print them on stderr);
/// returns them as a list. Empty strings are no warning.
py::list warn(const std::vector<std::string>& notes);
/// A size-like integer keyword: ValueError naming it unless lo ≤ value (≤ hi).
std::size_t checked_size(long long value, const char* keyword, long long lo = 0, long long hi = 100000000000000000LL);
/// A finite float keyword (NaN and infinities rejected, naming it).
double finite(double value, const char* keyword);

// --- arrays ----------------------------------------------------------------------------------
/// A NumPy array that takes over `values` (no copy; freed with the array).
template <class T>
py::array_t<T> to_numpy(std::vector<T>&& values) {
  auto* owner = new std::vector<T>(std::move(values));
  py::capsule base(owner, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>({owner->size()}, {sizeof(T)}, owner->data(), base);
}
template <class T>
py::array_t<T> to_numpy(const std::vector<T>& values) {
  return to_numpy(std::vector<T>(values));
}
/// A read-only view of `data` (n entries) kept alive by `owner` (the Python object holding it).
py::array_t<double> view(const std::vector<double>& data, const py::handle& owner);
/// Read-only attributes of a bound class named by the space-separated `names`, each a read-only
/// view (kept alive by the object) of a vector member of `part(self)` (in order).
template <class Class, class Part, class... M>
Class& views(Class&& c, const char* names, Part part, M... members) {
  using Self = typename std::remove_reference_t<Class>::type;
  std::istringstream words(names);
  std::string field;
  ((words >> field, c.def_property_readonly(field.c_str(),
                                            [part, members](py::object self) {
                                              return view(part(self.cast<const Self&>()).*members, self);
                                            })),
   ...);
  return c;
}
template <class T>
constexpr bool is_number_vector = false;
template <class T>
constexpr bool is_number_vector<std::vector<T>> = std::is_arithmetic_v<T>;
/// A C++ value as Python gets it: a vector of numbers as a NumPy array (taken over when an rvalue;
/// counts and indices as signed integers, so that NumPy arithmetic on them stays integer; bytes as
/// they are), a Python object as it is, the rest as pybind11 casts it.
template <class T>
py::object to_py(T&& value) {
  using V = std::remove_cvref_t<T>;
  if constexpr (is_number_vector<V>) {
    using E = typename V::value_type;
    if constexpr (std::is_unsigned_v<E> && sizeof(E) > 1) {
      return to_numpy(std::vector<long long>(value.begin(), value.end()));
    } else {
      return to_numpy(std::forward<T>(value));
    }
  } else if constexpr (std::is_base_of_v<py::object, V>) {
    return value;
  } else {
    return py::cast(std::forward<T>(value));
  }
}
/// {name: to_py(value)} for the space-separated `names` and the values, in order.
template <class... T>
py::dict fields(const char* names, T&&... values) {
  py::dict out;
  std::istringstream words(names);
  std::string name;
  ((words >> name, out[py::str(name)] = to_py(std::forward<T>(values))), ...);
  return out;
}

/// Read-only attributes of a bound class named by the space-separated `names`, each a member as
/// to_py gives it (in order): a vector of numbers as a NumPy copy, the rest as pybind11 casts it.
template <class Class, class T, class... M>
Class& readonly(Class&& c, const char* names, M T::*... members) {
  std::istringstream words(names);
  std::string field;
  ((words >> field, c.def_property_readonly(field.c_str(), [members](const T& x) { return to_py(x.*members); })), ...);
  return c;
}

// --- metadata ----------------------------------------------------------------------------------
py::object to_python(const nlohmann::json& value);
/// A result's metadata as a dict: {"function": "granular.<function>", "version": …, "blas": …}
/// updated with `described` (the library's describe_… of it, as the tool writes it).
py::object metadata(const std::string& function, const nlohmann::json& described);

// --- parsing the tools' words --------------------------------------------------------------------
/// A disorder by its name; a ValueError naming `keyword` for another word.
Disorder disorder_of(const std::string& name, const char* keyword = "disorder");

// --- long runs ------------------------------------------------------------------------------------
/// How a long call runs (granular._core.RunOptions): the library's run options (their rows, and the
/// checkpoint, "" = none) and whether a progress bar is drawn.
struct PyRun : RunOptions {
  bool progress_bar = false;
  int thread_request() const {  // validated with the other options
    validate(*this);
    return threads;
  }
};
/// Runs `work` with the GIL released on a thread of its own through granular._progress.run_long,
/// which polls for Ctrl-C, draws the progress bar when options.progress_bar, and on KeyboardInterrupt
/// sets the cancellation flag and waits for `work` to stop. `work` gets the library's RunOptions of
/// `options`, with that flag (RunOptions::cancelled) and a silent meter of `total` steps
/// (RunOptions::progress). `work` must not touch Python objects. Library exceptions propagate (as
/// Python exceptions).
void run_long(const std::string& label, std::size_t total, const PyRun& options,
              const std::function<void(const RunOptions&)>& work);

}  // namespace granular::python
