// Ctrl-C asks a long run to stop; it does not stop the process.
#include "granular/ensemble/interrupt.hpp"

#include <csignal>

#include <gtest/gtest.h>

namespace granular {
namespace {

TEST(Interrupt, TheFirstSignalIsARequestNotAnEnd) {
  const auto requested = stop_on_interrupt("interrupt_test");
  EXPECT_FALSE(requested());
  std::raise(SIGTERM);  // the process goes on: the handler only records it
  EXPECT_TRUE(requested());
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

}  // namespace
}  // namespace granular
