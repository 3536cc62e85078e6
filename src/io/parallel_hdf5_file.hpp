#pragma once
/// Private to src/io: an HDF5 file written collectively with MPI-IO by every rank of a
/// communicator, metadata (groups, attributes, dataset headers) included. Every member function
/// is collective; a failed HDF5 call is a kiln::InputError naming the file, thrown on every
/// rank alike.
#include "io/h5_handle.hpp"

#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

namespace kiln
{
namespace internal
{
/// The rows of a (rows) or (rows x c) dataset this rank writes, as runs of consecutive rows.
struct OwnedRows
{
  struct Run
  {
    hsize_t first = 0;
    hsize_t count = 0;
  };
  /// `owned`: this rank's rows, increasing; `n_rows`: the rows of the dataset.
  OwnedRows(const std::vector<int> &owned, int n_rows);

  hsize_t n_rows = 0;
  std::size_t n_owned = 0;
  std::vector<Run> runs;
};

/// An attribute holding one double (written as IEEE F64LE), 32-bit integer (STD I32LE) or
/// text (a fixed-length string).
struct ScalarAttribute
{
  const char *name;
  std::variant<double, std::int32_t, std::string> value;
};

class ParallelHdf5File
{
public:
  /// Creates (or truncates) `path`; InputError on every rank when it cannot.
  ParallelHdf5File(MPI_Comm comm, const std::string &path);
  const std::string &path() const { return path_; }

  /// Creates the group `name` (a path from the root, e.g. "steps/000000").
  H5Handle create_group(const std::string &name) const;
  /// Writes the dataset `name` in `location` (a file or group id): (rows) values for one
  /// component, (rows x n_components) for more, from `values`, n_components values per row
  /// of `rows`, row after row.
  void write_rows(hid_t location, const std::string &name, const OwnedRows &rows, int n_components,
                  const std::vector<double> &values) const;
  void write_rows(hid_t location, const std::string &name, const OwnedRows &rows, int n_components,
                  const std::vector<std::int64_t> &values) const;
  void write_rows(hid_t location, const std::string &name, const OwnedRows &rows, int n_components,
                  const std::vector<std::int32_t> &values) const;
  /// Appends `values` (rank 0's; every rank passes as many) to the 1-D float64 dataset `name`
  /// in `location`, which is created extendible (chunked, no size limit) if it does not exist;
  /// returns whether it was created.
  bool append_rows(hid_t location, const std::string &name,
                   const std::vector<double> &values) const;
  /// Writes the attributes on `location`, in order; `what` names them in the error message.
  void write_attributes(hid_t location, const std::vector<ScalarAttribute> &attributes,
                        const std::string &what) const;
  /// Opens the dataset `name` in `location`.
  H5Handle open_dataset(hid_t location, const std::string &name) const;
  /// The file itself, as a location (for root attributes).
  hid_t root() const { return file_.get(); }
  /// A WriteError (on every rank) naming the system's reason ("No space left on device",
  /// "File too large") unless the file's disk has `bytes` free and the file-size limit
  /// (ulimit -f) lets it grow by as much: checked before a step is written, on every rank (their
  /// limits may differ), because HDF5 cannot flush or close a parallel file cleanly after a
  /// write failed on some ranks only: its ranks hang in different collectives. Then rank 0
  /// allocates those bytes after the file's end (fallocate, keeping its size), so that another
  /// program filling the disk meanwhile cannot fail the step's writes (where the file system
  /// has no fallocate, the check alone).
  void reserve(std::uintmax_t bytes) const;
  /// The file's size on disk now [bytes] (rank 0's view, on every rank).
  std::uintmax_t size() const;
  /// Flushes everything written so far to disk.
  void flush() const;
  /// Closes the file (every handle on it must be closed); nothing can be written after.
  void close();
  /// InputError on every rank, naming the file and "`what` failed", unless `local_ok` is
  /// true on every rank.
  void check_io(bool local_ok, const std::string &what) const;

private:
  void write_rows(hid_t location, const std::string &name, hid_t file_type, hid_t memory_type,
                  const void *data, const OwnedRows &rows, int n_components) const;

  MPI_Comm comm_;
  std::string path_;
  // Declared in the order they are opened: destroyed (closed) in reverse.
  H5Handle fapl_;
  H5Handle dxpl_;
  H5Handle file_;
};
} // namespace internal
} // namespace kiln
