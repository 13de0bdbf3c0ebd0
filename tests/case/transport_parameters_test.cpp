// The parameters of a kicked run, rows over the typed case itself: "auto" stands for SABA2C until
// the step is settled, a given time step is the case's own, the words of the enums read back what
// they write, every row reaches its field of the case, the range checks of the choices are
// validate()'s and name the parameter, a fit window past T means no exponents (not an error), and a
// mode kick's own fields are told apart from their defaults.
#include "granular/case/transport_parameters.hpp"

#include <gtest/gtest.h>

#include <set>

#include <nlohmann/json.hpp>

namespace granular {
namespace {

void read(TransportCase& c, const std::string& name, const std::string& text) {
  parameter(transport_parameters(), name).text->read(c, text);
}

TEST(TransportParameters, AutoStandsForSaba2cUntilSettled) {
  TransportCase c;
  EXPECT_FALSE(c.automatic_integrator);
  EXPECT_EQ(c.dynamics.integration.integrator.name(), "saba2c");
  read(c, "integrator", "srkn14a");
  EXPECT_FALSE(c.automatic_integrator);
  EXPECT_EQ(c.dynamics.integration.integrator.name(), "srkn14a");
  read(c, "integrator", "auto");
  EXPECT_TRUE(c.automatic_integrator);  // settled with the step (scheme_choice.hpp)
  EXPECT_EQ(c.dynamics.integration.integrator.name(), "saba2c");
  EXPECT_EQ(parameter(transport_parameters(), "integrator").text->write(c), "auto");
}

// Flags are read in any order: the reference's largest step, given before the scheme, is kept.
TEST(TransportParameters, TheIntegratorWordKeepsTheReferencesLargestStep) {
  TransportCase c;
  std::get<Ref<TransportCase, double>>(parameter(transport_parameters(), "reference_max_step").field)(c) = 3e-9;
  read(c, "integrator", "reference");
  EXPECT_TRUE(c.dynamics.integration.integrator.reference);
  EXPECT_EQ(c.dynamics.integration.integrator.tolerance.max_step, 3e-9);
}

// What settling resolves travels in the case, not beside it: a time step given or not.
TEST(TransportParameters, AGivenTimeStepIsTheCasesOwnAndNoneLeavesThePreferredOne) {
  TransportCase c;
  const double preferred = c.dynamics.integration.time_step;
  EXPECT_FALSE(c.time_step.has_value());
  std::get<Ref<TransportCase, std::optional<double>>>(parameter(transport_parameters(), "time_step").field)(c) = 2.5e-7;
  ASSERT_TRUE(c.time_step.has_value());
  EXPECT_EQ(*c.time_step, 2.5e-7);
  EXPECT_EQ(c.dynamics.integration.time_step, preferred) << "the rule settles it (time_step_rule.hpp)";
}

/// Each row of transport_parameters() set to a value other than its default on a case of its own
/// (with what it needs to be described: a velocity kick for beta, the reference for its largest
/// step, the tangent map for renormalize), by the row itself: a row added to the table is covered
/// with no line written here. `f(row, before, after)` gets the case's descriptions.
template <class F>
void for_every_row_changed(F f) {
  for (const auto& p : transport_parameters()) {
    TransportCase c;
    c.kick = p.name == "beta" ? Kick::velocity : Kick::displacement;         // so that beta, alpha are described
    if (p.name == "reference_max_step") read(c, "integrator", "reference");  // described only then
    if (p.name == "renormalize")
      std::get<Ref<TransportCase, bool>>(parameter(transport_parameters(), "mle").field)(c) = true;
    const std::string before = describe(c).dump();
    std::visit(
        [&]<class Field>(const Field& field) {
          if constexpr (std::is_same_v<Field, std::monostate>) {
            if (p.name == "fit") read(c, "fit", "1e-3:2e-3");
            else
              read(c, p.name,
                   p.name == "centre"       ? "centroid"
                   : p.name == "integrator" ? "aba864"
                   : p.name == "force_law"  ? "fpu"
                   : p.name == "sampling"   ? "uniform"
                                            : "warn");
          } else {
            auto& value = field(c);
            using T = std::remove_cvref_t<decltype(value)>;
            if constexpr (std::is_same_v<T, bool>) value = !value;
            else if constexpr (std::is_same_v<T, std::optional<double>>) value = value.value_or(1.0) * 3;
            else if constexpr (std::is_arithmetic_v<T>) value = static_cast<T>(value * 3 + 7);
          }
        },
        p.field);
    f(p, c, before);
  }
}

// Each row with a field reaches a field of its own: setting it through the row changes what the
// case describes (the JSON of checkpoints and replays), and no two rows share a field.
TEST(TransportParameters, EveryRowReachesAFieldOfItsOwn) {
  std::set<std::string> described;
  for_every_row_changed([&](const Parameter<TransportCase>& p, const TransportCase& c, const std::string& before) {
    const std::string after = describe(c).dump();
    if (p.name == "deviation_samples" || p.name == "mle") return;  // not the case's identity: the run's outputs
    EXPECT_NE(before, after) << p.name << " does not reach the case";
    EXPECT_TRUE(described.insert(after).second) << p.name << " shares a field";
  });
}

// parse(describe(c)) is c for every row: what a replay file or a checkpoint's identity holds of a
// parameter comes back as it was set.
TEST(TransportParameters, ParseInvertsDescribeForEveryRow) {
  for_every_row_changed([](const Parameter<TransportCase>& p, const TransportCase& c, const std::string&) {
    const nlohmann::json described = describe(c);
    const TransportCase back = parse_case(described);
    EXPECT_EQ(describe(back), described) << p.name;
    if (p.text && p.name != "fit") {
      EXPECT_EQ(p.text->write(back), p.text->write(c)) << p.name;
    }
  });
}

TEST(TransportParameters, TheChoicesAreCheckedByValidateNamingThem) {
  const auto refused = [](auto set) {
    TransportCase c;
    c.chain.N = 101;
    set(c);
    try {
      validate_before_time_step(c);
    } catch (const InvalidInput& e) {
      return e.parameter();
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(refused([](TransportCase&) {}), "(accepted)");
  EXPECT_EQ(refused([](TransportCase& c) { c.site = 102; }), "site");
  EXPECT_EQ(refused([](TransportCase& c) { c.dynamics.spread.samples = 1; }), "samples");
  EXPECT_EQ(refused([](TransportCase& c) { c.dynamics.forces.samples = 1; }), "force_samples");  // an output row
  EXPECT_EQ(refused([](TransportCase& c) { c.dynamics.integration.window.threshold = -1; }), "window_threshold");
  EXPECT_EQ(refused([](TransportCase& c) { c.dynamics.spread.max_energy_error = 1.0 / 0.0; }), "max_energy_error");
  EXPECT_EQ(refused([](TransportCase& c) { c.fit_begin = 0; }), "fit");
  EXPECT_EQ(refused([](TransportCase& c) { c.bootstrap.resamples = 1; }), "bootstrap");
  EXPECT_EQ(refused([](TransportCase& c) { c.dynamics.integration.lyapunov.renormalize_every = 0; }), "renormalize");
  EXPECT_EQ(refused([](TransportCase& c) {
              c.dynamics.spread.stop_on_energy_error = false, c.dynamics.spread.max_energy_error = 0;
            }),
            "energy_guard");
  EXPECT_EQ(refused([](TransportCase& c) {
              c.dynamics.integration.window.enabled = false, c.dynamics.integration.window.threshold = 1e-20;
            }),
            "window_threshold");
}

TEST(TransportParameters, AFitWindowPastTheDurationFitsNothing) {
  TransportCase c;
  c.dynamics.integration.duration = 1e-2;
  c.fit_end = 1e-2;
  fit_within_duration(c);
  EXPECT_TRUE(c.fit);
  c.fit_end = 1e-2 * (1 + 1e-13);  // rounding of a typed T
  fit_within_duration(c);
  EXPECT_TRUE(c.fit);
  c.fit_end = 1.1e-2;
  fit_within_duration(c);
  EXPECT_FALSE(c.fit);
  c.dynamics.integration.duration = 2e-2;
  fit_within_duration(c);
  EXPECT_TRUE(c.fit);
}

TEST(TransportParameters, AModeKicksOwnFieldsAreToldFromTheirDefaults) {
  EXPECT_FALSE(chosen(ModeKick{}));
  EXPECT_FALSE(chosen(ModeKick{.amplitude = 1e-7}));  // the amplitude is any kick's α
  EXPECT_TRUE(chosen(ModeKick{.mode = 3}));
  EXPECT_TRUE(chosen(ModeKick{.near_khz = 0}));
  EXPECT_TRUE(chosen(ModeKick{.energy = 1e-9}));
}

}  // namespace
}  // namespace granular
