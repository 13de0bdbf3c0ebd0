// crystal: the linear spectrum of a two-dimensional granular crystal (docs/crystals.md): a square
// or hexagonal packing held by walls or closed on a torus, its static state by Newton on the
// contact network, and every mode (dense LAPACK) or the modes nearest a frequency (ARPACK, or SLEPc
// over MPI ranks), with vector IPRs and the level-spacing ratio <r>.
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/outputs.hpp"
#include "common/tool_main.hpp"
#include "granular/crystal/crystal_study.hpp"
#include "granular/files/crystal_files.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/io/output_paths.hpp"
#include "granular/parallel/mpi_context.hpp"

int main(int argc, char** argv) {
  using namespace granular;
  CLI::App app{
      "Modes of a 2D granular crystal: Lx x Ly steel beads in a square or hexagonal packing, held by four walls\n"
      "(each pushing with --F0 per bead it touches) or periodic under --strain, its static state solved by\n"
      "Newton (Hertz normal contacts). Every mode by dense LAPACK, or --count modes nearest --near [kHz] by\n"
      "ARPACK (SLEPc from 1e5 beads; --method chooses), or every mode in --window lo:hi [kHz] by SLEPc's spectrum\n"
      "slicing (under mpirun -n P the ranks share the matrix's rows).\n"
      "Writes PREFIX.csv (mode,freq_khz,omega2,ipr)\n"
      "and PREFIX.json (every parameter, the static state, <r>); with --vectors PREFIX-modes.csv.",
      "crystal"};
  tool::describe_common(app);
  CrystalCase c;
  std::string output = "crystal", dump_matrix;
  bool quiet = false;
  tool::add_parameters(app, c, crystal_parameters());
  tool::add_output_option(app, output, " (and PREFIX-modes.csv with --vectors)");
  app.add_option("--dump-matrix", dump_matrix,
                 "also write D as PREFIX.row_start.u64, PREFIX.column.u64, PREFIX.value.f64 (compressed rows, "
                 "little-endian; for another solver: tests/benchmarks/crystal_scipy.py)");
  app.add_flag("--quiet", quiet, "no summary on stderr");

  return tool::run(app, argc, argv, [&] {
    tool::Metadata meta("crystal", argc, argv);
    validate(c);
    const bool writer = MpiContext::instance().root();
    const TableOutputs paths{output + ".csv", output + ".json"};
    const std::string modes_path = output + "-modes.csv";
    const auto claim = tool::claim_output(output, meta.command());
    if (writer) {
      check_writable(paths.csv);
      check_writable(paths.json);
      if (c.vectors) check_writable(modes_path);
    }
    const CrystalResult r = crystal_study(c);
    if (!writer) return;
    if (!dump_matrix.empty()) write_crystal_matrix(dump_matrix, r.matrix);
    if (!quiet)
      std::fprintf(stderr, "crystal: %zu beads, %zu modes by %s in %.3g s; <r> = %.4f over %zu ratios\n",
                   r.packing.size(), r.spectrum.size(), r.method.c_str(), r.solve_seconds, r.ratio.mean, r.ratio.count);
    AtomicFile csv(paths.csv);
    write_crystal_csv(csv.stream(), r);
    std::vector<PendingOutput*> outputs{&csv};
    meta.merge(describe(c, r));
    meta["output"] = paths.csv;
    std::optional<AtomicFile> modes;
    if (c.vectors) {
      modes.emplace(modes_path);
      write_crystal_modes_csv(modes->stream(), r);
      outputs.push_back(&*modes);
      meta["modes"] = modes_path;
    }
    meta.write(paths.json, outputs);
  });
}
