#include "granular/parallel/mpi_context.hpp"

#ifdef GRANULAR_HAVE_MPI
#define OMPI_SKIP_MPICXX 1  // the C API only: no MPI C++ bindings to link
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

#include <cstdlib>

#include "granular/error.hpp"

namespace granular {

MpiContext& MpiContext::instance() {
  static MpiContext context;
  return context;
}

#ifdef GRANULAR_HAVE_MPI
namespace {
/// Started by mpirun/mpiexec (Open MPI, PMIx or MPICH-style launchers set these)? A plain
/// process stays a single rank without paying for MPI_Init.
bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"})
    if (std::getenv(v)) return true;
  return false;
}
}  // namespace
#endif

MpiContext::MpiContext() {
#ifdef GRANULAR_HAVE_MPI
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized || launched_by_mpi()) start();
#endif
}

void MpiContext::require() {
  if (!active_) start();
}

void MpiContext::start() {
#ifdef GRANULAR_HAVE_MPI
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    initialized_here_ = true;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  active_ = true;
#endif
}

MpiContext::~MpiContext() {
#ifdef GRANULAR_HAVE_MPI
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (initialized_here_ && !finalized) MPI_Finalize();
#endif
}

std::vector<std::vector<double>> MpiContext::gather_rows(std::size_t total, const std::vector<std::uint64_t>& indices,
                                                         const std::vector<std::vector<double>>& rows) const {
  std::vector<std::vector<double>> all(total);
  if (size_ == 1) {
    for (std::size_t i = 0; i < indices.size(); ++i) all[indices[i]] = rows[i];
    return all;
  }
#ifdef GRANULAR_HAVE_MPI
  // Flatten as [index, length, values…]… and gather the variable-length buffers on rank 0.
  std::vector<double> send;
  for (std::size_t i = 0; i < indices.size(); ++i) {
    send.push_back(static_cast<double>(indices[i]));
    send.push_back(static_cast<double>(rows[i].size()));
    send.insert(send.end(), rows[i].begin(), rows[i].end());
  }
  int count = static_cast<int>(send.size());
  std::vector<int> counts(size_), offsets(size_);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<double> received;
  if (rank_ == 0) {
    int total_count = 0;
    for (int r = 0; r < size_; ++r) {
      offsets[r] = total_count;
      total_count += counts[r];
    }
    received.resize(static_cast<std::size_t>(total_count));
  }
  MPI_Gatherv(send.data(), count, MPI_DOUBLE, received.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0,
              MPI_COMM_WORLD);
  if (rank_ != 0) return {};
  for (std::size_t p = 0; p < received.size();) {
    const auto index = static_cast<std::size_t>(received[p]);
    const auto length = static_cast<std::size_t>(received[p + 1]);
    if (index >= total) throw NumericalError("MPI gather: realization index out of range");
    all[index].assign(received.begin() + static_cast<long>(p + 2), received.begin() + static_cast<long>(p + 2 + length));
    p += 2 + length;
  }
  return all;
#else
  return all;
#endif
}

bool MpiContext::all(bool flag) const {
#ifdef GRANULAR_HAVE_MPI
  if (size_ > 1) {
    int local = flag ? 1 : 0, global = 0;
    MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD);
    return global != 0;
  }
#endif
  return flag;
}

}  // namespace granular
