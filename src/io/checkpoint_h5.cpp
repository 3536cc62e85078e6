#include "io/checkpoint_h5.hpp"

#include "io/hdf5_errors.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace kiln
{
namespace internal
{
H5::H5(const hid_t id, const H5Handle::Closer closer, const std::string &what) : handle_(id, closer)
{
  if (id < 0)
    throw std::runtime_error(what + in_parentheses(hdf5_failure_reason()));
}

void H5::close(const std::string &what)
{
  if (handle_.close() < 0)
    throw std::runtime_error(what + in_parentheses(hdf5_failure_reason()));
}

void check(const herr_t status, const std::string &what)
{
  if (status < 0)
    throw std::runtime_error(what + in_parentheses(hdf5_failure_reason()));
}

void write_attribute(const hid_t object, const std::string &name, const double value)
{
  const H5 space(H5Screate(H5S_SCALAR), H5Sclose, "dataspace");
  const H5 a(H5Acreate2(object, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT),
             H5Aclose, "attribute " + name);
  check(H5Awrite(a, H5T_NATIVE_DOUBLE, &value), "attribute " + name);
}

void write_attribute(const hid_t object, const std::string &name, const int value)
{
  const H5 space(H5Screate(H5S_SCALAR), H5Sclose, "dataspace");
  const H5 a(H5Acreate2(object, name.c_str(), H5T_STD_I32LE, space, H5P_DEFAULT, H5P_DEFAULT),
             H5Aclose, "attribute " + name);
  check(H5Awrite(a, H5T_NATIVE_INT, &value), "attribute " + name);
}

namespace
{
/// A fixed-length string type of `size` characters (at least 1).
hid_t string_type(const std::size_t size)
{
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, std::max<std::size_t>(size, 1));
  return type;
}
} // namespace

void write_attribute(const hid_t object, const std::string &name, const std::string &value)
{
  const H5 type(string_type(value.size()), H5Tclose, "string type");
  const H5 space(H5Screate(H5S_SCALAR), H5Sclose, "dataspace");
  const H5 a(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
             "attribute " + name);
  check(H5Awrite(a, type, value.empty() ? "" : value.data()), "attribute " + name);
}

void write_string(const hid_t group, const std::string &name, const std::string &value)
{
  const H5 type(string_type(value.size()), H5Tclose, "string type");
  const H5 space(H5Screate(H5S_SCALAR), H5Sclose, "dataspace");
  const H5 d(H5Dcreate2(group, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
             H5Dclose, "dataset " + name);
  check(H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, value.empty() ? "" : value.data()),
        "dataset " + name);
}

template <typename T>
void write_array(const hid_t group, const std::string &name, const std::vector<T> &values,
                 const hsize_t columns)
{
  const hsize_t dims[2] = {values.size() / columns, columns};
  const H5 space(H5Screate_simple(columns > 1 ? 2 : 1, dims, nullptr), H5Sclose, "dataspace");
  const hid_t file_type = std::is_same_v<T, double> ? H5T_IEEE_F64LE : H5T_STD_I32LE;
  const hid_t memory_type = std::is_same_v<T, double> ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT;
  // A Fletcher32 checksum of the data (read_checkpoint refuses a flipped bit); the filter needs
  // a chunked layout: one chunk of at most 2^20 rows.
  const H5 dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "dataset properties");
  if (!values.empty())
  {
    const hsize_t chunk[2] = {std::min<hsize_t>(dims[0], hsize_t{1} << 20), columns};
    check(H5Pset_chunk(dcpl, columns > 1 ? 2 : 1, chunk), "chunking dataset " + name);
    check(H5Pset_fletcher32(dcpl), "checksum of dataset " + name);
  }
  const H5 d(H5Dcreate2(group, name.c_str(), file_type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT),
             H5Dclose, "dataset " + name);
  check(H5Dwrite(d, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "dataset " + name);
}

template <typename T> T read_attribute(const hid_t object, const std::string &name)
{
  const H5 a(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose, "attribute " + name);
  T value{};
  check(H5Aread(a, std::is_same_v<T, double> ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT, &value),
        "attribute " + name);
  return value;
}

std::string read_string(const hid_t object, const std::string &name, const bool attribute)
{
  const std::string what = (attribute ? "attribute " : "dataset ") + name;
  const H5 item(attribute ? H5Aopen(object, name.c_str(), H5P_DEFAULT)
                          : H5Dopen2(object, name.c_str(), H5P_DEFAULT),
                attribute ? H5Aclose : H5Dclose, what);
  const H5 type(attribute ? H5Aget_type(item) : H5Dget_type(item), H5Tclose, what);
  if (H5Tget_class(type) != H5T_STRING)
    throw std::runtime_error(what + " is not a string");
  std::string value(H5Tget_size(type), '\0');
  check(attribute ? H5Aread(item, type, value.data())
                  : H5Dread(item, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, value.data()),
        what);
  value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
  return value;
}

template <typename T>
std::vector<T> read_array(const hid_t group, const std::string &name, const std::size_t size)
{
  const H5 d(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + name);
  const H5 space(H5Dget_space(d), H5Sclose, "dataset " + name);
  if (static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)) != size)
    throw std::runtime_error("dataset " + name + " has " +
                             std::to_string(H5Sget_simple_extent_npoints(space)) +
                             " values where " + std::to_string(size) + " are expected");
  std::vector<T> values(size);
  check(H5Dread(d, std::is_same_v<T, double> ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT, H5S_ALL, H5S_ALL,
                H5P_DEFAULT, values.data()),
        "dataset " + name);
  return values;
}

