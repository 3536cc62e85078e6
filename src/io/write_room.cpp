#include "io/write_room.hpp"

#include "base/errors.hpp"

#include <sys/resource.h>
#include <sys/statvfs.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace kiln
{
namespace internal
{
std::string room_shortfall(const std::string &path, const std::uintmax_t bytes)
{
  std::ostringstream text;
  struct statvfs disk = {};
  struct rlimit limit = {};
  std::error_code e;
  const std::uintmax_t now = std::filesystem::file_size(path, e);
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  const std::string folder = parent.empty() ? std::string(".") : parent.string();
  if (statvfs(folder.c_str(), &disk) == 0 &&
      static_cast<std::uintmax_t>(disk.f_bavail) * disk.f_frsize < bytes)
    text << std::strerror(ENOSPC) << ": "
         << static_cast<std::uintmax_t>(disk.f_bavail) * disk.f_frsize
         << " bytes free, the next step needs about " << bytes;
  else if (getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY && !e &&
           now + bytes > static_cast<std::uintmax_t>(limit.rlim_cur))
    text << std::strerror(EFBIG) << ": the file-size limit (ulimit -f) is "
         << static_cast<std::uintmax_t>(limit.rlim_cur) << " bytes, the file has " << now
         << " and the next step needs about " << bytes << " more";
  return text.str();
}

std::string write_failure_advice()
{
  return "the run cannot go on. Free space on the disk (or raise the file-size limit) and "
         "continue from the last checkpoint with kiln INPUT.xml --restart; the steps written "
         "before are kept";
}

bool is_write_failure(const int error)
{
  return error == ENOSPC || error == EFBIG || error == EDQUOT || error == EIO;
}

void check_text_write(const bool ok, const int error, const std::string &path,
                      const std::string &what)
{
  if (!ok && is_write_failure(error))
    throw WriteError(path + ": cannot write " + what + " (" + std::strerror(error) + "); " +
                     write_failure_advice());
}
} // namespace internal
} // namespace kiln
