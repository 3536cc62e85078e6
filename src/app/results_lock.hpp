#pragma once
/// One run at a time per File Base: an advisory lock on BASE.lock.
#include <Teuchos_Comm.hpp>

#include <string>

namespace kiln
{
/// Rank 0 takes an exclusive flock(2) on `path` (created if needed) and writes its process
/// id and host into it; if another process holds it, every rank throws the same InputError
/// naming that process and the lock file (so a second run on the same File Base exits with
/// status 1 before it touches any file). The destructor removes the file and releases the
/// lock; if the process dies first (a crash, SIGKILL) the kernel releases it, and the file
/// left behind no longer stops anyone. A lock file replaced while being taken (the holder
/// removed it on exit) is taken again on the new file. Collective (constructor).
class ResultsLock
{
public:
  /// `what` and `parameter` name the files and the parameter in the message (the
  /// checkpoints under a Checkpoint/File Base of their own take a lock of their own).
  ResultsLock(const std::string &path, const Teuchos::Comm<int> &comm,
              const std::string &what = "results with this File Base",
              const std::string &parameter = "Kiln/Output/\"File Base\"");
  ~ResultsLock();
  ResultsLock(const ResultsLock &) = delete;
  ResultsLock &operator=(const ResultsLock &) = delete;

  const std::string &path() const { return path_; }

private:
  std::string path_;
  int fd_ = -1; ///< rank 0: the locked file
};
} // namespace kiln
