#include "granular/parallel/mpi_context.hpp"

#include <dlfcn.h>

#include <cstdlib>

#include "granular/detail/component.hpp"
#include "granular/error.hpp"
#include "granular/parallel/detail/mpi_component.hpp"

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

/// Whether MPI is in the process already (a program or Python module that uses MPI itself may
/// have initialized it): only then can it be initialized without this library having loaded it.
bool mpi_loaded() {
#if GRANULAR_COMPONENTS_BUILT_IN
  return true;  // linked in
#else
  return dlsym(RTLD_DEFAULT, "MPI_Initialized") != nullptr;
#endif
}

/// The MPI component, loaded on first use.
const detail::MpiComponent& mpi_calls() {
  static const detail::MpiComponent* const component = GRANULAR_COMPONENT_TABLE(detail::MpiComponent, mpi, "MPI");
  return *component;
}
}  // namespace
#endif

MpiContext::MpiContext() {
#ifdef GRANULAR_HAVE_MPI
  // Loading MPI only to learn that it is not initialized would cost every plain run its start-up.
  const bool launched = launched_by_mpi();
  if (launched || (mpi_loaded() && mpi_calls().initialized())) start();
#endif
}

void MpiContext::require() {
  if (!active_) start();
}

void MpiContext::start() {
#ifdef GRANULAR_HAVE_MPI
  const detail::MpiComponent& mpi = mpi_calls();
  if (!mpi.initialized()) {
    mpi.init();
    initialized_here_ = true;
  }
  mpi.world(&rank_, &size_);
  active_ = true;
#endif
}

MpiContext::~MpiContext() {
#ifdef GRANULAR_HAVE_MPI
  if (initialized_here_ && !mpi_calls().finalized()) mpi_calls().finalize();
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
  std::vector<double> received;
  mpi_calls().gather(send, received);
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
  if (size_ > 1) return mpi_calls().all(flag);
#endif
  return flag;
}

}  // namespace granular
