#include "io/parallel_hdf5_file.hpp"

#include "base/errors.hpp"
#include "io/collective_checks.hpp"
#include "io/hdf5_errors.hpp"
#include "io/write_room.hpp"

#include <Teuchos_DefaultMpiComm.hpp>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace kiln
{
namespace internal
{
namespace
{
std::string directory_of(const std::string &path)
{
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash + 1);
}
} // namespace

OwnedRows::OwnedRows(const std::vector<int> &owned, const int n_rows_of_all)
    : n_rows(static_cast<hsize_t>(n_rows_of_all)), n_owned(owned.size())
{
  for (const int row : owned)
  {
    const auto r = static_cast<hsize_t>(row);
    if (!runs.empty() && runs.back().first + runs.back().count == r)
      ++runs.back().count;
    else
      runs.push_back({r, 1});
  }
}

ParallelHdf5File::ParallelHdf5File(const MPI_Comm comm, const std::string &path)
    : comm_(comm), path_(path)
{
  quiet_hdf5_errors();
  fapl_ = H5Handle(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_fapl_mpio(fapl_.get(), comm, MPI_INFO_NULL);
  // Metadata (groups, attributes, dataset headers) is written collectively too.
  H5Pset_all_coll_metadata_ops(fapl_.get(), true);
  H5Pset_coll_metadata_write(fapl_.get(), true);
  dxpl_ = H5Handle(H5Pcreate(H5P_DATASET_XFER), H5Pclose);
  H5Pset_dxpl_mpio(dxpl_.get(), H5FD_MPIO_COLLECTIVE);

  {
    const QuietHdf5Errors quiet;
    file_ = H5Handle(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl_.get()), H5Fclose);
  }
  check_input_collectively(comm_, file_.valid(), path_,
                           "cannot create the results file; check that the folder \"" +
                               directory_of(path_) +
                               "\" exists and is writable, or choose another output path");
}

void ParallelHdf5File::check_io(const bool local_ok, const std::string &what) const
{
  // Read before any other HDF5 call clears the error stack.
  const std::string reason = local_ok ? "" : hdf5_failure_reason();
  const Teuchos::MpiComm<int> comm(comm_);
  check_write_collectively(
      comm, local_ok, path_,
      what + " failed" + in_parentheses(reason) +
          "; the run cannot go on. Check that the disk is not full, that no file-size limit "
          "(ulimit -f) stops the file and that it is not removed or opened by another program "
          "while Kiln runs; the steps written before are kept (continue from the last "
          "checkpoint with kiln INPUT.xml --restart)");
}

H5Handle ParallelHdf5File::create_group(const std::string &name) const
{
  H5Handle group(H5Gcreate2(file_.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                 H5Gclose);
  check_io(group.valid(), "creating group /" + name);
  return group;
}

std::uintmax_t ParallelHdf5File::size() const
{
  std::error_code e;
  std::uint64_t bytes = std::filesystem::file_size(path_, e);
  if (e)
    bytes = 0;
  MPI_Bcast(&bytes, 1, MPI_UINT64_T, 0, comm_);
  return bytes;
}

namespace
{
/// Allocates `bytes` after the end of the file at `path` without changing its size; "" on
/// success or where the file system cannot (EOPNOTSUPP), else the system's reason.
std::string allocate_after_end(const std::string &path, const std::uintmax_t bytes)
{
  const int fd = ::open(path.c_str(), O_WRONLY);
  if (fd < 0)
    return "";
  struct stat info = {};
  int status = ::fstat(fd, &info);
  int error = 0;
  if (status == 0)
  {
    status = ::fallocate(fd, FALLOC_FL_KEEP_SIZE, info.st_size, static_cast<off_t>(bytes));
    error = status == 0 ? 0 : errno;
  }
  ::close(fd);
  if (status == 0 || error == EOPNOTSUPP || error == ENOSYS)
    return "";
  std::ostringstream text;
  text << std::strerror(error) << ": cannot set aside the " << bytes
       << " bytes the next step needs";
  return text.str();
}
} // namespace

void ParallelHdf5File::reserve(const std::uintmax_t bytes) const
{
  // Every rank: the ranks' file-size limits (and, on several nodes, their views of the disk)
  // may differ, and a write that fails on one rank only inside a collective HDF5 call leaves
  // HDF5's ranks in different collectives: the run hangs.
  const std::string shortfall = room_shortfall(path_, bytes);
  const Teuchos::MpiComm<int> comm(comm_);
  check_write_collectively(comm, shortfall.empty(), path_,
                           "the next step cannot be written (" + shortfall + "); " +
                               write_failure_advice());
  // The room found is then taken: rank 0 allocates the blocks after the file's end (the size
  // stays), so that another program filling the disk before the step's collective writes
  // cannot make them fail on some ranks only (which hangs HDF5). A file system without
  // fallocate keeps the check alone.
  std::string taken;
  if (comm.getRank() == 0)
    taken = allocate_after_end(path_, bytes);
  check_write_collectively(comm, taken.empty(), path_,
                           "the next step cannot be written (" + taken + "); " +
                               write_failure_advice());
}

void ParallelHdf5File::flush() const
{
  check_io(H5Fflush(file_.get(), H5F_SCOPE_GLOBAL) >= 0, "flushing the file");
}

H5Handle ParallelHdf5File::open_dataset(const hid_t location, const std::string &name) const
{
  H5Handle dataset(H5Dopen2(location, name.c_str(), H5P_DEFAULT), H5Dclose);
  check_io(dataset.valid(), "opening dataset \"" + name + "\"");
  return dataset;
}

void ParallelHdf5File::close()
{
  const bool ok = !file_.valid() || H5Fclose(file_.release()) >= 0;
  const std::string reason = ok ? "" : hdf5_failure_reason();
  // The property lists go whatever the outcome: nothing of the file stays open for
  // MPI_Finalize to trip on.
  dxpl_.reset();
  fapl_.reset();
  const Teuchos::MpiComm<int> comm(comm_);
  check_write_collectively(comm, ok, path_,
                           "closing the file failed" + in_parentheses(reason) +
                               "; check that the disk is not full and that no file-size limit "
                               "(ulimit -f) stops the file");
}

void ParallelHdf5File::write_rows(const hid_t location, const std::string &name,
                                  const OwnedRows &rows, const int n_components,
                                  const std::vector<double> &values) const
{
  write_rows(location, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.data(), rows, n_components);
}

void ParallelHdf5File::write_rows(const hid_t location, const std::string &name,
                                  const OwnedRows &rows, const int n_components,
                                  const std::vector<std::int64_t> &values) const
{
  write_rows(location, name, H5T_STD_I64LE, H5T_NATIVE_INT64, values.data(), rows, n_components);
}

void ParallelHdf5File::write_rows(const hid_t location, const std::string &name,
                                  const OwnedRows &rows, const int n_components,
                                  const std::vector<std::int32_t> &values) const
{
  write_rows(location, name, H5T_STD_I32LE, H5T_NATIVE_INT32, values.data(), rows, n_components);
}

/// Creates the dataset and writes this rank's rows into it, collectively: the file space
/// selects the union of this rank's runs of rows (or nothing), the memory space the owned
/// values in a row (or nothing, in a 1-value space).
void ParallelHdf5File::write_rows(const hid_t location, const std::string &name,
                                  const hid_t file_type, const hid_t memory_type, const void *data,
                                  const OwnedRows &rows, const int n_components) const
{
  const hsize_t n_cols = static_cast<hsize_t>(n_components);
  const int rank_of_data = n_components == 1 ? 1 : 2;
  const hsize_t dims[2] = {rows.n_rows, n_cols};

  const H5Handle file_space(H5Screate_simple(rank_of_data, dims, nullptr), H5Sclose);
  const H5Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_fill_time(dcpl.get(), H5D_FILL_TIME_NEVER); // every row is written below
  const H5Handle dataset(H5Dcreate2(location, name.c_str(), file_type, file_space.get(),
                                    H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                         H5Dclose);
  check_io(dataset.valid(), "creating dataset \"" + name + "\"");

  if (rows.runs.empty())
    H5Sselect_none(file_space.get());
  for (std::size_t r = 0; r < rows.runs.size(); ++r)
  {
    const hsize_t start[2] = {rows.runs[r].first, 0};
    const hsize_t count[2] = {rows.runs[r].count, n_cols};
    H5Sselect_hyperslab(file_space.get(), r == 0 ? H5S_SELECT_SET : H5S_SELECT_OR, start, nullptr,
                        count, nullptr);
  }
  const hsize_t n_values = rows.n_owned * n_cols;
  const hsize_t memory_dims[1] = {n_values > 0 ? n_values : 1};
  const H5Handle memory_space(H5Screate_simple(1, memory_dims, nullptr), H5Sclose);
  if (n_values == 0)
    H5Sselect_none(memory_space.get());
  const double dummy = 0.0;
  const herr_t status = H5Dwrite(dataset.get(), memory_type, memory_space.get(), file_space.get(),
                                 dxpl_.get(), n_values > 0 ? data : &dummy);
  check_io(status >= 0, "writing dataset \"" + name + "\"");
}

bool ParallelHdf5File::append_rows(const hid_t location, const std::string &name,
                                   const std::vector<double> &values) const
{
  const bool exists = H5Lexists(location, name.c_str(), H5P_DEFAULT) > 0;
  H5Handle dataset;
  if (exists)
    dataset = H5Handle(H5Dopen2(location, name.c_str(), H5P_DEFAULT), H5Dclose);
  else
  {
    const hsize_t none[1] = {0}, unlimited[1] = {H5S_UNLIMITED}, chunk[1] = {256};
    const H5Handle space(H5Screate_simple(1, none, unlimited), H5Sclose);
    const H5Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    H5Pset_chunk(dcpl.get(), 1, chunk);
    H5Pset_fill_time(dcpl.get(), H5D_FILL_TIME_NEVER); // every row is written
    dataset = H5Handle(H5Dcreate2(location, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT,
                                  dcpl.get(), H5P_DEFAULT),
                       H5Dclose);
  }
  check_io(dataset.valid(), (exists ? "opening dataset \"" : "creating dataset \"") + name + "\"");
  if (values.empty())
    return !exists;
  hsize_t old_size[1] = {0};
  {
    const H5Handle space(H5Dget_space(dataset.get()), H5Sclose);
    H5Sget_simple_extent_dims(space.get(), old_size, nullptr);
  }
  const hsize_t new_size[1] = {old_size[0] + values.size()};
  check_io(H5Dset_extent(dataset.get(), new_size) >= 0, "extending dataset \"" + name + "\"");
  const H5Handle file_space(H5Dget_space(dataset.get()), H5Sclose);
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  const hsize_t count[1] = {rank == 0 ? static_cast<hsize_t>(values.size()) : 1};
  const H5Handle memory_space(H5Screate_simple(1, count, nullptr), H5Sclose);
  if (rank == 0)
  {
    const hsize_t count_rows[1] = {values.size()};
    H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, old_size, nullptr, count_rows, nullptr);
  }
  else
  {
    H5Sselect_none(file_space.get());
    H5Sselect_none(memory_space.get());
  }
  const herr_t status = H5Dwrite(dataset.get(), H5T_NATIVE_DOUBLE, memory_space.get(),
                                 file_space.get(), dxpl_.get(), values.data());
  check_io(status >= 0, "appending to dataset \"" + name + "\"");
  return !exists;
}

void ParallelHdf5File::write_attributes(const hid_t location,
                                        const std::vector<ScalarAttribute> &attributes,
                                        const std::string &what) const
{
  const H5Handle scalar(H5Screate(H5S_SCALAR), H5Sclose);
  bool ok = true;
  for (const ScalarAttribute &a : attributes)
  {
    if (const auto *text = std::get_if<std::string>(&a.value))
    {
      const H5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
      H5Tset_size(type.get(), std::max<std::size_t>(text->size(), 1));
      const H5Handle attribute(
          H5Acreate2(location, a.name, type.get(), scalar.get(), H5P_DEFAULT, H5P_DEFAULT),
          H5Aclose);
      ok = ok && attribute.valid() &&
           H5Awrite(attribute.get(), type.get(), text->empty() ? "" : text->data()) >= 0;
      continue;
    }
    const bool is_double = std::holds_alternative<double>(a.value);
    const hid_t file_type = is_double ? H5T_IEEE_F64LE : H5T_STD_I32LE;
    const hid_t memory_type = is_double ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT32;
    const void *value = is_double ? static_cast<const void *>(&std::get<double>(a.value))
                                  : static_cast<const void *>(&std::get<std::int32_t>(a.value));
    const H5Handle attribute(
        H5Acreate2(location, a.name, file_type, scalar.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    ok = ok && attribute.valid() && H5Awrite(attribute.get(), memory_type, value) >= 0;
  }
  check_io(ok, what);
}
} // namespace internal
} // namespace kiln
