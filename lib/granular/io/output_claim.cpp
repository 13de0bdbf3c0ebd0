#include "granular/io/output_claim.hpp"

#include <exception>

#include "granular/error.hpp"
#include "granular/io/atomic_file.hpp"
#include "granular/parallel/mpi_context.hpp"

namespace granular {

OutputClaim::OutputClaim(const std::string& prefix, const std::string& command, const std::function<void()>& then) {
  const MpiContext& mpi = MpiContext::instance();
  std::exception_ptr failure;
  bool refused = false;
  if (mpi.root()) try {
      check_writable(prefix + ".lock");  // the folder's problem in the words of every output
      lock_.emplace(prefix, command);
      if (then) then();
    } catch (const InvalidInput&) {
      failure = std::current_exception();
      refused = true;
    } catch (...) {
      failure = std::current_exception();
    }
  const bool ok = mpi.all(!failure);
  if (ok) return;
  const bool was_refused = !mpi.all(!refused);  // the others end as rank 0 does
  lock_.reset();
  if (failure) std::rethrow_exception(failure);
  throw ClaimFailedOnRoot{was_refused};
}

}  // namespace granular
