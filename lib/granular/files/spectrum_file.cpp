#include "granular/files/spectrum_file.hpp"

#include <algorithm>
#include <cstdint>
#include <nlohmann/json.hpp>

#include "granular/io/atomic_file.hpp"
#include "granular/io/csv_writer.hpp"
#include "granular/io/hdf5_file.hpp"
#include "granular/parallel/mpi_context.hpp"

namespace granular {

std::unique_ptr<Hdf5File> write_spectrum_hdf5(const std::string& path, const Spectrum& s, const DynamicalMatrix& matrix) {
  auto out = std::make_unique<Hdf5File>(path);
  Hdf5File& file = *out;
  file.write("mode", std::vector<std::uint64_t>(s.mode.begin(), s.mode.end()));
  file.write("omega2", s.omega2);
  file.write("freq_khz", s.freq_khz);
  file.write("ipr", s.ipr);
  file.write("residual", s.residual);
  file.write("inverse_sqrt_mass", matrix.inverse_sqrt_mass);
  // Column-major N × K is exactly the row-major K × N array.
  if (!s.vectors.empty()) file.write("eigenvectors", s.vectors.data(), s.size(), s.beads);
  file.attribute("method", s.info.method);
  file.attribute(
      "eigenvectors_layout",
      "row j = unit eigenvector w of the dynamical matrix for mode[j]; displacement v = w * inverse_sqrt_mass");
  return out;
}

void write_spectrum_csv(std::ostream& out, const Spectrum& s, bool clusters) {
  if (clusters) {
    CsvWriter table(out, {"mode", "freq_khz", "ipr", "clustered"});
    for (std::size_t j = 0; j < s.size(); ++j) table.row(s.mode[j], s.freq_khz[j], s.ipr[j], int{s.clustered[j]});
  } else {
    CsvWriter table(out, {"mode", "freq_khz", "ipr"});
    for (std::size_t j = 0; j < s.size(); ++j) table.row(s.mode[j], s.freq_khz[j], s.ipr[j]);
  }
}

void write_matrix_dump(const std::string& prefix, const DynamicalMatrix& d) {
  AtomicFile diag(prefix + ".diag.f64"), off(prefix + ".offdiag.f64");
  diag.stream().write(reinterpret_cast<const char*>(d.diagonal.data()),
                      static_cast<std::streamsize>(8 * d.diagonal.size()));
  off.stream().write(reinterpret_cast<const char*>(d.off_diagonal.data()),
                     static_cast<std::streamsize>(8 * d.off_diagonal.size()));
  diag.commit();
  off.commit();
}

nlohmann::json describe(const BandEdges& e) {
  return {{"f1", e.f1 * 1e-3}, {"f2", e.f2 * 1e-3}, {"fb1", e.fb1 * 1e-3}, {"fb2", e.fb2 * 1e-3}, {"fb3", e.fb3 * 1e-3}};
}

nlohmann::json band_edges_of(const nlohmann::json& chain, const Material& material) {
  if (!chain.is_object() || !chain.contains("xi")) return nullptr;
  return describe(band_edges(material, chain.at("R1_m").get<double>(), chain.at("xi").get<double>(),
                             chain.at("F0_N").get<double>()));
}

nlohmann::json describe_spectrum(const Spectrum& r, const SpectrumRequest& q, const nlohmann::json& chain,
                                 const Material& material) {
  nlohmann::json meta;
  const auto flagged = static_cast<std::size_t>(std::count(r.clustered.begin(), r.clustered.end(), 1));
  meta["clustered"] = {{"relative_gap", cluster_relative_gap}, {"modes", flagged}};
  if (!chain.is_null()) meta["chain"] = chain;
  meta["method"] = to_string(q.config.method);
  meta["solver"] = {{"method", r.info.method}, {"fallbacks", r.info.fallbacks}};
  const ModeSelection& sel = q.selection;
  if (sel.kind != ModeSelection::Kind::all) {
    meta["selection"] = sel.kind == ModeSelection::Kind::nearest
                            ? nlohmann::json{{"near_khz", sel.near_khz}, {"count", sel.count}}
                            : nlohmann::json{{"window_khz", {sel.lo_khz, sel.hi_khz}}};
    meta["solver"].update({{"restarts", r.info.restarts},
                           {"candidates", r.info.candidates},
                           {"max_relative_residual", r.info.max_residual},
                           {"tolerance", q.config.tolerance},
                           {"mpi_ranks", MpiContext::instance().size()}});
  }
  if (!chain.is_null() && chain.contains("F0_N") && chain.at("F0_N").get<double>() > 0) {
    nlohmann::json edges = band_edges_of(chain, material);
    if (!edges.is_null()) meta["band_edges_khz"] = std::move(edges);
  }
  return meta;
}

}  // namespace granular
