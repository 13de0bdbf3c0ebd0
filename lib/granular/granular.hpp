#pragma once
// Everything a program using the toolkit needs, in one include. The pipeline reads top to bottom:
// a chain (model) → its dynamical matrix and spectrum (linear) → its nonlinear dynamics (dynamics)
// → many realizations (ensemble) → what the averages say (analysis) → the paper's studies (study).
#include "granular/error.hpp"
#include "granular/number_format.hpp"

#include "granular/model/bead_source.hpp"
#include "granular/model/chain.hpp"
#include "granular/model/configuration_file.hpp"
#include "granular/model/contact_law.hpp"
#include "granular/model/correlation.hpp"
#include "granular/model/disorder.hpp"
#include "granular/model/material.hpp"
#include "granular/model/named_chains.hpp"

#include "granular/linear/band_edges.hpp"
#include "granular/linear/density_of_states.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/mode_ipr.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/linear/transfer_matrix.hpp"
#include "granular/linear/tridiagonal_operator.hpp"

#include "granular/dynamics/force_law.hpp"
#include "granular/dynamics/initial_conditions.hpp"
#include "granular/dynamics/observables.hpp"
#include "granular/dynamics/propagator.hpp"
#include "granular/dynamics/scheme.hpp"
#include "granular/dynamics/spectral_density.hpp"
#include "granular/dynamics/spreading.hpp"

#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/ensemble/run_options.hpp"

#include "granular/analysis/bootstrap.hpp"
#include "granular/analysis/exponent_report.hpp"
#include "granular/analysis/log_derivative.hpp"
#include "granular/analysis/power_law_fit.hpp"
#include "granular/analysis/summary_statistics.hpp"

#include "granular/study/correlation_study.hpp"
#include "granular/study/exponent_table.hpp"
#include "granular/study/ipr_map.hpp"
#include "granular/study/localization_scan.hpp"
#include "granular/study/mode_kick.hpp"
#include "granular/study/paper_comparison.hpp"
#include "granular/study/spectrum_file.hpp"
#include "granular/study/spreading_files.hpp"
#include "granular/study/time_step_rule.hpp"
#include "granular/study/transport_study.hpp"
