#include "physics/materials/material_map.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"

#include <Teuchos_Array.hpp>

#include <algorithm>
#include <sstream>

namespace kiln
{
Teuchos::ParameterList MaterialMap::valid_named_parameters()
{
  Teuchos::ParameterList p = Material::valid_parameters();
  p.set("Blocks", Teuchos::Array<int>(),
        "the element block ids made of this material: each block of the mesh in exactly one "
        "material [-]");
  return p;
}

namespace
{
std::string listed(const std::vector<int> &ids)
{
  std::ostringstream s;
  for (std::size_t i = 0; i < ids.size(); ++i)
    s << (i == 0 ? "" : ", ") << ids[i];
  return s.str();
}
} // namespace

MaterialMap::MaterialMap(const Teuchos::ParameterList &kiln, const std::vector<int> &block_ids,
                         const std::string &input_path)
{
  const Teuchos::ParameterList &named = kiln.sublist("Materials");
  if (named.numParams() == 0)
  {
    // Kiln/Material (given or all defaults): one material for every block.
    const std::string where = input_path + ": Kiln/Material";
    materials_.emplace_back(kiln.sublist("Material"), where);
    names_.push_back("Material");
    paths_.push_back(where);
    blocks_.push_back(block_ids);
    for (const int block : block_ids)
      material_of_block_[block] = 0;
    return;
  }
  KILN_CHECK_INPUT(!given_in_input(kiln, "Material"),
                   parameter_path(input_path, "Kiln", "Material"),
                   "is given together with Kiln/\"Materials\"; give one material for every "
                   "block in Kiln/Material, or named materials with their \"Blocks\" in "
                   "Kiln/Materials, not both");
  const std::string valid_blocks = " (the mesh's element blocks: " + listed(block_ids) + ")";
  for (auto it = named.begin(); it != named.end(); ++it)
  {
    const std::string &name = named.name(it);
    const Teuchos::ParameterList &p = named.sublist(name);
    const std::string path = "Kiln/Materials/" + name;
    const std::string where = input_path + ": " + path;
    const auto &blocks = p.get<Teuchos::Array<int>>("Blocks");
    KILN_CHECK_INPUT(!blocks.empty(), parameter_path(input_path, path, "Blocks"),
                     "is missing or empty; list the element block ids made of material \""
                         << name << "\"" << valid_blocks);
    const int index = static_cast<int>(materials_.size());
    for (const int block : blocks)
    {
      KILN_CHECK_INPUT(std::find(block_ids.begin(), block_ids.end(), block) != block_ids.end(),
                       parameter_path(input_path, path, "Blocks"),
                       "block " << block << " is not in the mesh" << valid_blocks);
      const auto [at, inserted] = material_of_block_.emplace(block, index);
      KILN_CHECK_INPUT(inserted, parameter_path(input_path, path, "Blocks"),
                       "block " << block << " is also in Kiln/Materials/"
                                << (at->second == index ? name : names_[at->second])
                                << "/\"Blocks\"; every block has exactly one material: remove "
                                   "it from one of them");
    }
    materials_.emplace_back(p, where);
    names_.push_back(name);
    paths_.push_back(where);
    blocks_.emplace_back(blocks.begin(), blocks.end());
  }
  std::string names;
  for (const std::string &n : names_)
    names += (names.empty() ? "\"" : ", \"") + n + "\"";
  for (const int block : block_ids)
    KILN_CHECK_INPUT(material_of_block_.count(block) == 1, input_path + ": Kiln/Materials",
                     "element block " << block
                                      << " has no material; add it to the \"Blocks\" of one of "
                                         "the materials ("
                                      << names << ")");
}

int MaterialMap::index_of_block(const int block_id) const
{
  const auto it = material_of_block_.find(block_id);
  KILN_ASSERT(it != material_of_block_.end(), "block " << block_id << " has no material");
  return it->second;
}

bool MaterialMap::all_constant() const
{
  return std::all_of(materials_.begin(), materials_.end(),
                     [](const Material &m) { return m.is_constant(); });
}

const Material &MaterialMap::uniform_material() const
{
  return materials_.front();
}
} // namespace kiln
