#include "granular/study/butterfly.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "granular/ensemble/parallel_realizations.hpp"
#include "granular/error.hpp"
#include "granular/io/csv_writer.hpp"
#include "granular/io/range_syntax.hpp"
#include "granular/linear/dynamical_matrix.hpp"
#include "granular/linear/spectrum.hpp"
#include "granular/number_format.hpp"

namespace granular {

std::vector<double> default_butterfly_ratios() { return parse_number_list("0.005:0.995:0.005", "ratios", 0.005); }

namespace {
void read_ratios(ButterflyConfig& c, const std::string& text) { c.ratios = parse_number_list(text, "ratios", 0.005); }
std::string write_ratios(const ButterflyConfig& c) { return format_number_list(c.ratios); }
}  // namespace

const ParameterTable<ButterflyConfig>& butterfly_parameters() {
  using C = ButterflyConfig;
  static const ParameterTable<C> table{
      {"ratios", {}, {read_ratios, write_ratios}, "ratios beta > 0: start:stop[:step] (step 0.005) or a,b,c"},
      {"largest_box", &C::largest_box,
       "largest box of the dimension fit, as a fraction of the spectrum's extent (0: 5 %, or 8 smallest boxes if "
       "more)"},
      {"smallest_box", &C::smallest_box_spacings, "smallest box of the fit, in mean level spacings (extent / N)"},
      {"box_sizes", &C::box_sizes, "box sizes fitted, evenly spaced in log"}};
  return table;
}

ChainRecipe at_ratio(ChainRecipe chain, double beta) {
  std::get<Quasiperiodic>(chain.source).ratio = beta;
  return chain;
}

void validate_ratios(const ChainRecipe& chain, const std::vector<double>& ratios) {
  if (!chain.as<Quasiperiodic>())
    throw InvalidInput("quasi", ": a butterfly needs a quasiperiodic chain (s1, s2 or cylinders)");
  if (ratios.empty()) throw InvalidInput("ratios", ": no values");
  for (double beta : ratios) {
    if (!std::isfinite(beta) || !(beta > 0))
      throw InvalidInput("ratios", " " + format_number(beta) + ": every ratio beta must be finite and > 0");
    validate(at_ratio(chain, beta));
  }
}

void validate(const ButterflyConfig& c) {
  validate_ratios(c.chain, c.ratios);
  if (!(c.chain.F0 > 0)) throw InvalidInput("F0", " " + format_number(c.chain.F0) + ": the spectrum needs F0 > 0");
  if (!(c.largest_box >= 0 && c.largest_box <= 1))
    throw InvalidInput("largest_box",
                       " " + format_number(c.largest_box) + ": a fraction of the extent in (0, 1], or 0 (automatic)");
  const double smallest = c.smallest_box_spacings / static_cast<double>(c.chain.N);
  const double largest = largest_box_fraction(c, c.chain.N);
  if (!(smallest > 0) || !(smallest < largest))
    throw InvalidInput("smallest_box", " " + format_number(c.smallest_box_spacings) +
                                           ": must be > 0 and below the largest box (in spacings: " +
                                           format_number(largest * static_cast<double>(c.chain.N)) + ")");
  if (c.box_sizes < 2) throw InvalidInput("box_sizes", " " + std::to_string(c.box_sizes) + ": at least 2");
}

double largest_box_fraction(const ButterflyConfig& c, std::size_t modes) {
  if (c.largest_box > 0) return c.largest_box;
  return std::min(1.0, std::max(0.05, 8 * c.smallest_box_spacings / static_cast<double>(modes)));
}

std::vector<double> butterfly_box_sizes(const ButterflyConfig& c, double extent, std::size_t modes) {
  return geometric_box_sizes(largest_box_fraction(c, modes) * extent,
                             c.smallest_box_spacings * extent / static_cast<double>(modes), c.box_sizes);
}

std::vector<ButterflyColumn> compute_butterfly(const ButterflyConfig& c, const RunOptions& run) {
  validate(c);
  std::vector<ButterflyColumn> columns(c.ratios.size());
  parallel_realizations(
      c.ratios.size(), resolve_threads(run.threads),
      [&](std::size_t i, int) {
        if (run.cancelled && run.cancelled()) throw Cancelled();
        const Spectrum s = spectrum(dynamical_matrix(at_ratio(c.chain, c.ratios[i]).chain(c.realization)), all_modes(),
                                    {.method = SpectrumMethod::fast});
        ButterflyColumn& col = columns[i];
        col.ratio = c.ratios[i];
        col.freq_khz = s.freq_khz;
        col.ipr = s.ipr;
        const double extent = s.freq_khz.back() - s.freq_khz.front();
        col.dimension = box_counting_dimension(s.freq_khz, butterfly_box_sizes(c, extent, s.size()));
      },
      run.progress);
  return columns;
}

void write_butterfly_csv(std::ostream& out, const std::vector<ButterflyColumn>& columns) {
  CsvWriter table(out, {"ratio", "mode", "freq_khz", "ipr"});
  for (const ButterflyColumn& col : columns)
    for (std::size_t k = 0; k < col.freq_khz.size(); ++k) table.row(col.ratio, k + 1, col.freq_khz[k], col.ipr[k]);
}

nlohmann::json describe_butterfly(const ButterflyConfig& c, const std::vector<ButterflyColumn>& columns) {
  nlohmann::json meta;
  meta["chain"] = describe(c.chain, c.realization);
  meta["chain"]["quasiperiodic"]["ratio"] = "each of ratios";
  meta["ratios"] = c.ratios;
  meta["realization"] = c.realization;
  meta["solver"] = "fast";
  nlohmann::json box = {{"largest_box_of_extent", largest_box_fraction(c, c.chain.N)},
                        {"smallest_box_spacings", c.smallest_box_spacings},
                        {"box_sizes", c.box_sizes},
                        {"fit", "least squares of ln N(eps) on ln(1/eps); error = standard error of the slope"}};
  for (const ButterflyColumn& col : columns) {
    box["ratio"].push_back(col.ratio);
    box["dimension"].push_back(col.dimension.dimension);
    box["error"].push_back(col.dimension.error);
    box["box_khz_largest"].push_back(col.dimension.box_sizes.front());
    box["box_khz_smallest"].push_back(col.dimension.box_sizes.back());
  }
  meta["box_counting"] = box;
  return meta;
}

}  // namespace granular
