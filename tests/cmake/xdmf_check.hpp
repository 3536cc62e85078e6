#pragma once
/// Checks an XDMF file against the HDF5 file(s) it points to, as ParaView would need
/// them: the XML parses (Teuchos), every DataItem with Format="HDF" names a dataset
/// that exists with the stated Dimensions and a matching number type and precision,
/// topologies and attributes have as many rows as the grid has cells or nodes, and
/// the k-th grid of a Temporal collection has a Time whose value equals the "time"
/// attribute of /steps/NNNNNN (NNNNNN = k) and refers to no other step's data.
/// Header-only, for tests and the kiln_check_xdmf tool. Serial HDF5 calls only.

#include <Teuchos_FileInputSource.hpp>
#include <Teuchos_XMLObject.hpp>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace kiln
{
namespace internal
{
inline std::string xdmf_trim(const std::string &s)
{
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos)
    return "";
  const auto last = s.find_last_not_of(" \t\r\n");
  return s.substr(first, last - first + 1);
}

/// Whitespace-separated non-negative integers; false if there is anything else.
inline bool xdmf_parse_dimensions(const std::string &text, std::vector<hsize_t> &dims)
{
  dims.clear();
  std::istringstream in(text);
  std::string word;
  while (in >> word)
  {
    if (word.find_first_not_of("0123456789") != std::string::npos)
      return false;
    dims.push_back(static_cast<hsize_t>(std::stoull(word)));
  }
  return !dims.empty();
}

inline std::string xdmf_dims_string(const std::vector<hsize_t> &dims)
{
  std::ostringstream s;
  for (std::size_t i = 0; i < dims.size(); ++i)
    s << (i ? " " : "") << dims[i];
  return s.str();
}

/// Silences HDF5's error printout while checking whether things exist.
class XdmfQuietHdf5
{
public:
  XdmfQuietHdf5()
  {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~XdmfQuietHdf5() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  XdmfQuietHdf5(const XdmfQuietHdf5 &) = delete;
  XdmfQuietHdf5 &operator=(const XdmfQuietHdf5 &) = delete;

private:
  H5E_auto2_t func_ = nullptr;
  void *data_ = nullptr;
};

/// True if every link along the absolute `path` exists in `file`.
inline bool xdmf_h5_path_exists(const hid_t file, const std::string &path)
{
  if (path.empty() || path[0] != '/')
    return false;
  std::size_t pos = 1;
  while (pos <= path.size())
  {
    const auto next = path.find('/', pos);
    const std::string prefix = path.substr(0, next);
    if (H5Lexists(file, prefix.c_str(), H5P_DEFAULT) <= 0)
      return false;
    if (next == std::string::npos)
      break;
    pos = next + 1;
  }
  return true;
}

struct XdmfChecker
{
  std::string xmf_dir; ///< with a trailing '/', or empty
  std::string error;
  std::vector<std::pair<std::string, hid_t>> open_files;

  ~XdmfChecker()
  {
    for (auto &f : open_files)
      if (f.second >= 0)
        H5Fclose(f.second);
  }

  bool fail(const std::string &message)
  {
    if (error.empty())
      error = message;
    return false;
  }

  hid_t file(const std::string &name)
  {
    for (const auto &f : open_files)
      if (f.first == name)
        return f.second;
    const std::string path = name.size() && name[0] == '/' ? name : xmf_dir + name;
    const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    open_files.emplace_back(name, id);
    return id;
  }

  /// Checks one DataItem; on success `dims` are its dimensions and `h5_path` its path.
  bool check_data_item(const Teuchos::XMLObject &item, std::vector<hsize_t> &dims,
                       std::string &h5_path)
  {
    const std::string format = item.hasAttribute("Format") ? item.getAttribute("Format") : "XML";
    if (format != "HDF")
      return fail("DataItem with Format=\"" + format + "\": only HDF is checked");
    if (!item.hasAttribute("Dimensions") ||
        !xdmf_parse_dimensions(item.getAttribute("Dimensions"), dims))
      return fail("DataItem without valid Dimensions");
    std::string text;
    for (int i = 0; i < item.numContentLines(); ++i)
      text += item.getContentLine(i);
    text = xdmf_trim(text);
    const auto colon = text.find(':');
    if (colon == std::string::npos || colon == 0)
      return fail("DataItem \"" + text + "\" is not FILE.h5:/path");
    const std::string file_name = text.substr(0, colon);
    h5_path = text.substr(colon + 1);
    const hid_t f = file(file_name);
    if (f < 0)
      return fail("DataItem \"" + text + "\": cannot open HDF5 file \"" + file_name +
                  "\" (relative to the .xmf folder)");
    if (!xdmf_h5_path_exists(f, h5_path))
      return fail("DataItem \"" + text + "\": " + h5_path + " does not exist in " + file_name);
    const hid_t dataset = H5Dopen2(f, h5_path.c_str(), H5P_DEFAULT);
    if (dataset < 0)
      return fail("DataItem \"" + text + "\": " + h5_path + " is not a dataset");
    const hid_t space = H5Dget_space(dataset);
    const hid_t type = H5Dget_type(dataset);
    const int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> actual(rank > 0 ? static_cast<std::size_t>(rank) : 0);
    if (rank > 0)
      H5Sget_simple_extent_dims(space, actual.data(), nullptr);
    const H5T_class_t type_class = H5Tget_class(type);
    const std::size_t type_size = H5Tget_size(type);
    H5Tclose(type);
    H5Sclose(space);
    H5Dclose(dataset);
    if (actual != dims)
      return fail("DataItem \"" + text + "\" states Dimensions \"" + xdmf_dims_string(dims) +
                  "\" but the dataset is " + xdmf_dims_string(actual));
    const std::string number_type =
        item.hasAttribute("NumberType") ? item.getAttribute("NumberType") : "Float";
    const bool float_type = number_type == "Float";
    const bool int_type = number_type == "Int" || number_type == "UInt";
    if ((float_type && type_class != H5T_FLOAT) || (int_type && type_class != H5T_INTEGER) ||
        (!float_type && !int_type))
      return fail("DataItem \"" + text + "\": NumberType \"" + number_type +
                  "\" does not match the dataset's type");
    const std::string precision =
        item.hasAttribute("Precision") ? item.getAttribute("Precision") : "4";
    if (precision != std::to_string(type_size))
      return fail("DataItem \"" + text + "\": Precision " + precision + " but the dataset has " +
                  std::to_string(type_size) + "-byte values");
    return true;
  }

  /// The single DataItem child of `parent` (Topology, Geometry, Attribute).
  bool check_only_data_item(const Teuchos::XMLObject &parent, std::vector<hsize_t> &dims,
                            std::string &h5_path)
  {
    const int i = parent.findFirstChild("DataItem");
    if (i < 0)
      return fail(parent.getTag() + " without a DataItem");
    return check_data_item(parent.getChild(i), dims, h5_path);
  }

  /// A Uniform grid; `step` >= 0 when it is the step-th member of a Temporal collection.
  bool check_uniform_grid(const Teuchos::XMLObject &grid, const int step)
  {
    const std::string grid_name =
        "Grid \"" + (grid.hasAttribute("Name") ? grid.getAttribute("Name") : std::string()) + "\"";
    hsize_t n_cells = 0;
    hsize_t n_nodes = 0;
    bool has_topology = false;
    bool has_geometry = false;
    std::vector<std::string> paths;
    std::vector<hsize_t> dims;
    std::string path;
    for (int c = 0; c < grid.numChildren(); ++c)
    {
      const Teuchos::XMLObject &child = grid.getChild(c);
      if (child.getTag() == "Topology")
      {
        if (!check_only_data_item(child, dims, path))
          return false;
        n_cells = dims[0];
        has_topology = true;
        if (child.hasAttribute("NumberOfElements") &&
            child.getAttribute("NumberOfElements") != std::to_string(n_cells))
          return fail(grid_name + ": Topology NumberOfElements differs from its DataItem");
        if (child.hasAttribute("NodesPerElement") &&
            (dims.size() != 2 || child.getAttribute("NodesPerElement") != std::to_string(dims[1])))
          return fail(grid_name + ": Topology NodesPerElement differs from its DataItem");
      }
      else if (child.getTag() == "Geometry")
      {
        if (!check_only_data_item(child, dims, path))
          return false;
        const std::string type =
            child.hasAttribute("GeometryType") ? child.getAttribute("GeometryType") : "XYZ";
        if (type != "XYZ" || dims.size() != 2 || dims[1] != 3)
          return fail(grid_name + ": Geometry must be XYZ with n x 3 coordinates");
        n_nodes = dims[0];
        has_geometry = true;
      }
    }
    if (!has_topology || !has_geometry)
      return fail(grid_name + ": needs a Topology and a Geometry");
    for (int c = 0; c < grid.numChildren(); ++c)
    {
      const Teuchos::XMLObject &child = grid.getChild(c);
      if (child.getTag() != "Attribute")
        continue;
      const std::string name =
          grid_name + " Attribute \"" +
          (child.hasAttribute("Name") ? child.getAttribute("Name") : std::string()) + "\"";
      if (!check_only_data_item(child, dims, path))
        return false;
      paths.push_back(path);
      const std::string center = child.hasAttribute("Center") ? child.getAttribute("Center") : "";
      if (center != "Node" && center != "Cell")
        return fail(name + ": Center must be Node or Cell");
      if (dims[0] != (center == "Node" ? n_nodes : n_cells))
        return fail(name + ": " + std::to_string(dims[0]) + " rows, but the grid has " +
                    std::to_string(center == "Node" ? n_nodes : n_cells) + " " + center + "s");
      const std::string type =
          child.hasAttribute("AttributeType") ? child.getAttribute("AttributeType") : "Scalar";
      const hsize_t n_components = dims.size() > 1 ? dims[1] : 1;
      if ((type == "Scalar" && n_components != 1) || (type == "Vector" && n_components != 3) ||
          (type == "Tensor6" && n_components != 6) || (type == "Tensor" && n_components != 9))
        return fail(name + ": AttributeType " + type + " with " + std::to_string(n_components) +
                    " components");
    }
    if (step < 0)
      return true;

    const int t = grid.findFirstChild("Time");
    if (t < 0 || !grid.getChild(t).hasAttribute("Value"))
      return fail(grid_name + ": a member of a Temporal collection needs <Time Value=...>");
    double time = 0.0;
    try
    {
      time = std::stod(grid.getChild(t).getAttribute("Value"));
    }
    catch (const std::exception &)
    {
      return fail(grid_name + ": Time Value is not a number");
    }
    char group[32];
    std::snprintf(group, sizeof group, "/steps/%06d", step);
    for (const auto &p : paths)
      if (p.rfind("/steps/", 0) == 0 && p.rfind(std::string(group) + "/", 0) != 0)
        return fail(grid_name + " (member " + std::to_string(step) + ") refers to " + p);
    // The step's group is in the file the topology refers to.
    const int topology = grid.findFirstChild("Topology");
    const auto &item =
        grid.getChild(topology).getChild(grid.getChild(topology).findFirstChild("DataItem"));
    std::string text;
    for (int i = 0; i < item.numContentLines(); ++i)
      text += item.getContentLine(i);
    text = xdmf_trim(text);
    const hid_t f = file(text.substr(0, text.find(':')));
    if (!xdmf_h5_path_exists(f, group) || H5Aexists_by_name(f, group, "time", H5P_DEFAULT) <= 0)
      return fail(grid_name + ": " + group + " or its attribute time does not exist");
    const hid_t attribute = H5Aopen_by_name(f, group, "time", H5P_DEFAULT, H5P_DEFAULT);
    double stored = 0.0;
    const herr_t status = H5Aread(attribute, H5T_NATIVE_DOUBLE, &stored);
    H5Aclose(attribute);
    if (status < 0)
      return fail(grid_name + ": cannot read " + group + " attribute time");
    if (!(std::abs(stored - time) <= 1e-12 * std::max(1.0, std::abs(stored))))
    {
      std::ostringstream s;
      s.precision(17);
      s << grid_name << ": Time " << time << " but " << group << " has time " << stored;
      return fail(s.str());
    }
    return true;
  }

  bool check_grid(const Teuchos::XMLObject &grid)
  {
    const std::string type =
        grid.hasAttribute("GridType") ? grid.getAttribute("GridType") : "Uniform";
    if (type == "Uniform")
      return check_uniform_grid(grid, -1);
    if (type != "Collection")
      return fail("GridType \"" + type + "\" is not checked");
    const bool temporal =
        grid.hasAttribute("CollectionType") && grid.getAttribute("CollectionType") == "Temporal";
    int member = 0;
    for (int c = 0; c < grid.numChildren(); ++c)
    {
      const Teuchos::XMLObject &child = grid.getChild(c);
      if (child.getTag() != "Grid")
        continue;
      const std::string child_type =
          child.hasAttribute("GridType") ? child.getAttribute("GridType") : "Uniform";
      if (temporal && child_type != "Uniform")
        return fail("a Temporal collection may only hold Uniform grids here");
      if (!(temporal ? check_uniform_grid(child, member) : check_grid(child)))
        return false;
      ++member;
    }
    if (member == 0)
      return fail("a Collection grid without member grids");
    return true;
  }

  bool check_document(const Teuchos::XMLObject &root)
  {
    if (root.getTag() != "Xdmf")
      return fail("the root element is <" + root.getTag() + ">, not <Xdmf>");
    const int d = root.findFirstChild("Domain");
    if (d < 0)
      return fail("no <Domain>");
    const Teuchos::XMLObject &domain = root.getChild(d);
    int n_grids = 0;
    for (int c = 0; c < domain.numChildren(); ++c)
      if (domain.getChild(c).getTag() == "Grid")
      {
        ++n_grids;
        if (!check_grid(domain.getChild(c)))
          return false;
      }
    if (n_grids == 0)
      return fail("the Domain holds no Grid");
    return true;
  }
};
} // namespace internal

/// "" if `xmf_path` is a sound XDMF file for Kiln's HDF5 layout, else what is wrong.
inline std::string check_xdmf(const std::string &xmf_path)
{
  internal::XdmfChecker checker;
  const auto slash = xmf_path.find_last_of('/');
  checker.xmf_dir = slash == std::string::npos ? "" : xmf_path.substr(0, slash + 1);
  if (!std::ifstream(xmf_path))
    return xmf_path + ": cannot open the file";
  const internal::XdmfQuietHdf5 quiet;
  try
  {
    const Teuchos::XMLObject root = Teuchos::FileInputSource(xmf_path).getObject();
    if (root.isEmpty())
      return xmf_path + ": empty or unreadable XML";
    if (!checker.check_document(root))
      return xmf_path + ": " + checker.error;
  }
  catch (const std::exception &e)
  {
    return xmf_path + ": cannot parse: " + e.what();
  }
  return "";
}
} // namespace kiln
