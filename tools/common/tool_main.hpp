#pragma once
// What every tool shares: option parsing errors and library exceptions become one line on
// stderr and an exit code (2 bad input, 1 I/O, 3 numerical failure, 130 interrupted: the
// message says how to resume); --help and --version exit 0. The body only runs after every
// option parsed. Library errors name parameters in the library's vocabulary (`time_step`); here
// they are told in the flag the user typed (`--dt`). A library table of parameters becomes
// options by add_parameters.
#include <algorithm>
#include <cstdio>
#include <functional>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include <CLI/CLI.hpp>

#include "granular/blas_library.hpp"
#include "granular/code_identity.hpp"
#include "granular/error.hpp"
#include "granular/io/nearest_word.hpp"
#include "granular/io/output_claim.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/io/shell_quote.hpp"
#include "granular/parameter_names.hpp"
#include "granular/parameter_table.hpp"

namespace granular::tool {

enum ExitCode { ok = 0, io_failure = 1, bad_input = 2, numerical_failure = 3, interrupted = 130 };

/// The command that continues an interrupted run: argv as typed, shell-quoted, with --resume
/// (added if absent) and without --fresh.
inline std::string resume_command(int argc, char** argv) {
  std::vector<std::string> words;
  std::copy_if(argv, argv + argc, std::back_inserter(words), [](std::string_view w) { return w != "--fresh"; });
  if (std::find(words.begin(), words.end(), "--resume") == words.end()) words.push_back("--resume");
  return shell_command(words);
}

inline void describe_common(CLI::App& app) {
  // The BLAS is resolved when the process starts (Debian's alternatives), so --version asks it.
  app.set_version_flag("--version", [] {
    return std::string("granular ") + GRANULAR_VERSION + " (commit " + code_commit() + ")\nBLAS: " + blas_library();
  });
  app.get_formatter()->column_width(34);
  app.footer("Physics and units: docs/physics.md (installed to share/doc/granular/physics.md)");
}

/// Prints each of `warnings` on stderr as "warning: …", the empty ones skipped; says whether one was.
inline bool warn(const std::vector<std::string>& warnings) {
  bool any = false;
  for (const std::string& w : warnings)
    if (!w.empty()) {
      std::fprintf(stderr, "warning: %s\n", w.c_str());
      any = true;
    }
  return any;
}

/// An option whose --help shows its default.
template <class T>
CLI::Option* add_option(CLI::App& app, const std::string& name, T& value, const std::string& description) {
  return app.add_option(name, value, description)->capture_default_str();
}

/// An integer option that also takes scientific notation (--N 1e7), rejecting non-integers (and
/// negatives for an unsigned one).
template <class Integer>
CLI::Option* add_integer(CLI::App& app, const std::string& name, Integer& value, const std::string& description) {
  const auto digits = [name](std::string& text) -> std::string {
    try {
      // CLI11 would wrap a negative into an unsigned field (-1 as 2^64 - 1): refused, naming the option.
      if (std::is_unsigned_v<Integer> && text.find_first_not_of(" \t") != std::string::npos &&
          text[text.find_first_not_of(" \t")] == '-')
        throw InvalidInput(name, " " + text + ": must be >= 0");
      text = integer_digits(text, name);
    } catch (const InvalidInput& e) {
      return e.what();
    }
    return {};
  };
  return add_option(app, name, value, description)->transform(CLI::Validator(digits, "", "integer notation"));
}

/// The option that stands for a library parameter by the usual rule: "--" and its front-end
/// word, '_' as '-' (`time_step` → --dt, `fit_step` → --fit-step).
inline std::string option_name(const std::string& word) {
  std::string flag = "--" + word;
  std::replace(flag.begin() + 2, flag.end(), '_', '-');
  return flag;
}

/// What a tool takes of a parameter table: `only` these (none: all) but `except` (parameters it
/// does not take); `flags` names the flag for a parameter where the usual rule is wrong.
struct Shown {
  std::set<std::string> only{}, except{};
  std::map<std::string, std::string> flags{};
};

/// Registers an option for every row of `table` (parameter_table.hpp) that is shown, bound to its
/// field of `o`, or read by its text form (Parameter::text) as the command line is parsed: a flag
/// for a bool, an integer that takes scientific notation for a long long or unsigned long, a
/// comma list for a vector, a number or word otherwise; its --help line is the row's help, each parameter it names told
/// as this tool's flag. Returns them by parameter name.
template <class Choices>
std::map<std::string, CLI::Option*> add_parameters(CLI::App& app, Choices& o, const ParameterTable<Choices>& table,
                                                   const Shown& shown = {}) {
  std::map<std::string, CLI::Option*> options;
  for (const Parameter<Choices>& p : table) {
    if ((!shown.only.empty() && !shown.only.contains(p.name)) || shown.except.contains(p.name)) continue;
    if (p.field.index() == 0 && !p.text) continue;
    const std::string flag = option_name(word_of(p)),
                      help = tell_parameters(p.help, [&](const std::string&named) {
                        const auto it = shown.flags.find(named);
                        return it != shown.flags.end() ? it->second : option_name(front_end_word(named));
                      });
    // The option under `name`: a flag, an integer, a number or word, or read by the text form.
    const auto add_as = [&](const std::string& name, const std::string& description) {
      return std::visit(
          [&]<class Field>(const Field& field) -> CLI::Option* {
            if (p.text)
              return app.add_option_function<std::string>(
                  name, [&o, read = p.text->read](const std::string& text) { read(o, text); }, description);
            if constexpr (std::is_same_v<Field, std::monostate>) return nullptr;
            else if constexpr (std::is_same_v<Field, Ref<Choices, bool>>)
              return app.add_flag(name, field(o), description);
            else if constexpr (std::is_same_v<Field, Ref<Choices, int>> ||
                               std::is_same_v<Field, Ref<Choices, long long>> ||
                               std::is_same_v<Field, Ref<Choices, unsigned long>>)
              return add_integer(app, name, field(o), description);
            else if constexpr (std::is_same_v<Field, Ref<Choices, std::vector<double>>> ||
                               std::is_same_v<Field, Ref<Choices, std::vector<long>>>)
              return app.add_option(name, field(o), description)->delimiter(',');  // a,b,c (or a b c)
            else return app.add_option(name, field(o), description);
          },
          p.field);
    };
    CLI::Option* option = add_as(flag, help);
    for (const std::string& word : p.former_words) {  // taken, out of --help, with a note when used
      const std::string note = deprecation_note(option_name(word), flag);
      add_as(option_name(word), "")
          ->group("")
          ->check(CLI::Validator(
              [note](const std::string&) {
                warn({note});
                return std::string();
              },
              ""));
    }
    if (p.shows_default && p.text) option->default_str(p.text->write(o));
    else if (p.shows_default && !std::holds_alternative<Ref<Choices, bool>>(p.field)) option->capture_default_str();
    options[p.name] = option;
  }
  return options;
}

/// The flag of `app` that a library parameter stands for ("" when none: the message is kept).
inline std::string flag_for(const CLI::App& app, const std::string& parameter,
                            const std::map<std::string, std::string>& overrides) {
  if (parameter.empty() || parameter.starts_with("--")) return parameter;
  if (auto it = overrides.find(parameter); it != overrides.end()) return it->second;
  // The front end's word first (--F0, --near): a former spelling may still be a hidden option.
  if (const std::string word = option_name(front_end_word(parameter)); app.get_option_no_throw(word)) return word;
  if (const std::string flag = option_name(parameter); app.get_option_no_throw(flag)) return flag;
  return "";
}

/// `message` with every library parameter it names (`max_energy_error`) told as the flag of `app`
/// it stands for (`--max-energy-error`); other words are kept.
inline std::string flags_in(const CLI::App& app, const std::string& message,
                            const std::map<std::string, std::string>& overrides) {
  return rename_parameters(message, [&](const std::string& word) { return flag_for(app, word, overrides); });
}

/// The option of `app` nearest `typed` by edit distance (for "did you mean"), or "".
inline std::string nearest_option(const CLI::App& app, const std::string& typed) {
  std::vector<std::string> flags;
  for (const CLI::Option* o : app.get_options())
    for (const std::string& name : o->get_lnames()) flags.push_back("--" + name);
  return nearest_word(typed.substr(0, typed.find('=')), flags);  // further than 2 edits is no suggestion
}

/// Parses argv into `app`, then runs `body`, mapping every failure to a message and exit code.
/// `overrides` maps library parameters to this tool's flags where the usual rule (parameter
/// `time_step` → `--time-step` if the tool has it, else a common synonym such as `--dt`) is wrong.
inline int run(CLI::App& app, int argc, char** argv, const std::function<void()>& body,
               const std::map<std::string, std::string>& overrides = {}) {
  const std::string name = app.get_name();
  for (int i = 1; i < argc; ++i)
    if (argv[i][0] == '\0') {  // CLI11 would read "" as 0 for numbers
      std::fprintf(stderr, "%s: error: %s: empty value\n", name.c_str(), i > 1 ? argv[i - 1] : "argument");
      return bad_input;
    }
  try {  // a text form (Parameter::text) may refuse its value while the command line is parsed
    app.parse(argc, argv);
    body();
    return ok;
  } catch (const CLI::Success& e) {  // --help, --help-all, --version
    return app.exit(e);
  } catch (const CLI::ExtrasError& e) {
    std::string hint;
    for (const std::string& extra : app.remaining())
      if (extra.starts_with("-")) {
        const std::string near = nearest_option(app, extra);
        if (!near.empty()) hint = " (did you mean " + near + "?)";
        break;
      }
    std::fprintf(stderr, "%s: error: %s%s (see %s --help)\n", name.c_str(), e.what(), hint.c_str(), name.c_str());
    return bad_input;
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "%s: error: %s (see %s --help)\n", name.c_str(), e.what(), name.c_str());
    return bad_input;
  } catch (const InvalidInput& e) {
    const std::string flag = flag_for(app, e.parameter(), overrides);
    const auto told = [&](const std::string& p) {  // parameters the message names in `backticks`
      const std::string named = flag_for(app, p, overrides);
      return named.empty() ? p : named;
    };
    const std::string message =
        flag.empty() ? tell_parameters(e.what(), told) : flag + tell_parameters(e.problem(), told);
    std::fprintf(stderr, "%s: error: %s\n", name.c_str(), message.c_str());
    return bad_input;
  } catch (const IoError& e) {
    std::fprintf(stderr, "%s: I/O error: %s\n", name.c_str(), e.what());
    return io_failure;
  } catch (const NumericalError& e) {
    std::fprintf(stderr, "%s: numerical failure: %s\n", name.c_str(), flags_in(app, e.what(), overrides).c_str());
    return numerical_failure;
  } catch (const Cancelled&) {  // a clean stop: every finished realization is in the checkpoint
    std::fprintf(stderr, "%s: interrupted; the finished realizations are kept. To continue:\n%s\n", name.c_str(),
                 resume_command(argc, argv).c_str());
    return interrupted;
  } catch (const ClaimFailedOnRoot& e) {  // rank 0 has said why
    return e.refused ? bad_input : io_failure;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: error: %s\n", name.c_str(), e.what());
    return numerical_failure;
  }
}

}  // namespace granular::tool
