// Every job's options are made from its tables: each row a tool takes is a flag of its --help,
// with the row's own help (a parameter in backticks told as its flag), so that a tool's --help
// cannot drift from the table that Python's signatures, validation and the JSON are made of too.
// The rows a tool does not take, or words in its own way, are listed beside it.
#include <cstdio>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "granular/case/chain_choices.hpp"
#include "granular/case/transport_parameters.hpp"
#include "granular/crystal/crystal_case.hpp"
#include "granular/klein_gordon/klein_gordon_case.hpp"
#include "granular/linear/mode_selection_choices.hpp"
#include "granular/linear/spectrum_parameters.hpp"
#include "granular/orbits/breather_parameters.hpp"
#include "granular/parameter_names.hpp"
#include "granular/study/butterfly.hpp"
#include "granular/study/correlation_study.hpp"
#include "granular/study/crystal_ipr_map.hpp"
#include "granular/study/dynamical_butterfly.hpp"
#include "granular/study/exponent_choices.hpp"
#include "granular/study/ipr_map.hpp"
#include "tool_runner.hpp"

namespace granular::testing {
namespace {

/// Each row of `table` but `skip` is a flag of `tool`'s --help followed (on its line) by the row's help.
template <class C>
void expect_rows_in_help(const std::string& tool, const ParameterTable<C>& table,
                         const std::set<std::string>& skip = {}) {
  const std::string help = tool_help(tool);
  ASSERT_FALSE(help.empty()) << tool;
  for (const Parameter<C>& p : table) {
    if (skip.contains(p.name)) continue;
    const std::string flag = flag_for(p.name);
    std::string needle = "  ";  // (append: GCC 12 warns falsely of overlap in a chain of +)
    needle.append(flag).append(" ");
    const std::size_t at = help.find(needle);
    ASSERT_NE(at, std::string::npos) << tool << ": " << flag << " is not in --help";
    const std::string entry = help.substr(at, help.find("\n  -", at + 1) - at);
    const std::string told = tell_parameters(p.help, flag_for);
    EXPECT_NE(entry.find(told.substr(0, 40)), std::string::npos) << tool << " " << flag << ": " << entry;
  }
}

TEST(HelpFromTables, EveryRowATakesIsAFlagWithTheRowsHelp) {
  // spreading: the fit window as --fit (its rows' shorthand); --deviation-samples told for --deviation
  const std::set<std::string> window{"fit_begin", "fit_end"};
  std::set<std::string> spreading = window;
  spreading.insert("deviation_samples");
  expect_rows_in_help("spreading", transport_parameters(), spreading);
  expect_rows_in_help("spreading", kicked_case_parameters());
  expect_rows_in_help("spreading", mode_kick_parameters());
  // exponents: an ensemble of cases (no one run's tangent outputs), its own table and chain rows
  std::set<std::string> exponents = spreading;
  exponents.insert({"lyapunov_vectors", "covariant_vectors", "covariant_transient"});
  expect_rows_in_help("exponents", transport_parameters(), exponents);
  expect_rows_in_help("exponents", exponent_table_parameters());
  expect_rows_in_help("exponents", exponent_parameters());
  expect_rows_in_help("exponents", mode_kick_parameters());
  expect_rows_in_help("ipr-map", ipr_map_parameters());
  expect_rows_in_help("ipr-map", mode_selection_parameters());
  expect_rows_in_help("spectrum", spectrum_parameters(), {"vectors"});  // the tool takes a file: --vectors FILE
  expect_rows_in_help("spectrum", mode_selection_parameters());
  expect_rows_in_help("butterfly", butterfly_parameters());
  expect_rows_in_help("butterfly", dynamical_butterfly_parameters());
  expect_rows_in_help("crystal", crystal_parameters());
  expect_rows_in_help("crystal-ipr-map", crystal_ipr_map_parameters());
  expect_rows_in_help("klein-gordon", klein_gordon_parameters());
  expect_rows_in_help("breathers", breather_parameters());
  expect_rows_in_help("correlations", correlation_parameters());
}

}  // namespace
}  // namespace granular::testing
