#pragma once
// Chains loaded from text files: one value per line, '#' starts a comment, blank lines skipped.
#include <string>
#include <vector>

#include "granular/model/disorder.hpp"

namespace granular {

/// One bead type (1 or 2) per line. Throws InvalidInput (file name and line) or IoError.
Configuration read_configuration_file(const std::string& path);

/// One radius in metres per line (finite, > 0). Throws InvalidInput or IoError. With `warnings`,
/// appends "FILE:LINE: radius R m is outside ..." for every radius outside the plausible range of
/// bead_distribution.hpp (0.1 mm – 10 cm; 4.76 is likely millimetres typed as metres).
std::vector<double> read_radii_file(const std::string& path, std::vector<std::string>* warnings = nullptr);

/// One displacement in metres per line (finite, any sign): a state's u_n, bead by bead. Throws
/// InvalidInput (naming `parameter` when the file cannot be read, else the file and line) or IoError.
std::vector<double> read_displacements_file(const std::string& path, const char* parameter);

/// The same parsers on text already in memory (what the fuzz targets drive).
Configuration parse_configuration_text(const std::string& text, const std::string& source);
std::vector<double> parse_radii_text(const std::string& text, const std::string& source,
                                     std::vector<std::string>* warnings = nullptr);
std::vector<double> parse_displacements_text(const std::string& text, const std::string& source);

/// The warning for an implausible radius r [m] from `where` (a file and line, or an option).
std::string implausible_radius_warning(const std::string& where, double r);

}  // namespace granular
