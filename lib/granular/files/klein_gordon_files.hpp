#pragma once
// The table of the `klein-gordon` job, so that the tool and Python write alike; the JSON is
// describe(case, result) (klein_gordon/klein_gordon_study.hpp).
#include <memory>
#include <ostream>
#include <string>

#include "granular/io/hdf5_file.hpp"
#include "granular/klein_gordon/klein_gordon_study.hpp"

namespace granular {

/// t,m2,P[,mle,mean_log10_mle]: one row per sample, t [1/ω₀]; m2 [sites²], P [sites] and Λ [ω₀]
/// the means over the realizations (one realization: its own), and ⟨log10 Λ⟩; the last two only
/// when Λ was computed.
void write_klein_gordon_csv(std::ostream& out, const KleinGordonResult& r);

/// Realization 0's energy map (`energy_map`) in the granular chain's layout (spreading_files.hpp,
/// write_energy_map): datasets energy [sample][site] (E_l, in units of H), t [1/omega0], site
/// (1 … N), units as attributes. Returned uncommitted, as AtomicFile is.
std::unique_ptr<Hdf5File> write_klein_gordon_energy_map(const std::string& path, const KleinGordonResult& r);

}  // namespace granular
