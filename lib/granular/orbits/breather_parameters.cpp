#include "granular/orbits/breather_parameters.hpp"

#include "granular/error.hpp"

namespace granular {
namespace {

using B = BreatherBranchConfig;
using S = ShootingConfig;

// The enums' words.
void read_law(B& c, const std::string& word) {
  c.law = parse_force_law(word);
  if (c.law == ForceLawKind::linear)
    throw InvalidInput("law", " linear: every amplitude is a periodic orbit at a mode's frequency; use hertz or fpu");
}
std::string write_law(const B& c) { return to_string(c.law); }
void read_scheme(B& c, const std::string& word) { c.shooting.scheme = parse_scheme(word); }
std::string write_scheme(const B& c) { return c.shooting.scheme.name; }
void read_newton(B& c, const std::string& word) { c.shooting.newton = parse_newton_method(word); }
std::string write_newton(const B& c) { return to_string(c.shooting.newton); }
void read_floquet(B& c, const std::string& word) { c.floquet_method = parse_floquet_method(word); }
std::string write_floquet(const B& c) { return to_string(c.floquet_method); }
void read_continuation(B& c, const std::string& word) { c.continuation = parse_continuation(word); }
std::string write_continuation(const B& c) { return to_string(c.continuation); }

}  // namespace

const ParameterTable<BreatherBranchConfig>& breather_parameters() {
  using P = Parameter<B>;
  static const ParameterTable<B> table{
      {"mode", &B::mode, "seed: linear mode number 1..N (0: by `near_khz` or `start_khz`)"},
      P{"near_khz", &B::near_khz, "seed: the linear mode nearest this frequency [kHz]", false}.formerly("near_khz"),
      {"start_khz", &B::start_khz,
       "first breather frequency [kHz] (default: the seed's, shifted by `start_offset` towards `target_khz`)", false},
      {"start_offset", &B::start_offset, "relative shift of the first frequency from the seed"},
      {"site", &B::site, "F0 = 0 (on-site springs: quasi s1 with k0_n_per_m): seed bead 1..N (0: the middle one)"},
      {"target_khz", &B::target_khz, "stop at this frequency [kHz] (default: no target, go down)", false},
      {"step_khz", &B::step_khz,
       "first continuation step [kHz] (0: the start's distance from the seed; 0.1 % of it from a seed profile)"},
      P{"continuation",
        {},
        {read_continuation, write_continuation},
        "natural (in frequency; a fold ends the branch) | arclength (pseudo-arclength: passes folds)"}
          .as_word(),
      {"max_points", &B::max_points, "points on the branch at most"},
      P{"law", {}, {read_law, write_law}, "bond force law: hertz | fpu"}.as_word(),
      P{"scheme",
        {},
        {read_scheme, write_scheme},
        "splitting scheme of shooting and monodromy: saba2c | saba2 | aba864 | srkn14a"}
          .as_word(),
      {"steps_per_period", path<B>(&B::shooting, &S::steps_per_period),
       "scheme steps per period, even (0: omega_max tau <= 0.05, at least 128)"},
      {"tolerance", path<B>(&B::shooting, &S::tolerance),
       "Newton stops at relative residual |du/dt(T/2)| / (omega_b |x0|) <= this"},
      P{"newton",
        {},
        {read_newton, write_newton},
        "Newton's linear solve: dense (N x N Jacobian) | krylov (matrix-free GMRES) | auto (dense to N = 1000)"}
          .as_word(),
      P{"floquet_method",
        {},
        {read_floquet, write_floquet},
        "multipliers: dense (all 2N) | arpack (the `floquet_multipliers` largest |mu|) | auto (dense to N = 1000, "
        "then ARPACK; up to N = 3000 within the dense cost, then dense unless all converged)"}
          .as_word(),
      P{"floquet_multipliers", &B::floquet_multipliers, "ARPACK: how many multipliers of largest |mu|"}.formerly(
          "floquet_multipliers"),
      {"stability_tolerance", &B::stability_tolerance, "stable when max |mu| <= 1 + this"},
      {"through_opening", &B::through_opening,
       "continue past points where a contact opens (at F0 = 0 every contact opens: it does not matter)"}};
  return table;
}

}  // namespace granular
