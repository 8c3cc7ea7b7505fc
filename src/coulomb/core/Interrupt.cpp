/// @file Interrupt.cpp
/// @brief The recording handler of SIGINT/SIGTERM (Interrupt.hpp).
#include "coulomb/core/Interrupt.hpp"

#include <csignal>

#include <Teuchos_CommHelpers.hpp>

namespace coulomb {

namespace {

volatile std::sig_atomic_t received = 0;

extern "C" void recordSignal(int signal) { received = signal; }

}  // namespace

void installInterruptHandlers() {
  struct sigaction action {};
  action.sa_handler = recordSignal;
  sigemptyset(&action.sa_mask);
  // SA_RESETHAND: the second signal takes the default action (ends the process).
  action.sa_flags = SA_RESETHAND | SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int interruptSignalOnAnyRank(const Teuchos::Comm<int>& comm) {
  const int local = received;
  int any = local;
  if (comm.getSize() > 1) Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, local, Teuchos::outArg(any));
  return any;
}

const char* signalName(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "a signal";
}

}  // namespace coulomb
