#include "io/run_fingerprint.hpp"

#include "base/hash.hpp"

#include <Teuchos_XMLParameterListHelpers.hpp>

#include <cstdint>
#include <iomanip>
#include <sstream>

namespace kiln
{
namespace
{
/// The blocks of the input that define the problem, besides Physics.
const char *const physics_blocks[] = {"Mesh", "Material", "Materials", "Thermal", "Mechanics"};
} // namespace

RunFingerprint RunFingerprint::of(const Mesh &mesh, const DofLayout &layout,
                                  const Teuchos::ParameterList &input)
{
  RunFingerprint f;
  f.n_nodes = mesh.n_nodes();
  f.n_cells = mesh.n_cells();
  f.n_pairs = static_cast<int>(mesh.gap_pairs.size());
  // The first gap's side set (0: none); the mesh's counts tell several gaps apart.
  f.gap_side_set = mesh.gap_side_sets.empty() ? 0 : mesh.gap_side_sets.front();
  std::vector<double> coordinates;
  for (const Point &x : mesh.coordinates)
    coordinates.insert(coordinates.end(), x.begin(), x.end());
  const std::vector<int> &cells = mesh.cell_node_ids;
  std::uint64_t hash = fnv1a(coordinates.data(), coordinates.size());
  hash = fnv1a(cells.data(), cells.size(), hash);
  hash = fnv1a(mesh.block_id.data(), mesh.block_id.size(), hash);
  std::ostringstream hex;
  hex << std::hex << std::setw(16) << std::setfill('0') << hash;
  f.mesh_hash = hex.str();
  f.layout = std::string(layout.temperature ? "temperature " : "") +
             (layout.displacement ? "displacement " : "") + (layout.contact ? "contact" : "");
  f.physics.emplace_back("Kiln/\"Physics\"", input.get<std::string>("Physics"));
  for (const char *block : physics_blocks)
  {
    std::ostringstream xml;
    // A list the input lacks (a deck not read through validated()) counts as empty.
    Teuchos::writeParameterListToXmlOStream(
        input.isSublist(block) ? input.sublist(block) : Teuchos::ParameterList(block), xml);
    f.physics.emplace_back(std::string("Kiln/") + block, xml.str());
  }
  return f;
}

std::string RunFingerprint::difference(const RunFingerprint &saved) const
{
  std::ostringstream d;
  if (n_nodes != saved.n_nodes || n_cells != saved.n_cells || n_pairs != saved.n_pairs ||
      gap_side_set != saved.gap_side_set)
    d << "the mesh differs: the checkpoint's has " << saved.n_cells << " cells, " << saved.n_nodes
      << " nodes and " << saved.n_pairs << " gap pairs (gap side set " << saved.gap_side_set
      << "); this input's has " << n_cells << " cells, " << n_nodes << " nodes and " << n_pairs
      << " gap pairs (gap side set " << gap_side_set << ")";
  else if (mesh_hash != saved.mesh_hash)
    d << "the mesh differs: it has the checkpoint's sizes but other coordinates or cells "
         "(fingerprint "
      << mesh_hash << ", the checkpoint's " << saved.mesh_hash << ")";
  else if (layout != saved.layout)
    d << "the unknowns differ: the checkpoint has " << saved.layout << ", this input " << layout;
  else
    for (std::size_t i = 0; i < physics.size() && i < saved.physics.size(); ++i)
      if (physics[i] != saved.physics[i])
      {
        d << physics[i].first
          << " differs from the checkpoint's; a restart may change the time stepping, the "
             "solver, the output and the checkpoints, not the problem";
        break;
      }
  return d.str();
}

std::string RunFingerprint::digest() const
{
  std::ostringstream all;
  all << n_nodes << ' ' << n_cells << ' ' << n_pairs << ' ' << gap_side_set << ' ' << mesh_hash
      << ' ' << layout;
  for (const auto &[name, block] : physics)
    all << '\n' << name << '\n' << block;
  const std::string text = all.str();
  std::ostringstream hex;
  hex << std::hex << std::setw(16) << std::setfill('0') << fnv1a(text.data(), text.size());
  return hex.str();
}
} // namespace kiln
