#pragma once
/// Private to src/io: HDF5 failures as one Kiln message instead of HDF5's error stack.
#include <hdf5.h>

#include <string>

namespace kiln
{
namespace internal
{
/// Turns off HDF5's printout of its error stack for the rest of the process: every HDF5 call
/// Kiln makes is checked, and a failure becomes one Kiln message naming the file and the
/// system's reason (hdf5_failure_reason()).
void quiet_hdf5_errors();

/// Silences HDF5's printout of its error stack while it lives, and restores the printout
/// that was set before (for calls whose failure becomes a Kiln error message instead).
class QuietHdf5Errors
{
public:
  QuietHdf5Errors();
  ~QuietHdf5Errors();
  QuietHdf5Errors(const QuietHdf5Errors &) = delete;
  QuietHdf5Errors &operator=(const QuietHdf5Errors &) = delete;

private:
  H5E_auto2_t old_function_ = nullptr;
  void *old_data_ = nullptr;
};

/// The system's reason for the HDF5 failure just seen, read from HDF5's error stack (e.g.
/// "No space left on device", "File too large"), or "" if the stack names none. Call it right
/// after the failed call: the next HDF5 call clears the stack.
std::string hdf5_failure_reason();

/// " (REASON)" for hdf5_failure_reason() = REASON, "" for "".
std::string in_parentheses(const std::string &reason);
} // namespace internal
} // namespace kiln
