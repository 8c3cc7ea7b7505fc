#pragma once
/// @file Interrupt.hpp
/// @brief SIGINT and SIGTERM as a request to stop: the handler only records
/// the signal; the step loop and the Newton iterations ask every rank
/// (interruptSignalOnAnyRank) and stop cleanly, keeping the converged steps
/// in the result file. The handler restores the default action, so a second
/// signal ends the process at once. The `coulomb` executable installs it; a
/// program embedding the library decides for itself.
#include <Teuchos_Comm.hpp>

namespace coulomb {

/// Installs the recording handler for SIGINT and SIGTERM.
void installInterruptHandlers();

/// Collective: the signal some rank received since the start (the largest
/// number if several), 0 if none.
int interruptSignalOnAnyRank(const Teuchos::Comm<int>& comm);

/// "SIGINT", "SIGTERM" or "a signal".
const char* signalName(int signal);

}  // namespace coulomb
