#pragma once
// What every tool shares: option parsing errors and library exceptions become one line on
// stderr and an exit code (2 bad input, 1 I/O, 3 numerical failure); --help and --version
// exit 0. The body only runs after every option parsed.
#include <cstdio>
#include <functional>
#include <string>

#include <CLI/CLI.hpp>

#include "granular/error.hpp"

namespace granular::tool {

enum ExitCode { ok = 0, io_failure = 1, bad_input = 2, numerical_failure = 3 };

inline void describe_common(CLI::App& app) {
  app.set_version_flag("--version", std::string("granular ") + GRANULAR_VERSION);
  app.get_formatter()->column_width(34);
  app.footer("Physics and units: docs/physics.md (installed to share/doc/granular/physics.md)");
}

/// Parses argv into `app`, then runs `body`, mapping every failure to a message and exit code.
inline int run(CLI::App& app, int argc, char** argv, const std::function<void()>& body) {
  const std::string name = app.get_name();
  for (int i = 1; i < argc; ++i)
    if (argv[i][0] == '\0') {  // CLI11 would read "" as 0 for numbers
      std::fprintf(stderr, "%s: error: %s: empty value\n", name.c_str(), i > 1 ? argv[i - 1] : "argument");
      return bad_input;
    }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "%s: error: %s (see %s --help)\n", name.c_str(), e.what(), name.c_str());
    return bad_input;
  }
  try {
    body();
    return ok;
  } catch (const InvalidInput& e) {
    std::fprintf(stderr, "%s: error: %s\n", name.c_str(), e.what());
    return bad_input;
  } catch (const IoError& e) {
    std::fprintf(stderr, "%s: I/O error: %s\n", name.c_str(), e.what());
    return io_failure;
  } catch (const NumericalError& e) {
    std::fprintf(stderr, "%s: numerical failure: %s\n", name.c_str(), e.what());
    return numerical_failure;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: error: %s\n", name.c_str(), e.what());
    return numerical_failure;
  }
}

/// Output prefix: "out.csv" → "out" so that "out.json" sits beside it.
inline std::string json_path_for(const std::string& csv_path) {
  const auto dot = csv_path.rfind('.');
  const auto slash = csv_path.rfind('/');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (has_ext ? csv_path.substr(0, dot) : csv_path) + ".json";
}

}  // namespace granular::tool
