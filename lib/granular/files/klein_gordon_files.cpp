#include "granular/files/klein_gordon_files.hpp"

#include <string>
#include <vector>

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

}  // namespace granular
