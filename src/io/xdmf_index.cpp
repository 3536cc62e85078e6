#include "io/xdmf_index.hpp"

#include "io/collective_checks.hpp"
#include "io/field_catalog.hpp"

#include "base/errors.hpp"

#include <Teuchos_DefaultMpiComm.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <utility>

namespace kiln
{
namespace internal
{
namespace
{
/// The file name of `path`, escaped for XML text (a deck named steel&al.xml gives
/// steel&amp;al.h5, which ParaView's parser reads back as steel&al.h5). OutputSchedule
/// refuses a name that is not UTF-8, the encoding of the index.
std::string file_name_of(const std::string &path)
{
  const auto slash = path.find_last_of('/');
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  std::string escaped;
  for (const char c : name)
    switch (c)
    {
    case '&':
      escaped += "&amp;";
      break;
    case '<':
      escaped += "&lt;";
      break;
    case '>':
      escaped += "&gt;";
      break;
    case '"':
      escaped += "&quot;";
      break;
    case '\'':
      escaped += "&apos;";
      break;
    default:
      escaped += c;
    }
  return escaped;
}
} // namespace

/// Scalar, Vector (x y z) or Matrix. A symmetric tensor is a Matrix, not an XDMF Tensor6
/// (whose order xx xy xz yy yz zz readers would permute): ParaView labels its 6 columns
/// XX YY ZZ XY YZ XZ, the order Kiln writes (tensor_components()).
const char *attribute_type(const FieldSpec &f)
{
  const FieldDescription *known = describe_field(f.name);
  const std::vector<std::string> xyz = {"x", "y", "z"};
  if (f.n_components == 1)
    return "Scalar";
  if (f.n_components == 3 && (known == nullptr || known->components == xyz))
    return "Vector";
  return "Matrix";
}

std::string step_group_name(const int step)
{
  std::ostringstream s;
  s << std::setw(6) << std::setfill('0') << step;
  return s.str();
}

namespace
{
/// XDMF's TopologyType name of a volume or face type.
std::string xdmf_name(const CellType type)
{
  switch (type)
  {
  case CellType::tri3:
    return "Triangle";
  case CellType::quad4:
    return "Quadrilateral";
  case CellType::tri6:
    return "Triangle_6";
  case CellType::quad8:
    return "Quadrilateral_8";
  case CellType::quad9:
    return "Quadrilateral_9";
  case CellType::hex8:
    return "Hexahedron";
  case CellType::tet4:
    return "Tetrahedron";
  case CellType::wedge6:
    return "Wedge";
  case CellType::pyramid5:
    return "Pyramid";
  case CellType::tet10:
    return "Tetrahedron_10";
  case CellType::hex20:
    return "Hexahedron_20";
  case CellType::hex27:
    return "Hexahedron_27";
  default:
    throw InternalError("no XDMF topology for " + ReferenceCell::of(type).name());
  }
}
} // namespace

XdmfTopology xdmf_topology(const Mesh &mesh, bool &needs_own_dataset)
{
  const std::vector<CellType> types = mesh.types();
  needs_own_dataset = types.size() > 1;
  for (const CellType type : types)
    needs_own_dataset = needs_own_dataset || !ReferenceCell::of(type).xdmf_order().empty();
  XdmfTopology topology;
  topology.dataset = needs_own_dataset ? "/mesh/topology" : "/mesh/connectivity";
  if (types.size() == 1)
  {
    topology.type = xdmf_name(types.front());
    topology.nodes_per_element = ReferenceCell::of(types.front()).n_nodes();
  }
  else
  {
    topology.type = "Mixed";
    topology.n_entries = static_cast<long long>(mesh.n_cells() + mesh.cell_node_ids.size());
  }
  return topology;
}

XdmfIndex::XdmfIndex(const MPI_Comm comm, const std::string &xmf_path, const std::string &h5_path,
                     const int n_nodes, const int n_cells, XdmfTopology topology)
    : comm_(comm), xmf_path_(xmf_path), h5_name_(file_name_of(h5_path)), n_nodes_(n_nodes),
      n_cells_(n_cells), topology_(std::move(topology))
{
}

void XdmfIndex::rename(const std::string &xmf_path, const std::string &h5_path)
{
  xmf_path_ = xmf_path;
  h5_name_ = file_name_of(h5_path);
}

void XdmfIndex::add_gap(const std::string &name, const int n_points, const int n_faces,
                        const std::optional<CellType> face_type, const long long n_entries)
{
  if (n_points > 0)
    gaps_.push_back({name, n_points, n_faces, face_type, n_entries});
}

void XdmfIndex::add_step(const double time)
{
  steps_.push_back({time, {}});
}

void XdmfIndex::add_field(const FieldSpec &field)
{
  steps_.back().fields.push_back(field);
}

bool XdmfIndex::has_field(const std::string &name) const
{
  for (const auto &f : steps_.back().fields)
    if (f.name == name)
      return true;
  return false;
}

void XdmfIndex::write_data_item(std::ostream &out, const std::string &indent,
                                const std::string &path, const std::string &dimensions,
                                const char *number_type, const int precision) const
{
  out << indent << "<DataItem Dimensions=\"" << dimensions << "\" NumberType=\"" << number_type
      << "\" Precision=\"" << precision << "\" Format=\"HDF\">" << h5_name_ << ":" << path
      << "</DataItem>\n";
}

/// One Uniform grid: the mesh, the mesh attributes and, for a step, its fields.
void XdmfIndex::write_grid(std::ostream &out, const std::string &indent, const Step *step,
                           const int index) const
{
  const std::string in1 = indent + "  ";
  const std::string in2 = in1 + "  ";
  const std::string nodes = std::to_string(n_nodes_);
  const std::string cells = std::to_string(n_cells_);
  out << indent << "<Grid Name=\"" << (step ? "step_" + step_group_name(index) : "mesh")
      << "\" GridType=\"Uniform\">\n";
  if (step)
    out << in1 << "<Time Value=\"" << std::setprecision(17) << step->time << "\"/>\n";
  if (topology_.type == "Mixed")
  {
    out << in1 << "<Topology TopologyType=\"Mixed\" NumberOfElements=\"" << cells << "\">\n";
    write_data_item(out, in2, topology_.dataset, std::to_string(topology_.n_entries), "Int", 8);
  }
  else
  {
    const std::string per_element = std::to_string(topology_.nodes_per_element);
    out << in1 << "<Topology TopologyType=\"" << topology_.type << "\" NumberOfElements=\"" << cells
        << "\" NodesPerElement=\"" << per_element << "\">\n";
    write_data_item(out, in2, topology_.dataset, cells + " " + per_element, "Int", 8);
  }
  out << in1 << "</Topology>\n";
  out << in1 << "<Geometry GeometryType=\"XYZ\">\n";
  write_data_item(out, in2, "/mesh/coordinates", nodes + " 3", "Float", 8);
  out << in1 << "</Geometry>\n";
  for (const char *name : {"block_id", "cell_rank"})
  {
    out << in1 << "<Attribute Name=\"" << name << "\" AttributeType=\"Scalar\" Center=\"Cell\">\n";
    write_data_item(out, in2, std::string("/mesh/") + name, cells, "Int", 4);
    out << in1 << "</Attribute>\n";
  }
  if (step)
    for (const auto &f : step->fields)
      write_attribute(out, in1, f, f.center == Center::node ? nodes : cells,
                      "/steps/" + step_group_name(index) + "/" + f.name);
  out << indent << "</Grid>\n";
}

void XdmfIndex::write_attribute(std::ostream &out, const std::string &indent, const FieldSpec &f,
                                const std::string &rows, const std::string &path) const
{
  std::string dimensions = rows;
  if (f.n_components > 1)
    dimensions += " " + std::to_string(f.n_components);
  out << indent << "<Attribute Name=\"" << f.name << "\" AttributeType=\"" << attribute_type(f)
      << "\" Center=\"" << (f.center == Center::node ? "Node" : "Cell") << "\">\n";
  write_data_item(out, indent + "  ", path, dimensions, "Float", 8);
  out << indent << "</Attribute>\n";
}

/// The gap surface at one step: its faces (triangles, quadrilaterals or both) and the step's node
/// fields at its points.
void XdmfIndex::write_gap_grid(std::ostream &out, const std::string &indent, const Gap &gap,
                               const Step &step, const int index) const
{
  const std::string in1 = indent + "  ";
  const std::string in2 = in1 + "  ";
  const std::string points = std::to_string(gap.n_points);
  const std::string faces = std::to_string(gap.n_faces);
  const std::string group = "/" + gap.name;
  out << indent << "<Grid Name=\"" << gap.name << "_" << step_group_name(index)
      << "\" GridType=\"Uniform\">\n";
  out << in1 << "<Time Value=\"" << std::setprecision(17) << step.time << "\"/>\n";
  if (!gap.face_type)
  {
    out << in1 << "<Topology TopologyType=\"Mixed\" NumberOfElements=\"" << faces << "\">\n";
    write_data_item(out, in2, group + "/connectivity", std::to_string(gap.n_entries), "Int", 8);
  }
  else
  {
    const std::string nodes = std::to_string(ReferenceCell::of(*gap.face_type).n_nodes());
    out << in1 << "<Topology TopologyType=\"" << xdmf_name(*gap.face_type)
        << "\" NumberOfElements=\"" << faces << "\" NodesPerElement=\"" << nodes << "\">\n";
    write_data_item(out, in2, group + "/connectivity", faces + " " + nodes, "Int", 8);
  }
  out << in1 << "</Topology>\n";
  out << in1 << "<Geometry GeometryType=\"XYZ\">\n";
  write_data_item(out, in2, group + "/coordinates", points + " 3", "Float", 8);
  out << in1 << "</Geometry>\n";
  for (const auto &f : step.fields)
    if (f.center == Center::node)
      write_attribute(out, in1, f, points,
                      group + "/steps/" + step_group_name(index) + "/" + f.name);
  out << indent << "</Grid>\n";
}

std::string XdmfIndex::text() const
{
  std::ostringstream out;
  out << "<?xml version=\"1.0\" ?>\n"
      << "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
      << "  <Domain>\n";
  if (steps_.empty())
    write_grid(out, "    ", nullptr, 0);
  else
  {
    // The gaps first: meshio's TimeSeriesReader reads the last Temporal collection.
    for (const Gap &gap : gaps_)
    {
      out << "    <Grid Name=\"" << gap.name
          << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
      for (std::size_t s = 0; s < steps_.size(); ++s)
        write_gap_grid(out, "      ", gap, steps_[s], static_cast<int>(s));
      out << "    </Grid>\n";
    }
    out << "    <Grid Name=\"results\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (std::size_t s = 0; s < steps_.size(); ++s)
      write_grid(out, "      ", &steps_[s], static_cast<int>(s));
    out << "    </Grid>\n";
  }
  out << "  </Domain>\n"
      << "</Xdmf>\n";
  return out.str();
}

void XdmfIndex::write() const
{
  bool ok = true;
  int error_number = 0;
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  if (rank == 0)
  {
    const std::string temporary = xmf_path_ + ".tmp";
    {
      std::ofstream out(temporary, std::ios::trunc);
      out << text();
      out.close();
      ok = static_cast<bool>(out);
    }
    ok = ok && std::rename(temporary.c_str(), xmf_path_.c_str()) == 0;
    error_number = ok ? 0 : errno;
    if (!ok)
      std::remove(temporary.c_str());
  }
  const std::string reason = error_number != 0 ? std::strerror(error_number) : "an I/O error";
  const Teuchos::MpiComm<int> comm(comm_);
  check_write_collectively(comm, ok, xmf_path_,
                           "cannot write the XDMF file (" + reason +
                               "); check that its folder is writable, that the disk is not full "
                               "and that no file-size limit (ulimit -f) stops it");
}
} // namespace internal
} // namespace kiln
