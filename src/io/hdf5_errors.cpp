#include "io/hdf5_errors.hpp"

#include <hdf5.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace kiln
{
namespace internal
{
namespace
{
herr_t collect_description(const unsigned, const H5E_error2_t *error, void *data)
{
  if (error != nullptr && error->desc != nullptr)
    static_cast<std::vector<std::string> *>(data)->emplace_back(error->desc);
  return 0;
}

/// The system's text for "errno = N" in `description`, or "".
std::string errno_text(const std::string &description)
{
  const auto at = description.find("errno = ");
  if (at == std::string::npos)
    return "";
  const int number = std::atoi(description.c_str() + at + 8);
  return number > 0 ? std::strerror(number) : "";
}
} // namespace

void quiet_hdf5_errors()
{
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

QuietHdf5Errors::QuietHdf5Errors()
{
  H5Eget_auto2(H5E_DEFAULT, &old_function_, &old_data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

QuietHdf5Errors::~QuietHdf5Errors()
{
  H5Eset_auto2(H5E_DEFAULT, old_function_, old_data_);
}

std::string hdf5_failure_reason()
{
  std::vector<std::string> descriptions;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collect_description, &descriptions);
  // The innermost call (the file driver's write(2) or MPI-IO call) says why.
  for (const std::string &d : descriptions)
    if (const std::string text = errno_text(d); !text.empty())
      return text;
  for (const std::string &d : descriptions)
    if (d.find("MPI_ERR_NO_SPACE") != std::string::npos)
      return std::strerror(ENOSPC);
  for (const std::string &d : descriptions)
    if (d.find("MPI_ERR_") != std::string::npos)
      return d;
  return descriptions.empty() ? "" : descriptions.back();
}

std::string in_parentheses(const std::string &reason)
{
  return reason.empty() ? "" : " (" + reason + ")";
}
} // namespace internal
} // namespace kiln
