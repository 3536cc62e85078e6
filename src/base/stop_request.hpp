#pragma once
/// A run asked to stop by a signal (a batch system's time limit, Ctrl-C): the signal is noted,
/// the time loop finishes its step, writes a checkpoint and ends.
#include <Teuchos_Comm.hpp>

#include <string>

namespace kiln
{
/// Makes SIGTERM, SIGINT and SIGUSR1 note a stop request instead of ending the process; a
/// second one ends it at once (the default action). Under Open MPI's mpirun send SIGUSR1:
/// mpirun passes it to every rank, while on SIGTERM it kills the ranks a second later.
void install_stop_handlers();
/// The signal that asked to stop on this rank, or 0.
int stop_signal();
/// The signal that asked any rank to stop, or 0 (collective).
int stop_signal(const Teuchos::Comm<int> &comm);
/// "SIGTERM", "SIGINT", "SIGUSR1" or "signal N".
std::string signal_name(int signal);
/// For tests: as if `signal` had arrived (0 clears).
void set_stop_signal(int signal);
} // namespace kiln
