#pragma once
/// Private to src/io: the serial HDF5 reads and writes of a checkpoint (rank 0 writes it, every
/// rank reads it). A failure is a std::runtime_error naming the object ("attribute time",
/// "dataset x") and the system's reason, which write_checkpoint and read_checkpoint turn into
/// one InputError naming the file.
#include "io/h5_handle.hpp"

#include <hdf5.h>

#include <cstddef>
#include <string>
#include <vector>

namespace kiln
{
namespace internal
{
/// An HDF5 handle closed at the end of its scope (an H5Handle) that must be valid: an invalid
/// (< 0) identifier is the error `what`.
class H5
{
public:
  H5(hid_t id, H5Handle::Closer closer, const std::string &what);
  /// Closes the object now; an error (`what` failed) if that fails.
  void close(const std::string &what);
  operator hid_t() const { return handle_.get(); }

private:
  H5Handle handle_;
};

/// An error `what` (with HDF5's reason) if `status` < 0.
void check(herr_t status, const std::string &what);

/// Scalar attributes: IEEE F64LE, STD I32LE or a fixed-length string.
void write_attribute(hid_t object, const std::string &name, double value);
void write_attribute(hid_t object, const std::string &name, int value);
void write_attribute(hid_t object, const std::string &name, const std::string &value);
/// A scalar dataset holding a fixed-length string.
void write_string(hid_t group, const std::string &name, const std::string &value);
/// The dataset `name` of `values` (double or int): (size) for one column, (size / columns x
/// columns) for more, with a Fletcher32 checksum.
template <typename T>
void write_array(hid_t group, const std::string &name, const std::vector<T> &values,
                 hsize_t columns);

/// The scalar attribute `name` as T (double or int).
template <typename T> T read_attribute(hid_t object, const std::string &name);
/// The fixed-length string of an attribute (`attribute`) or a scalar dataset `name`.
std::string read_string(hid_t object, const std::string &name, bool attribute);
/// The `size` values of the dataset `name` as T (double or int); an error if it holds
/// another number.
template <typename T>
std::vector<T> read_array(hid_t group, const std::string &name, std::size_t size);
/// Row `row` of the two-dimensional dataset `name`, or empty if it has not `rows` rows.
std::vector<double> read_row(hid_t group, const std::string &name, int rows, int row);

/// Writes `bytes` to `path` and makes them durable (fsync): an error naming the system's
/// reason (e.g. "No space left on device", "File too large") if any of it fails.
void write_file(const std::string &path, const std::vector<char> &bytes);
} // namespace internal
} // namespace kiln
