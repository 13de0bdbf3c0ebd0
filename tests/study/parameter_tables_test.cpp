// The library's parameter tables (parameter_table.hpp), of which the tools make their options and
// Python its attributes: a parameter named in backticks in a help text is told in a front end's
// words, and is a parameter some table describes (a misspelled reference would reach every --help
// and docstring); no table names a parameter twice.
#include "granular/parameter_table.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "granular/study/chain_choices.hpp"
#include "granular/study/dynamical_butterfly.hpp"
#include "granular/study/transport_choices.hpp"

namespace granular {
namespace {

TEST(ParameterTables, TellTheParametersInBackticksInAFrontEndsWords) {
  const auto flag = [](const std::string& p) { return "--" + front_end_word(p); };
  EXPECT_EQ(tell_parameters("a multiple of `time_step`, at most `duration`", flag), "a multiple of --dt, at most --T");
  EXPECT_EQ(tell_parameters("no parameter", flag), "no parameter");
  EXPECT_EQ(tell_parameters("an unpaired ` stays", flag), "an unpaired ` stays");
  EXPECT_EQ(word_of(parameter(mode_kick_parameters(), "mode_khz")), "mode_khz");
  EXPECT_EQ(word_of(parameter(transport_parameters(), "time_step")), "dt");
  EXPECT_THROW(parameter(transport_parameters(), "no_such_parameter"), std::out_of_range);
}

template <class Choices>
void collect_names(const ParameterTable<Choices>& table, std::set<std::string>& names) {
  std::set<std::string> own;
  for (const auto& p : table) {
    EXPECT_TRUE(own.insert(p.name).second) << p.name << " twice in one table";
    EXPECT_FALSE(p.help.empty()) << p.name;
    EXPECT_EQ(p.help.find("--"), std::string::npos) << p.name << ": a flag in the library's help";
    names.insert(p.name);
  }
}

template <class Choices>
void expect_references_known(const ParameterTable<Choices>& table, const std::set<std::string>& names) {
  for (const auto& p : table)
    tell_parameters(p.help, [&](const std::string& named) {
      EXPECT_TRUE(names.contains(named)) << p.name << "'s help names `" << named << "`, which no table describes";
      return named;
    });
}

TEST(ParameterTables, NameEachParameterOnceAndReferOnlyToParametersTheyDescribe) {
  std::set<std::string> names;
  collect_names(chain_parameters(), names);
  collect_names(transport_parameters(), names);
  collect_names(beyond_parameters(), names);
  collect_names(mode_kick_parameters(), names);
  collect_names(dynamical_butterfly_parameters(), names);
  EXPECT_GE(names.size(), 45U);
  expect_references_known(chain_parameters(), names);
  expect_references_known(transport_parameters(), names);
  expect_references_known(beyond_parameters(), names);
  expect_references_known(mode_kick_parameters(), names);
  expect_references_known(dynamical_butterfly_parameters(), names);
}

}  // namespace
}  // namespace granular
