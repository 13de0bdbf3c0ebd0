#pragma once
// Options beyond the paper (docs/physics.md, "Nonlinear dynamics"): dissipation (both `spreading` and
// `exponents`) and the maximal Lyapunov exponent by the tangent map (`spreading --mle`, `exponents --mle`). Library
// messages name `damping_time`, `kk_gamma`, `deviation_samples`; tool::run tells them as these flags.
#include <string>

#include <CLI/CLI.hpp>

#include "granular/dynamics/spreading.hpp"
#include "granular/error.hpp"
#include "granular/study/transport_choices.hpp"
#include "tool_main.hpp"

namespace granular::tool {

struct BeyondOptions {
  double damping_time = 0, kk_gamma = 0;
  bool mle = false;
  long long renormalize = 10, deviation_samples = 20;
  std::string deviation;  ///< CSV of the deviation-vector distribution; empty = none
};

inline void add_damping_options(CLI::App& app, BeyondOptions& o) {
  add_option(app, "--damping-time", o.damping_time,
             "on-site viscous damping time tau_d [s] of -(m/tau_d) du/dt; 0 = none");
  add_option(app, "--kk-gamma", o.kk_gamma,
             "Kuwabara-Kono contact damping gamma_KK [s]: bond force A[d]^{3/2} + gamma A [d]^{1/2} dd/dt; 0 = none");
}

/// --mle (with `help`: what the tool writes) and --renormalize.
inline void add_mle_options(CLI::App& app, BeyondOptions& o, const std::string& help) {
  app.add_flag("--mle", o.mle, help);
  add_option(app, "--renormalize", o.renormalize, "steps between renormalizations of the deviation vector");
}

inline void add_lyapunov_options(CLI::App& app, BeyondOptions& o) {
  add_mle_options(app, o, "maximal Lyapunov exponent by the tangent map: column mle = X1(t) [1/s] (ensemble: its mean)");
  app.add_option("--deviation", o.deviation, "CSV t,site,share: the deviation vector along the chain (with --mle)");
  add_option(app, "--deviation-samples", o.deviation_samples, "uniform times of --deviation");
}

/// granular::apply(BeyondChoices) (transport_choices.hpp), once the file option only the tool has
/// is read: --deviation FILE turns on --deviation-samples.
inline void apply(const BeyondOptions& o, SpreadingConfig& d) {
  if (!o.deviation.empty() && !o.mle) throw InvalidInput("--deviation: needs --mle");
  if (o.deviation_samples < 2)
    throw InvalidInput("--deviation-samples " + std::to_string(o.deviation_samples) + ": at least 2");
  granular::apply(BeyondChoices{o.damping_time, o.kk_gamma, o.mle, o.renormalize,
                                o.deviation.empty() ? 0 : o.deviation_samples},
                  d);
}

}  // namespace granular::tool
