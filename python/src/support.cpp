// The shared helpers of bindings.hpp: conversions at the boundary and the long-run driver.
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <regex>

#include "bindings.hpp"
#include "granular/blas_library.hpp"
#include "granular/code_identity.hpp"
#include "granular/ensemble/progress_meter.hpp"
#include "granular/error.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/number_format.hpp"
#include "granular/parallel/mpi_context.hpp"
#include "granular/parameter_names.hpp"
#include "granular/parameter_table.hpp"

namespace granular::python {

namespace {
/// The Python keyword a library parameter name stands for (`precompression` → `F0`, `time_step`
/// → `dt`, a legacy flag `--force-law` → `force_law`); keywords are the tools' option names.
std::string keyword_of(const std::string& parameter) {
  // Library names that are not the keyword itself (the keywords are the tools' option names):
  // Python's own, beyond the words every front end uses (front_end_word).
  static const std::map<std::string, std::string> synonyms{{"lo_khz", "window"},
                                                           {"hi_khz", "window"},
                                                           {"selection", "near"},
                                                           {"lyapunov", "mle"}};
  std::string name = parameter;
  if (name.starts_with("--")) {  // a legacy message naming a flag: --force-law → force_law
    name = name.substr(2);
    for (char& c : name)
      if (c == '-') c = '_';
    return name;
  }
  if (auto it = synonyms.find(name); it != synonyms.end()) return it->second;
  return front_end_word(name);
}

/// Messages written in flag vocabulary ("--T 0.5: …", "… beyond --T 0.01") told in keywords.
std::string keywords_in(const std::string& message) {
  static const std::regex flag(R"(--([A-Za-z][A-Za-z0-9-]*))");
  std::string out;
  auto begin = std::sregex_iterator(message.begin(), message.end(), flag);
  std::size_t last = 0;
  for (auto it = begin; it != std::sregex_iterator(); ++it) {
    out += message.substr(last, static_cast<std::size_t>(it->position()) - last);
    out += keyword_of(it->str());
    last = static_cast<std::size_t>(it->position() + it->length());
  }
  return out + message.substr(last);
}
}  // namespace

void bad_value(const std::string& keyword, const std::string& problem) { throw InvalidInput(keyword, problem); }

std::size_t checked_size(long long value, const char* keyword, long long lo, long long hi) {
  if (value < lo) bad_value(keyword, " " + std::to_string(value) + ": must be >= " + std::to_string(lo));
  if (value > hi) bad_value(keyword, " " + std::to_string(value) + ": must be <= " + std::to_string(hi));
  return static_cast<std::size_t>(value);
}

double finite(double value, const char* keyword) {
  if (!std::isfinite(value)) bad_value(keyword, " " + format_number(value) + ": must be finite");
  return value;
}

void bind_errors(py::module_& m) {
  // The checks the keyword functions in granular/*.py share with the bindings (same messages).
  m.def("_size", &checked_size, py::arg("value"), py::arg("keyword"), py::arg("lo") = 0,
        py::arg("hi") = 100000000000000000LL);
  m.def("_finite", &finite);
  m.def("_parse_numbers", [](const std::string& text, const std::string& keyword, double default_step) {
    return parse_number_list(text, keyword, default_step);  // the tools' range syntax (granular/_arguments.py)
  });
  m.def("_format_number", [](double x) { return format_number(x); });
  static py::exception<NumericalError> numerical(m, "NumericalError", PyExc_RuntimeError);  // doc: __init__.py
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidInput& e) {
      const std::string message =  // other parameters named in `backticks` told as keywords too
          e.parameter().empty() ? keywords_in(tell_parameters(e.what(), keyword_of))
                                : keyword_of(e.parameter()) + keywords_in(tell_parameters(e.problem(), keyword_of));
      PyErr_SetString(PyExc_ValueError, message.c_str());
    } catch (const IoError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const NumericalError& e) {
      PyErr_SetString(numerical.ptr(), e.what());
    } catch (const Cancelled&) {
      PyErr_SetString(PyExc_KeyboardInterrupt,
                      "interrupted (Ctrl-C) after the work in flight; a run with checkpoint= keeps its finished "
                      "realizations there: call it again with resume=True to continue");
    }
  });
}

// --- arrays ------------------------------------------------------------------------------------

