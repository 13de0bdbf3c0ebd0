// The MPI component (libgranular_mpi.so; mpi_component.hpp): the only file of libgranular that
// calls MPI (the SLEPc component calls it through PETSc).
#define OMPI_SKIP_MPICXX 1  // the C API only: no MPI C++ bindings to link
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

#include "granular/parallel/detail/mpi_component.hpp"

namespace granular {

namespace {

bool mpi_initialized() {
  int flag = 0;
  MPI_Initialized(&flag);
  return flag != 0;
}

bool mpi_finalized() {
  int flag = 0;
  MPI_Finalized(&flag);
  return flag != 0;
}

void mpi_init() {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
}

void mpi_finalize() { MPI_Finalize(); }

void mpi_world(int* rank, int* size) {
  MPI_Comm_rank(MPI_COMM_WORLD, rank);
  MPI_Comm_size(MPI_COMM_WORLD, size);
}

void mpi_gather(const std::vector<double>& send, std::vector<double>& received) {
  int rank = 0, size = 1;
  mpi_world(&rank, &size);
  int count = static_cast<int>(send.size());
  std::vector<int> counts(size), offsets(size);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  received.clear();
  if (rank == 0) {
    int total_count = 0;
    for (int r = 0; r < size; ++r) {
      offsets[r] = total_count;
      total_count += counts[r];
    }
    received.resize(static_cast<std::size_t>(total_count));
  }
  MPI_Gatherv(send.data(), count, MPI_DOUBLE, received.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0,
              MPI_COMM_WORLD);
}

bool mpi_all(bool flag) {
  int local = flag ? 1 : 0, global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD);
  return global != 0;
}

}  // namespace

}  // namespace granular

const granular::detail::MpiComponent* granular_mpi_component() {
  using namespace granular;
  static const detail::MpiComponent component{&mpi_initialized, &mpi_finalized, &mpi_init, &mpi_finalize,
                                              &mpi_world,       &mpi_gather,    &mpi_all};
  return &component;
}
