#include "app/results_lock.hpp"

#include "base/errors.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace kiln
{
namespace internal
{
namespace
{
/// The holder's "pid PID on HOST" as written in the lock file, or "" if unreadable.
std::string lock_holder(const int fd)
{
  char text[256] = {};
  const ssize_t n = pread(fd, text, sizeof text - 1, 0);
  std::string holder = n > 0 ? std::string(text, static_cast<std::size_t>(n)) : "";
  while (!holder.empty() && (holder.back() == '\n' || holder.back() == ' '))
    holder.pop_back();
  return holder;
}

/// Takes the lock on rank 0: the locked descriptor, or -1 with `error` set.
int take_lock(const std::string &path, const std::string &what, const std::string &parameter,
              std::string &error)
{
  for (int attempt = 0; attempt < 100; ++attempt)
  {
    const int fd = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
    {
      const auto slash = path.find_last_of('/');
      const std::string folder = slash == std::string::npos ? "." : path.substr(0, slash + 1);
      error = std::string("cannot create the lock file (") + std::strerror(errno) +
              "); check that the folder \"" + folder +
              "\" exists and is writable, or choose another " + parameter;
      return -1;
    }
    if (flock(fd, LOCK_EX | LOCK_NB) != 0)
    {
      const int e = errno;
      const std::string holder = lock_holder(fd);
      close(fd);
      if (e != EWOULDBLOCK)
      {
        error = std::string("cannot lock the file (") + std::strerror(e) + ")";
        return -1;
      }
      error = "another Kiln run (" + (holder.empty() ? std::string("process unknown") : holder) +
              ") is writing " + what +
              " and holds this lock file; wait for it to end, or give "
              "this run another " +
              parameter;
      return -1;
    }
    // The holder before us may have removed the file after we opened it: then we hold a lock
    // on a file nobody else sees; try again on the one at `path`.
    struct stat by_fd = {}, by_path = {};
    if (fstat(fd, &by_fd) == 0 && stat(path.c_str(), &by_path) == 0 &&
        by_fd.st_ino == by_path.st_ino && by_fd.st_dev == by_path.st_dev)
    {
      char host[256] = {};
      gethostname(host, sizeof host - 1);
      const std::string text =
          "pid " + std::to_string(getpid()) + " on " + std::string(host) + "\n";
      const bool written = ftruncate(fd, 0) == 0 && pwrite(fd, text.data(), text.size(), 0) ==
                                                        static_cast<ssize_t>(text.size());
      (void)written; // the lock holds without the text; only a second run's message lacks it
      return fd;
    }
    close(fd);
  }
  error = "the lock file keeps being replaced; is another program removing it?";
  return -1;
}
} // namespace
} // namespace internal

ResultsLock::ResultsLock(const std::string &path, const Teuchos::Comm<int> &comm,
                         const std::string &what, const std::string &parameter)
    : path_(path)
{
  std::string error;
  if (comm.getRank() == 0)
    fd_ = internal::take_lock(path_, what, parameter, error);
  check_collectively(comm, error.empty(), path_, error);
}

ResultsLock::~ResultsLock()
{
  if (fd_ < 0)
    return;
  // Removed while still held, so no other run can have locked the file we remove.
  unlink(path_.c_str());
  close(fd_);
}
} // namespace kiln
