#pragma once
// The JSON beside every CSV (io/run_metadata.hpp), made from a tool's argv: the command line as
// typed, shell-quoted; --quiet silences the final line.
#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "granular/io/run_metadata.hpp"
#include "granular/io/shell_quote.hpp"

namespace granular::tool {

struct Metadata : RunMetadata {
  Metadata(const std::string& tool, int argc, char** argv)
      : RunMetadata(tool, shell_command(std::vector<std::string>(argv, argv + argc)),
                    std::find(argv, argv + argc, std::string_view("--quiet")) != argv + argc) {}
};

}  // namespace granular::tool
