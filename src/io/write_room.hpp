#pragma once
/// Private to src/io: a full disk or a file-size limit, found before a write or named after
/// one failed, in the words every writer uses (a WriteError: exit 2, the run cannot go on).
#include <cstdint>
#include <string>

namespace kiln
{
namespace internal
{
/// "" if `bytes` more fit in the file `path` (free space on its disk and the file-size
/// limit, ulimit -f), else why not: "No space left on device: ... bytes free, ...". Local.
std::string room_shortfall(const std::string &path, std::uintmax_t bytes);

/// What follows a write's failure in its message: the run cannot go on, what to do.
std::string write_failure_advice();

/// True for an errno that says the disk or the file may not grow (ENOSPC, EFBIG, EDQUOT, EIO):
/// a WriteError, not a mistake in the input.
bool is_write_failure(int error);

/// After writing `what` to the text file `path` (ok: it went well; `error`: errno after it):
/// a failure of the disk or the file-size limit throws a WriteError naming both and the
/// system's reason; other failures are left to the caller.
void check_text_write(bool ok, int error, const std::string &path, const std::string &what);
} // namespace internal
} // namespace kiln
