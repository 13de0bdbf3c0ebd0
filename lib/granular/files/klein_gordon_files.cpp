#include "granular/files/klein_gordon_files.hpp"

#include <string>
#include <vector>

#include "granular/files/spreading_files.hpp"
#include "granular/io/csv_writer.hpp"

namespace granular {

void write_klein_gordon_csv(std::ostream& out, const KleinGordonResult& r) {
  const KleinGordonEnsemble& e = r.ensemble;
  const bool mle = !e.mle.empty();
  CsvWriter table(out, mle ? std::vector<std::string>{"t", "m2", "P", "mle", "mean_log10_mle"}
                           : std::vector<std::string>{"t", "m2", "P"});
  for (std::size_t s = 0; s < e.time.size(); ++s)
    if (mle) table.row(e.time[s], e.m2[s], e.participation[s], e.mle[s], e.mean_log10_mle[s]);
    else table.row(e.time[s], e.m2[s], e.participation[s]);
}

std::unique_ptr<Hdf5File> write_klein_gordon_energy_map(const std::string& path, const KleinGordonResult& r) {
  const KleinGordonRun& run = r.ensemble.runs.front();
  const std::size_t samples = run.time.size(), n = samples ? run.energy_map.size() / samples : 0;
  auto file = write_energy_map(path, run.time, run.energy_map, n, 1);
  file->attribute("units", "energy: site energies E_l in units of H (each row sums to H); t: 1/omega0; site: 1..N");
  file->attribute("realization", "0");
  return file;
}

}  // namespace granular
