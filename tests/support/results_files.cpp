#include "support/results_files.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace kiln_test
{
std::string temporary_base(const std::string &name, const Teuchos::Comm<int> &comm)
{
  int pid = static_cast<int>(getpid());
  Teuchos::broadcast(comm, 0, Teuchos::outArg(pid));
  return (std::filesystem::temp_directory_path() /
          ("kiln_" + name + "_np" + std::to_string(comm.getSize()) + "_" + std::to_string(pid)))
      .string();
}

void remove_results(const std::string &base, const Teuchos::Comm<int> &comm)
{
  comm.barrier();
  if (comm.getRank() != 0)
    return;
  const std::filesystem::path path(base);
  const std::string prefix = path.filename().string() + ".";
  std::vector<std::filesystem::path> files;
  for (const auto &entry : std::filesystem::directory_iterator(path.parent_path()))
    if (entry.path().filename().string().rfind(prefix, 0) == 0)
      files.push_back(entry.path());
  for (const auto &file : files)
    std::filesystem::remove(file);
}

std::vector<double> read_step(const std::string &h5_path, const std::string &field, const int step,
                              double &time)
{
  std::vector<double> values;
  const hid_t file = H5Fopen(h5_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(file, 0) << h5_path;
  if (file < 0)
    return values;
  H5G_info_t steps{};
  EXPECT_GE(H5Gget_info_by_name(file, "/steps", &steps, H5P_DEFAULT), 0) << h5_path;
  const int index = step < 0 ? static_cast<int>(steps.nlinks) - 1 : step;
  EXPECT_LT(index, static_cast<int>(steps.nlinks)) << h5_path << ": no output step " << index;
  char group[32];
  std::snprintf(group, sizeof group, "/steps/%06d", index);
  time = std::nan("");
  if (H5Lexists(file, group, H5P_DEFAULT) > 0)
  {
    const hid_t attribute = H5Aopen_by_name(file, group, "time", H5P_DEFAULT, H5P_DEFAULT);
    EXPECT_GE(H5Aread(attribute, H5T_NATIVE_DOUBLE, &time), 0);
    H5Aclose(attribute);
    const std::string path = std::string(group) + "/" + field;
    const hid_t dataset = H5Lexists(file, path.c_str(), H5P_DEFAULT) > 0
                              ? H5Dopen2(file, path.c_str(), H5P_DEFAULT)
                              : H5I_INVALID_HID;
    EXPECT_GE(dataset, 0) << h5_path << ": no " << path;
    if (dataset >= 0)
    {
      const hid_t space = H5Dget_space(dataset);
      values.resize(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
      H5Sclose(space);
      EXPECT_GE(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
                0);
      // Tensors stored in ParaView's order (components "xx,yy,zz,xy,yz,xz") come back in
      // Kiln's Voigt order xx yy zz xy xz yz, the order of the tests' exact states.
      if (H5Aexists(dataset, "components") > 0)
      {
        const hid_t components_attribute = H5Aopen(dataset, "components", H5P_DEFAULT);
        const hid_t type = H5Aget_type(components_attribute);
        std::string components(H5Tget_size(type), '\0');
        H5Aread(components_attribute, type, components.data());
        components.resize(std::min(components.size(), components.find('\0')));
        H5Tclose(type);
        H5Aclose(components_attribute);
        if (components == "xx,yy,zz,xy,yz,xz")
          for (std::size_t row = 0; 6 * row + 5 < values.size(); ++row)
            std::swap(values[6 * row + 4], values[6 * row + 5]);
      }
      H5Dclose(dataset);
    }
  }
  H5Fclose(file);
  return values;
}

std::vector<double> read_last_step(const std::string &h5_path, const std::string &field,
                                   double &time)
{
  return read_step(h5_path, field, -1, time);
}
std::vector<double> read_dataset(const std::string &h5_path, const std::string &path)
{
  std::vector<double> values;
  const hid_t file = H5Fopen(h5_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(file, 0) << h5_path;
  if (file < 0)
    return values;
  const hid_t dataset = H5Lexists(file, path.c_str(), H5P_DEFAULT) > 0
                            ? H5Dopen2(file, path.c_str(), H5P_DEFAULT)
                            : H5I_INVALID_HID;
  EXPECT_GE(dataset, 0) << h5_path << ": no " << path;
  if (dataset >= 0)
  {
    const hid_t space = H5Dget_space(dataset);
    values.resize(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
    H5Sclose(space);
    EXPECT_GE(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0);
    H5Dclose(dataset);
  }
  H5Fclose(file);
  return values;
}

std::string read_text_attribute(const std::string &h5_path, const std::string &path,
                                const std::string &name)
{
  std::string text;
  const hid_t file = H5Fopen(h5_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(file, 0) << h5_path;
  if (file < 0)
    return text;
  if (H5Aexists_by_name(file, path.c_str(), name.c_str(), H5P_DEFAULT) > 0)
  {
    const hid_t attribute =
        H5Aopen_by_name(file, path.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
    const hid_t type = H5Aget_type(attribute);
    text.assign(H5Tget_size(type), '\0');
    H5Aread(attribute, type, text.data());
    text.resize(std::min(text.size(), text.find('\0')));
    H5Tclose(type);
    H5Aclose(attribute);
  }
  else
    ADD_FAILURE() << h5_path << ": " << path << " has no attribute " << name;
  H5Fclose(file);
  return text;
}

std::vector<double> csv_column(const std::string &path, const std::string &name)
{
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  std::string line, cell;
  std::getline(in, line);
  std::istringstream header(line);
  int column = -1;
  for (int c = 0; std::getline(header, cell, ','); ++c)
    if (cell.rfind(name + " [", 0) == 0)
      column = c;
  EXPECT_GE(column, 0) << path << ": no column " << name;
  std::vector<double> values;
  while (std::getline(in, line))
  {
    std::istringstream row(line);
    for (int c = 0; std::getline(row, cell, ','); ++c)
      if (c == column)
        values.push_back(cell == "nan" ? std::nan("") : std::stod(cell));
  }
  return values;
}
} // namespace kiln_test
