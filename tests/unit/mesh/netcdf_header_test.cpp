// Tests src/mesh/netcdf_header.cpp: the classic header of the reference meshes and of a file
// Kiln writes gives their exact size; truncated copies and damaged headers are InputErrors.
// KILN_TEST_NP: 1
#include "mesh/netcdf_header.hpp"

#include "base/errors.hpp"
#include "mesh/exodus_io.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
using Kind = kiln::NetcdfHeader::Kind;
using testing::HasSubstr;

const std::string mesh_dir = std::string(KILN_SHARED_DIR) + "/meshes/";

std::vector<unsigned char> bytes_of(const std::string &path)
{
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

kiln::NetcdfHeader header_of(const std::vector<unsigned char> &bytes)
{
  return kiln::read_netcdf_header(bytes.data(), bytes.size(), bytes.size());
}

/// A file in the working directory, unique per process; removed at scope end.
struct TempFile
{
  std::string path;
  explicit TempFile(const std::string &tag)
      : path("kiln-netcdf-test-" + tag + "-" + std::to_string(::getpid()) + ".exo")
  {
  }
  ~TempFile() { std::remove(path.c_str()); }
  void write(const std::vector<unsigned char> &bytes, const std::size_t n) const
  {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char *>(bytes.data()), static_cast<std::streamsize>(n));
  }
};

std::string check_error(const std::string &path)
{
  try
  {
    kiln::check_netcdf_file(path);
  }
  catch (const kiln::InputError &e)
  {
    return e.what();
  }
  return "";
}

TEST(NetcdfHeader, ReferenceMeshesEndWhereTheirHeaderSays)
{
  for (const char *name : {"rotated-cube.exo", "aligned-cube.exo"})
  {
    const auto bytes = bytes_of(mesh_dir + name);
    const kiln::NetcdfHeader h = header_of(bytes);
    ASSERT_EQ(h.kind, Kind::classic) << name << ": " << h.problem;
    EXPECT_EQ(h.data_end, bytes.size()) << name;
    EXPECT_EQ(check_error(mesh_dir + name), "");
  }
}

TEST(NetcdfHeader, FileWrittenByKilnPasses)
{
  const TempFile file("written");
  kiln::write_exodus_mesh(kiln::read_exodus_mesh(mesh_dir + "rotated-cube.exo", 0.01), file.path);
  const auto bytes = bytes_of(file.path);
  const kiln::NetcdfHeader h = header_of(bytes);
  if (h.kind == Kind::classic)
    EXPECT_LE(h.data_end, bytes.size());
  else
    EXPECT_EQ(h.kind, Kind::not_classic); // netCDF-4: the HDF5 library checks its own files
  EXPECT_EQ(check_error(file.path), "");
}

TEST(NetcdfHeader, EveryTruncationIsFound)
{
  // The netCDF library reads the missing bytes as zeros: a cut copy read as a mesh with node
  // 0 in its cells or side 0 in its side sets. Every shorter length must be caught here.
  const auto bytes = bytes_of(mesh_dir + "rotated-cube.exo");
  const TempFile file("cut");
  for (std::size_t n = 4; n < bytes.size(); n += (n < 64 ? 1 : 97))
  {
    const kiln::NetcdfHeader h = kiln::read_netcdf_header(bytes.data(), n, n);
    EXPECT_TRUE(h.kind == Kind::need_more || (h.kind == Kind::classic && h.data_end > n))
        << "cut at " << n;
  }
  file.write(bytes, 13000);
  EXPECT_THAT(check_error(file.path),
              HasSubstr(file.path + ": the file is truncated: it holds 13000 bytes but its "
                                    "header places data up to byte 14304"));
  file.write(bytes, 100);
  EXPECT_THAT(check_error(file.path),
              HasSubstr("the file is truncated: it ends (at byte 100) inside its netCDF header"));
}

TEST(NetcdfHeader, DamagedHeadersAreFound)
{
  const auto good = bytes_of(mesh_dir + "rotated-cube.exo");
  // The dimension list's tag (bytes 8-11 of a CDF-1 or CDF-2 file) is 0x0A.
  auto bad_tag = good;
  bad_tag[11] = 0x0B;
  EXPECT_EQ(header_of(bad_tag).kind, Kind::damaged);
  EXPECT_THAT(header_of(bad_tag).problem, HasSubstr("the dimension list has the tag 11"));
  // A dimension count larger than the file can hold runs out of bytes: a truncated or damaged
  // header, reported as such by check_netcdf_file.
  auto huge_count = good;
  huge_count[12] = 0x7F;
  EXPECT_EQ(header_of(huge_count).kind, Kind::need_more);
  const TempFile file("damaged");
  file.write(bad_tag, bad_tag.size());
  EXPECT_THAT(check_error(file.path), HasSubstr("its netCDF header is damaged (the dimension list "
                                                "has the tag 11)"));
}

TEST(NetcdfHeader, OtherFilesAreLeftToTheLibrary)
{
  const std::vector<unsigned char> hdf5 = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1A, '\n'};
  EXPECT_EQ(header_of(hdf5).kind, Kind::not_classic);
  const std::vector<unsigned char> text = {'h', 'e', 'l', 'l', 'o'};
  EXPECT_EQ(header_of(text).kind, Kind::not_classic);
  const std::vector<unsigned char> tiny = {'C', 'D'};
  EXPECT_EQ(header_of(tiny).kind, Kind::need_more);
}
} // namespace
