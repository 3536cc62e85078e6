#include "mesh/mesh_factory.hpp"

#include "base/errors.hpp"
#include "base/log.hpp"
#include "base/parameters.hpp"
#include "mesh/box_mesh_generator.hpp"
#include "mesh/exodus_io.hpp"
#include "mesh/mesh_checks.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace kiln
{
Teuchos::ParameterList MeshFactory::valid_parameters()
{
  Teuchos::ParameterList p("Mesh");
  p.set("Type", "Box",
        "\"Box\": the generated block (sublist Box); \"Exodus\": an Exodus II "
        "file (sublist Exodus)",
        choice_validator({"Box", "Exodus"}));
  p.set("Gap Side Set", 10,
        "id of the interior side set at which the mesh is split into a gap of zero width; "
        "0 for no gap (for several gaps, \"Gap Side Sets\"); with Box/\"Second Half Cells\" "
        "no gap unless given (given nonzero, an error: the halves share no plane) [-]",
        nonnegative_int_validator());
  p.set("Gap Side Sets", Teuchos::Array<int>(),
        "ids of the interior side sets at which the mesh is split into gaps, which may cross "
        "(the box's 10, 11 and 12 are its mid-planes normal to x, y and z); a node where k "
        "parts meet gets a copy per part. Given, it replaces \"Gap Side Set\" (give one of "
        "the two) [-]");
  p.set("Partition", "METIS",
        "how the cells are shared among the MPI ranks: \"METIS\" (k-way, balanced, few cut "
        "faces); \"By Block\": the element blocks in increasing id go to the ranks in order, "
        "block i to rank i np / n_blocks (needs at most as many ranks as blocks; for tests "
        "and studies, e.g. the two halves of the contact box on two ranks, the partition "
        "boundary on the gap)",
        choice_validator({"METIS", "By Block"}));
  p.sublist("Box", false, "the generated block; see doc/mesh.md")
      .setParameters(BoxMeshGenerator::valid_parameters());
  Teuchos::ParameterList &exodus = p.sublist("Exodus", false, "an Exodus II mesh (Cubit)");
  exodus.set("File", "",
             "path of the Exodus II file, relative to the working directory; required when "
             "Type = \"Exodus\" unless given by kiln --mesh FILE");
  exodus.set("Coordinate Scale", 1.0,
             "factor applied to the file's coordinates to get metres (0.01 for a mesh in cm; "
             "must be 1 for a file written by Kiln, which is in metres) [m per file unit]",
             positive_double_validator());
  return p;
}

MeshFactory::MeshFactory(const Teuchos::ParameterList &params, const std::string &where,
                         const std::string &mesh_file)
    : params_(params), where_(where)
{
  type_ = mesh_file.empty() ? params.get<std::string>("Type") : "Exodus";
  exodus_file_ = mesh_file.empty() ? params.sublist("Exodus").get<std::string>("File") : mesh_file;
  scale_ = params.sublist("Exodus").get<double>("Coordinate Scale");
  const auto &gap_sets = params.get<Teuchos::Array<int>>("Gap Side Sets");
  if (!gap_sets.empty())
  {
    KILN_CHECK_INPUT(!given_in_input(params, "Gap Side Set"), where_ + "/\"Gap Side Sets\"",
                     "is given with \"Gap Side Set\"; give one of the two (\"Gap Side Sets\" "
                     "for several gaps)");
    for (const int id : gap_sets)
      KILN_CHECK_INPUT(id > 0, where_ + "/\"Gap Side Sets\"",
                       "lists " << id << "; side set ids are positive");
    gap_side_sets_.assign(gap_sets.begin(), gap_sets.end());
    gap_parameter_ = "Gap Side Sets";
  }
  else
  {
    if (params.get<int>("Gap Side Set") != 0)
      gap_side_sets_.push_back(params.get<int>("Gap Side Set"));
    gap_parameter_ = "Gap Side Set";
  }
  // Halves meshed apart share no plane to split at: no gap unless one is asked for (refused).
  if (type_ == "Box" &&
      !params.sublist("Box").get<Teuchos::Array<int>>("Second Half Cells").empty())
  {
    KILN_CHECK_INPUT(gap_side_sets_.empty() || !given_in_input(params, gap_parameter_),
                     where_ + "/\"" + gap_parameter_ + "\"",
                     "names a gap, but Box/\"Second Half Cells\" meshes the halves apart: they "
                     "share no side set to split at. Set it to 0 and pair the cut faces (side "
                     "sets 10 and 20) in Mechanics/Contact/Pairs");
    gap_side_sets_.clear();
  }
  if (!mesh_file.empty() && params.get<std::string>("Type") == "Box")
  {
    const auto &cells = params.sublist("Box").get<Teuchos::Array<int>>("Cells");
    std::ostringstream note;
    note << where_ << ": --mesh " << mesh_file
         << " replaces the Box this input defines (Type = \"Box\", Cells {" << cells[0] << ", "
         << cells[1] << ", " << cells[2] << "}); the file is read with Exodus/\"Coordinate "
         << "Scale\" = " << scale_ << " [m per file unit]"
         << (given_in_input(params.sublist("Exodus"), "Coordinate Scale")
                 ? ""
                 : ", the default: its coordinates are taken as metres (set Kiln/Mesh/Exodus/"
                   "\"Coordinate Scale\" to 0.01 for a mesh in cm)");
    warn_once(note.str());
  }
  KILN_CHECK_INPUT(type_ != "Exodus" || !exodus_file_.empty(), where_ + "/Exodus/\"File\"",
                   "missing: Type = \"Exodus\" needs the path of the mesh file; set "
                   "Mesh/Exodus/\"File\" or run kiln --mesh FILE");
}

Mesh MeshFactory::build() const
{
  KILN_CHECK_INPUT(type_ != "Exodus" || std::filesystem::exists(exodus_file_),
                   where_ + "/Exodus/\"File\"",
                   "the mesh file \"" << exodus_file_
                                      << "\" does not exist (relative paths start "
                                         "from the working directory "
                                      << std::filesystem::current_path().string() << ")");
  Mesh mesh;
  if (type_ == "Box")
  {
    const auto wants = [&](const int id)
    { return std::find(gap_side_sets_.begin(), gap_side_sets_.end(), id) != gap_side_sets_.end(); };
    mesh = BoxMeshGenerator(params_.sublist("Box"), where_ + "/Box").generate(wants(11), wants(12));
  }
  else
  {
    // Kiln writes metres; a scale meant for a Cubit file in cm would shrink such a file.
    KILN_CHECK_INPUT(scale_ == 1.0 || !exodus_file_in_metres(exodus_file_),
                     where_ + "/Exodus/\"Coordinate Scale\"",
                     "is " << scale_ << ", but the mesh file \"" << exodus_file_
                           << "\" was written by Kiln (kiln --write-mesh or Exodus results) and "
                              "its coordinates are in metres already: they would be multiplied "
                              "by "
                           << scale_
                           << ". Set \"Coordinate Scale\" to 1 for this file (a scale is for "
                              "meshes from other programs, 0.01 for Cubit meshes in cm)");
    mesh = read_exodus_mesh(exodus_file_, scale_);
  }
  std::ostringstream scale;
  if (type_ == "Box")
    scale << where_ << "/Box/\"Size\" and \"Cells\"";
  else
    scale << where_ << "/Exodus/\"Coordinate Scale\" = " << scale_
          << " (0.01 for a mesh in cm, 0.001 in mm)";
  check_mesh(mesh, type_ == "Box" ? where_ + "/Box" : exodus_file_, scale.str());
  return mesh;
}

MeshFactory::Counts MeshFactory::counts() const
{
  Counts c;
  if (type_ == "Box")
  {
    const BoxMeshGenerator box(params_.sublist("Box"), where_ + "/Box"); // checks the counts
    const auto &cells = params_.sublist("Box").get<Teuchos::Array<int>>("Cells");
    c.cells = box.n_cells();
    // The split at a mid-plane (the box's interior side sets 10, 11, 12) gives its nodes
    // copies (where planes cross, more: an estimate).
    c.nodes = box.n_nodes();
    for (const int id : gap_side_sets_)
      for (int d = 0; d < 3; ++d)
        if (id == 10 + d)
          c.nodes += (cells[(d + 1) % 3] + 1LL) * (cells[(d + 2) % 3] + 1LL);
    c.source = where_ + "/Box/\"Cells\" = {" + std::to_string(cells[0]) + ", " +
               std::to_string(cells[1]) + ", " + std::to_string(cells[2]) + "}";
    return c;
  }
  KILN_CHECK_INPUT(std::filesystem::exists(exodus_file_), where_ + "/Exodus/\"File\"",
                   "the mesh file \"" << exodus_file_
                                      << "\" does not exist (relative paths start "
                                         "from the working directory "
                                      << std::filesystem::current_path().string() << ")");
  const ExodusCounts exodus = exodus_counts(exodus_file_);
  c.cells = exodus.elements;
  c.nodes = exodus.nodes;
  c.source = "the mesh file " + exodus_file_;
  return c;
}

std::string MeshFactory::description() const
{
  if (type_ == "Exodus")
    return "Exodus file " + exodus_file_;
  const auto &cells = params_.sublist("Box").get<Teuchos::Array<int>>("Cells");
  return "generated box " + std::to_string(cells[0]) + " x " + std::to_string(cells[1]) + " x " +
         std::to_string(cells[2]);
}
} // namespace kiln
