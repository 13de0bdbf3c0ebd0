#include "granular/crystal/crystal_study.hpp"

#include <chrono>
#include <cmath>
#include <numbers>

#include <nlohmann/json.hpp>

#include "granular/error.hpp"
#include "granular/number_format.hpp"
#include "granular/parameter_json.hpp"

namespace granular {
CrystalResult crystal_study(const CrystalCase& c) {
  validate(c);
  CrystalResult r;
  r.packing = make_packing(c.disorder.width > 0 ? disordered(c.packing, c.disorder) : c.packing);
  r.state = static_state(r.packing);
  r.matrix = crystal_matrix(r.packing, r.state);
  const CrystalMatrix& d = r.matrix;
  const CrystalSpectrumConfig modes{.vectors = c.vectors};
  r.method = c.window                                                                 ? "slepc-slicing"
             : !c.near                                                                ? "lapack"
             : nearest_method_for(c.method, r.packing.size()) == NearestMethod::slepc ? "slepc"
                                                                                      : "arpack";
  const auto start = std::chrono::steady_clock::now();
  r.spectrum = c.window ? crystal_window_modes(d, c.window->first * 1e3, c.window->second * 1e3, modes)
               : c.near ? crystal_nearest_modes(d, *c.near * 1e3, c.count, modes, c.method)
                        : crystal_spectrum(d, modes);
  if (r.spectrum.size() == 0)
    throw InvalidInput("window", " " + format_number(c.window->first) + ":" + format_number(c.window->second) +
                                     ": no mode of the crystal in it");
  r.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::vector<double>& f = r.spectrum.freq_hz;  // ascending; the window defaults to all of them
  r.ratio =
      spacing_ratio(r.spectrum, c.ratio_lo ? *c.ratio_lo * 1e3 : f.front(), c.ratio_hi ? *c.ratio_hi * 1e3 : f.back());
  return r;
}

nlohmann::json describe(const CrystalCase& c, const CrystalResult& r) {
  nlohmann::json meta;
  meta["parameters"] = describe_rows(c, crystal_parameters());
  const Packing& p = r.packing;
  meta["packing"] = {{"beads", p.size()},
                     {"contacts", p.contacts.size()},
                     {"wall_contacts", p.wall_contacts.size()},
                     {"spacing_m", p.spacing},
                     {"uniform_overlap_m", p.uniform_overlap}};
  const StaticState& s = r.state;
  meta["static_state"] = {{"newton_steps", s.iterations},
                          {"max_imbalance", s.imbalance},
                          {"open_contacts", s.open_contacts.size()},
                          {"open_wall_contacts", s.open_wall_contacts.size()},
                          {"rigid", s.rigid}};
  meta["spectrum"] = {{"method", r.method},
                      {"solve_seconds", r.solve_seconds},
                      {"modes", r.spectrum.size()},
                      {"spacing_ratio", r.ratio.count > 0 ? nlohmann::json(r.ratio.mean) : nlohmann::json(nullptr)},
                      {"spacing_ratios_averaged", r.ratio.count},
                      {"poisson_ratio", 2 * std::numbers::ln2 - 1},
                      {"goe_ratio", 0.5307}};
  return meta;
}

}  // namespace granular
