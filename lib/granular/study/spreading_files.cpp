#include "granular/study/spreading_files.hpp"

#include "granular/io/csv_writer.hpp"
#include "granular/io/hdf5_file.hpp"

namespace granular {

void write_spreading_csv(std::ostream& out, const SpreadingResult& r) {
  CsvWriter t(out, {"t", "m2", "ipr", "energy_error", "m2_centroid"});
  for (std::size_t i = 0; i < r.t.size(); ++i) t.row(r.t[i], r.m2[i], r.ipr[i], r.energy_error[i], r.m2_centroid[i]);
}

void write_spreading_csv(std::ostream& out, const TransportSummary& m) {
  CsvWriter t(out, {"t", "m2", "ipr", "energy_error", "m2_centroid"});
  for (std::size_t i = 0; i < m.t.size(); ++i)
    t.row(m.t[i], m.m2.mean[i], m.ipr.mean[i], m.energy_error.mean[i], m.m2_centroid.mean[i]);
}

void write_standard_errors_csv(std::ostream& out, const TransportSummary& m) {
  CsvWriter t(out, {"t", "m2_se", "ipr_se", "energy_error_se", "m2_centroid_se"});
  for (std::size_t i = 0; i < m.t.size(); ++i)
    t.row(m.t[i], m.m2.standard_error[i], m.ipr.standard_error[i], m.energy_error.standard_error[i],
          m.m2_centroid.standard_error[i]);
}

void write_final_state_csv(std::ostream& out, const SpreadingResult& r) {
  CsvWriter t(out, {"site", "u", "v", "energy"});
  for (std::size_t i = 0; i < r.final_state.size(); ++i)
    t.row(i + 1, r.final_state.u[i], r.final_state.v[i], r.final_energy[i]);
}

void write_profile_csv(std::ostream& out, const SpreadingResult& r) {
  CsvWriter t(out, {"site", "energy", "force"});
  for (std::size_t i = 0; i < r.final_energy.size(); ++i) t.row(i + 1, r.final_energy[i], r.final_force[i]);
}

void write_profile_csv(std::ostream& out, const TransportSummary& m) {
  CsvWriter t(out, {"site", "energy", "energy_se"});
  for (std::size_t i = 0; i < m.profile.mean.size(); ++i) t.row(i + 1, m.profile.mean[i], m.profile.standard_error[i]);
}

void write_forces_csv(std::ostream& out, const SpreadingResult& r, const std::vector<std::size_t>& sites) {
  CsvWriter t(out, {"t", "site", "force"});
  for (std::size_t k = 0; k < r.force_t.size(); ++k)
    for (std::size_t j = 0; j < sites.size(); ++j) t.row(r.force_t[k], sites[j] + 1, r.forces[j][k]);
}

void write_spectrum_csv(std::ostream& out, const SpreadingResult& r) {
  CsvWriter t(out, {"freq_khz", "g"});
  for (std::size_t j = 0; j < r.spectrum.size(); ++j) t.row(r.spectrum_khz[j], r.spectrum[j]);
}

void write_energy_map(const std::string& path, const SpreadingResult& r, std::size_t stride) {
  std::vector<double> sites;
  for (std::size_t k = 0; k < r.map_columns; ++k) sites.push_back(static_cast<double>(k * stride + 1));
  write_hdf5_atomically(path, {{"energy", {r.map_t.size(), r.map_columns}, r.map_energy.data()},
                               {"t", {r.map_t.size()}, r.map_t.data()},
                               {"site", {sites.size()}, sites.data()}});
}

nlohmann::json describe_run(const SpreadingResult& r, const nlohmann::json& realization) {
  return {{"realization", realization},
          {"initial_energy_J", r.initial_energy},
          {"max_energy_error", r.max_energy_error},
          {"steps", r.steps},
          {"bond_updates", r.bond_updates},
          {"integration_s", r.seconds},
          {"window_final", {r.window_begin + 1, r.window_end}},
          {"wall_energy", r.wall_energy},
          {"reached_walls", r.reached_walls}};
}

}  // namespace granular
