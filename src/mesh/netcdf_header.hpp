#pragma once
/// The header of a netCDF classic file (the format of most Exodus II meshes: CDF-1,
/// CDF-2 "64-bit offset" and CDF-5), read without the netCDF library.
///
/// The netCDF library reads a classic file that is shorter than its header says as
/// if the missing bytes were zeros: a mesh cut short by a failed copy then reads
/// with node 0 in its connectivity or side 0 in its side sets, and the error blames
/// the mesh. Reading the header first tells a truncated file from a bad mesh, and a
/// damaged header is reported before the library parses it.
#include <cstdint>
#include <string>

namespace kiln
{
struct NetcdfHeader
{
  enum class Kind
  {
    not_classic, ///< not a netCDF classic file (netCDF-4/HDF5, or not netCDF at all)
    classic,     ///< a classic header, read whole
    damaged,     ///< starts like a classic file but its header is inconsistent
    need_more    ///< the bytes given end inside the header: give more of the file
  };
  Kind kind = Kind::not_classic;
  int version = 0;            ///< 1, 2 or 5 for a classic file
  std::uint64_t data_end = 0; ///< the byte just past the last variable's data
  std::string problem;        ///< what is wrong, for Kind::damaged
};

/// Reads the header from the first `size` bytes of a file of `file_size` bytes (the
/// whole file need not be given: Kind::need_more asks for more).
NetcdfHeader read_netcdf_header(const unsigned char *bytes, std::uint64_t size,
                                std::uint64_t file_size);

/// Throws InputError naming `path` when it is a netCDF classic file whose header is
/// damaged or announces more bytes than the file holds (a truncated copy). Files of
/// other kinds pass (the netCDF library checks them).
void check_netcdf_file(const std::string &path);
} // namespace kiln
