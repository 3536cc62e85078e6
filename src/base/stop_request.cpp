#include "base/stop_request.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <csignal>

namespace kiln
{
namespace
{
volatile std::sig_atomic_t received = 0;

extern "C" void note_stop(const int signal)
{
  received = signal;
  // A second signal ends the process.
  std::signal(signal, SIG_DFL);
}
} // namespace

void install_stop_handlers()
{
  std::signal(SIGTERM, note_stop);
  std::signal(SIGINT, note_stop);
  std::signal(SIGUSR1, note_stop);
}

int stop_signal()
{
  return received;
}

int stop_signal(const Teuchos::Comm<int> &comm)
{
  const int local = received;
  int global = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, local, Teuchos::outArg(global));
  return global;
}

std::string signal_name(const int signal)
{
  return signal == SIGTERM   ? "SIGTERM"
         : signal == SIGINT  ? "SIGINT"
         : signal == SIGUSR1 ? "SIGUSR1"
                             : "signal " + std::to_string(signal);
}

void set_stop_signal(const int signal)
{
  received = signal;
}
} // namespace kiln
