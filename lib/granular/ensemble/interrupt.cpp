#include "granular/ensemble/interrupt.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstring>

namespace granular {
namespace {

volatile std::sig_atomic_t interrupt_requested = 0;
char interrupt_message[160];

void on_interrupt(int signal) {
  interrupt_requested = 1;
  std::signal(signal, SIG_DFL);  // a second Ctrl-C stops at once
  const ssize_t ignored = ::write(2, interrupt_message, std::strlen(interrupt_message));
  (void)ignored;
}

}  // namespace

std::function<bool()> stop_on_interrupt(const std::string& program) {
  std::snprintf(interrupt_message, sizeof interrupt_message,
                "\n%s: stopping once the realizations in flight are saved (Ctrl-C again: stop at once)\n",
                program.c_str());
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  return [] { return interrupt_requested != 0; };
}

}  // namespace granular