/// Row `row` of the two-dimensional dataset `name`, or empty if it has not `rows` rows.
std::vector<double> read_row(const hid_t group, const std::string &name, const int rows,
                             const int row)
{
  const H5 d(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "dataset " + name);
  const H5 space(H5Dget_space(d), H5Sclose, "dataset " + name);
  hsize_t dims[2] = {0, 0};
  if (H5Sget_simple_extent_ndims(space) != 2 ||
      H5Sget_simple_extent_dims(space, dims, nullptr) != 2 || dims[0] != static_cast<hsize_t>(rows))
    return {};
  std::vector<double> all(dims[0] * dims[1]);
  check(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, all.data()),
        "dataset " + name);
  return std::vector<double>(all.begin() + static_cast<std::ptrdiff_t>(row * dims[1]),
                             all.begin() + static_cast<std::ptrdiff_t>((row + 1) * dims[1]));
}

/// Writes `bytes` to `path` and makes them durable (fsync): an error naming the system's
/// reason (e.g. "No space left on device", "File too large") if any of it fails.
void write_file(const std::string &path, const std::vector<char> &bytes)
{
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0)
    throw std::runtime_error(std::string("cannot create the file (") + std::strerror(errno) + ")");
  std::size_t written = 0;
  int error_number = 0;
  while (written < bytes.size() && error_number == 0)
  {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno != EINTR)
      error_number = errno;
    else if (n > 0)
      written += static_cast<std::size_t>(n);
  }
  if (error_number == 0 && ::fsync(fd) != 0)
    error_number = errno;
  if (::close(fd) != 0 && error_number == 0)
    error_number = errno;
  if (error_number != 0)
    throw std::runtime_error(std::string("writing the file failed (") +
                             std::strerror(error_number) + ")");
}

template void write_array(hid_t, const std::string &, const std::vector<double> &, hsize_t);
template void write_array(hid_t, const std::string &, const std::vector<int> &, hsize_t);
template double read_attribute(hid_t, const std::string &);
template int read_attribute(hid_t, const std::string &);
template std::vector<double> read_array(hid_t, const std::string &, std::size_t);
template std::vector<int> read_array(hid_t, const std::string &, std::size_t);
} // namespace internal
} // namespace kiln