py::array_t<double> view(const std::vector<double>& data, const py::handle& owner) {
  py::array_t<double> a({data.size()}, {sizeof(double)}, data.data(), owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

// --- metadata ------------------------------------------------------------------------------------

py::object to_python(const nlohmann::json& value) {
  // The library's JSON text read by Python's json module: the same dict the tools' files hold.
  return py::module_::import("json").attr("loads")(value.dump());
}

py::object metadata(const std::string& function, const nlohmann::json& described) {
  nlohmann::json meta = {{"function", "granular." + function},
                         {"version", code_version()},
                         {"commit", code_commit()},
                         {"blas", blas_library()}};
  meta.update(described);
  return to_python(meta);
}

Disorder disorder_of(const std::string& name, const char* keyword) {
  try {
    return parse_disorder(name);
  } catch (const InvalidInput&) {
    bad_value(keyword, " '" + name + "': expected h, A, RDM1 or RDM2");
  }
}

// --- long runs -----------------------------------------------------------------------------------

namespace {
template <class F>
struct Finally {  ///< calls f when it goes out of scope
  F f;
  ~Finally() { f(); }
};
template <class F>
Finally(F) -> Finally<F>;  // clang before 17 deduces no aggregate's arguments (the fuzzers build this with clang)
}  // namespace

void run_long(const std::string& label, std::size_t total, const PyRun& options,
              const std::function<void(const RunOptions&)>& work) {
  struct Shared {  // whether `work` may start (run_long has not returned) and whether it runs
    std::mutex mutex;
    std::condition_variable stopped;
    bool open = true, running = false;
  };
  auto shared = std::make_shared<Shared>();
  auto meter = std::make_shared<ProgressMeter>(total, label, 0);  // silent: the bar is drawn from Python
  auto cancel = std::make_shared<std::atomic<bool>>(false);
  validate(options);
  RunOptions run = options;
  run.progress = meter.get();
  run.cancelled = [cancel] { return cancel->load(std::memory_order_relaxed); };
  const py::cpp_function call([&, shared] {
    if (std::lock_guard lock(shared->mutex); !shared->open) return;  // too late: run_long has returned
    else shared->running = true;
    const Finally stop{[&s = *shared] {
      std::lock_guard lock(s.mutex);
      s.running = false;
      s.stopped.notify_all();
    }};
    py::gil_scoped_release release;
    work(run);
  });
  // However this returns (a KeyboardInterrupt anywhere in the Python driver included), `work` is
  // told to stop and waited for before what it uses goes out of scope.
  const Finally close{[&] {
    cancel->store(true);
    py::gil_scoped_release release;
    std::unique_lock lock(shared->mutex);
    shared->open = false;
    shared->stopped.wait(lock, [&] { return !shared->running; });
  }};
  // Under mpirun the ranks talk MPI from the thread that started it: stay on this thread.
  if (MpiContext::instance().size() > 1) {
    call();
    return;
  }
  // What a Ctrl-C says: the call that continues the run, as the tools print the command that does.
  const std::string function = "granular." + label;
  const bool resumable = label == "transport" || label == "exponent_table";  // the calls that take checkpoint=
  const std::string interrupted =
      !options.checkpoint.empty()
          ? "interrupted (Ctrl-C) after the work in flight; the finished realizations are kept in '" +
                options.checkpoint + "'. To continue: call " + function +
                "(...) again with the same arguments and resume=True"
          : "interrupted (Ctrl-C) after the work in flight; nothing was kept" +
                std::string(resumable ? " (no checkpoint=): call " + function +
                                            "(..., checkpoint='run.checkpoint') to keep the finished realizations "
                                            "of a run, and again with resume=True to continue it"
                                      : "; call " + function + "(...) again to run it");
  // granular._progress.run_long: a worker thread, the progress bar and Ctrl-C.
  py::module_::import("granular._progress")
      .attr("run_long")(call, py::cpp_function([meter] { return meter->done(); }),
                        py::cpp_function([cancel] { cancel->store(true); }), label, total, options.progress_bar,
                        interrupted);
}

/// Each warning of the library as a Python RuntimeWarning (the tools print them on stderr).
py::list warn(const std::vector<std::string>& notes) {
  py::list out;
  for (const auto& note : notes) {
    if (note.empty()) continue;  // no warning
    out.append(note);
    if (PyErr_WarnEx(PyExc_RuntimeWarning, note.c_str(), 2) != 0) throw py::error_already_set();
  }
  return out;
}

}  // namespace granular::python
