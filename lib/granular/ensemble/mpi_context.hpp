#pragma once
// Moved to granular/parallel/mpi_context.hpp; this forwarding header goes once every branch has moved.
#include "granular/parallel/mpi_context.hpp"
