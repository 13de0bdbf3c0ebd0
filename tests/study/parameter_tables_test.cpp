// The library's parameter tables (parameter_table.hpp), of which the tools make their options and
// Python its attributes: a parameter named in backticks in a help text is told in a front end's
// words, and is a parameter some table describes (a misspelled reference would reach every --help
// and docstring); no table names a parameter twice.
#include "granular/parameter_table.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "granular/case/chain_choices.hpp"
#include "granular/case/chain_length_rule.hpp"
#include "granular/case/kicked_case.hpp"
#include "granular/case/spreading_outputs.hpp"
#include "granular/case/transport_parameters.hpp"
#include "granular/ensemble/run_options.hpp"
#include "granular/error.hpp"
#include "granular/linear/mode_selection_choices.hpp"
#include "granular/study/dynamical_butterfly.hpp"
#include "granular/study/exponent_choices.hpp"
#include "granular/study/ipr_map.hpp"

namespace granular {
namespace {

TEST(ParameterTables, TellTheParametersInBackticksInAFrontEndsWords) {
  const auto flag = [](const std::string& p) { return "--" + front_end_word(p); };
  EXPECT_EQ(tell_parameters("a multiple of `time_step`, at most `duration`", flag), "a multiple of --dt, at most --T");
  EXPECT_EQ(tell_parameters("no parameter", flag), "no parameter");
  EXPECT_EQ(tell_parameters("an unpaired ` stays", flag), "an unpaired ` stays");
  EXPECT_EQ(word_of(parameter(mode_kick_parameters(), "near_khz")), "near");
  EXPECT_EQ(parameter(mode_kick_parameters(), "near_khz").former_words, std::vector<std::string>{"mode_khz"});
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
  collect_names(mode_kick_parameters(), names);
  collect_names(dynamical_butterfly_parameters(), names);
  collect_names(exponent_parameters(), names);
  collect_names(exponent_table_parameters(), names);
  collect_names(kicked_case_parameters(), names);
  collect_names(ipr_map_parameters(), names);
  collect_names(spreading_output_parameters(), names);
  collect_names(mode_selection_parameters(), names);
  collect_names(long_run_parameters(), names);
  EXPECT_GE(names.size(), 45U);
  expect_references_known(chain_parameters(), names);
  expect_references_known(transport_parameters(), names);
  expect_references_known(mode_kick_parameters(), names);
  expect_references_known(dynamical_butterfly_parameters(), names);
  expect_references_known(exponent_parameters(), names);
  expect_references_known(exponent_table_parameters(), names);
  expect_references_known(kicked_case_parameters(), names);
  expect_references_known(ipr_map_parameters(), names);
  expect_references_known(spreading_output_parameters(), names);
  expect_references_known(mode_selection_parameters(), names);
  expect_references_known(long_run_parameters(), names);
}

/// Every text form of `table` reads back what it writes of the defaults, and a value it cannot
/// read is refused naming its parameter; returns how many there are.
template <class Choices>
int expect_text_forms_read_what_they_write(const ParameterTable<Choices>& table, const std::string& unreadable) {
  int forms = 0;
  for (const auto& p : table) {
    if (!p.text) continue;
    ++forms;
    Choices defaults, read;
    const std::string text = p.text->write(defaults);
    p.text->read(read, text);
    EXPECT_EQ(p.text->write(read), text) << p.name;
    try {
      p.text->read(read, unreadable);
      ADD_FAILURE() << p.name << " read '" << unreadable << "'";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.parameter(), p.name) << e.what();
    }
  }
  return forms;
}

TEST(ParameterTables, TextFormsReadWhatTheyWriteAndNameTheirParameter) {
  // beta, fit, active_window and the words centre, integrator, force_law, sampling, energy_guard
  EXPECT_EQ(expect_text_forms_read_what_they_write(transport_parameters(), "1:x"), 8);
  EXPECT_EQ(expect_text_forms_read_what_they_write(exponent_table_parameters(), "h,,A"), 4);   // chains, ic, F0s
  EXPECT_EQ(expect_text_forms_read_what_they_write(kicked_case_parameters(), "1:x"), 1);       // ic
  EXPECT_EQ(expect_text_forms_read_what_they_write(ipr_map_parameters(), "1:x"), 2);           // xi, q
  EXPECT_EQ(expect_text_forms_read_what_they_write(spreading_output_parameters(), "1:x"), 2);  // forces_at, spectrum_of
  EXPECT_EQ(expect_text_forms_read_what_they_write(mode_selection_parameters(), "1:x"), 1);    // window
  EXPECT_EQ(expect_text_forms_read_what_they_write(long_run_chain_parameters(), "1:x"), 1);    // N
  TransportCase o;
  parameter(transport_parameters(), "beta").text->read(o, "match");
  EXPECT_FALSE(o.beta) << "'match': the energy of alpha";
  parameter(transport_parameters(), "fit").text->read(o, "2e-3:5e-3");
  EXPECT_EQ(o.fit_begin, 2e-3);
  EXPECT_EQ(o.fit_end, 5e-3);
  parameter(transport_parameters(), "active_window").text->read(o, "off");
  EXPECT_FALSE(o.dynamics.integration.window.enabled);
  EXPECT_EQ(parameter(transport_parameters(), "active_window").text->write(o), "off");
}

TEST(ParameterTables, TheLongRunChainLengthIsANumberOrAuto) {
  const auto& n = *parameter(long_run_chain_parameters(), "N").text;
  ChainChoices o;
  n.read(o, "auto");
  EXPECT_TRUE(o.auto_n);
  EXPECT_EQ(n.write(o), "auto");
  n.read(o, "2.5e3");
  EXPECT_FALSE(o.auto_n) << "a number after 'auto' is the number";
  EXPECT_EQ(o.n, 2500);
  for (const char* bad : {"1e3.5", "12x", "Auto", "2.5"}) {
    try {
      n.read(o, bad);
      ADD_FAILURE() << "read '" << bad << "'";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(std::string(e.what()), "N " + std::string(bad) + ": an integer or 'auto'");
    }
  }
  EXPECT_EQ(parameter(chain_parameters(), "N").text, std::nullopt) << "only long runs size N themselves";
}

TEST(ParameterTables, TheListOfBeadsAndTheWindowReadAndWriteTheirValues) {
  const auto& forces_at = *parameter(spreading_output_parameters(), "forces_at").text;
  TransportCase outputs;
  forces_at.read(outputs, "601,631,661");
  EXPECT_EQ(outputs.dynamics.forces.sites, (std::vector<std::size_t>{600, 630, 660})) << "the observer's: 0-based";
  EXPECT_EQ(forces_at.write(outputs), "601,631,661");
  forces_at.read(outputs, "");
  EXPECT_TRUE(outputs.dynamics.forces.sites.empty()) << "an empty list: no force series";
  EXPECT_THROW(forces_at.read(outputs, "3,0"), InvalidInput) << "beads count from 1";

  const auto& window = *parameter(mode_selection_parameters(), "window").text;
  ModeSelectionChoices modes;
  window.read(modes, "10:12.5");
  ASSERT_TRUE(modes.window);
  EXPECT_EQ(*modes.window, (std::pair{10.0, 12.5}));
  EXPECT_EQ(window.write(modes), "10:12.5");
  EXPECT_EQ(choose_modes(modes).kind, ModeSelection::Kind::window);
  for (const char* bad : {"12", "1:2:3", "a:2", "1:", ":2", "1:2x", "1:nan"}) {
    try {
      window.read(modes, bad);
      ADD_FAILURE() << "read '" << bad << "'";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(std::string(e.what()), "window '" + std::string(bad) + "': expected F1:F2, two frequencies in kHz");
    }
  }
  window.read(modes, "");
  EXPECT_FALSE(modes.window) << "an empty window: none";
  EXPECT_EQ(choose_modes(ModeSelectionChoices{.near = 15.0, .count = 20}).count, 20);
}

}  // namespace
}  // namespace granular
