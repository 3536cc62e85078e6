#pragma once
/// The material of each element block: materials by name, each assigned to blocks.
#include "physics/materials/material.hpp"

#include <Teuchos_ParameterList.hpp>

#include <map>
#include <string>
#include <vector>

namespace kiln
{
/// Which material each element block is made of (doc/materials.md, "Materials and blocks").
/// The input gives either
/// - Kiln/Material: one material for every block (the decks before issue 31), or
/// - Kiln/Materials: named sublists, each a Material plus "Blocks", the element block ids it
///   fills (as Truchas' BODY material_name and MOOSE's `block =`).
/// Every block of the mesh has exactly one material; both lists at once is an input error.
class MaterialMap
{
public:
  /// One entry of Kiln/Materials: Material::valid_parameters() and "Blocks".
  static Teuchos::ParameterList valid_named_parameters();
  /// `kiln` is the validated Kiln list (its "Material" and "Materials"), `block_ids` the mesh's
  /// distinct element block ids, `input_path` the input file for messages. Throws InputError
  /// naming the list, the material and the block if both lists are given, if a block has no
  /// material or two, if a material lists a block the mesh lacks or no block, or if a
  /// material's properties are invalid.
  MaterialMap(const Teuchos::ParameterList &kiln, const std::vector<int> &block_ids,
              const std::string &input_path);

  /// The number of distinct materials.
  int n_materials() const { return static_cast<int>(materials_.size()); }
  /// Material i (0 <= i < n_materials()), in input order.
  const Material &material(const int i) const { return materials_[i]; }
  /// Its name: the Materials entry's name, or "Material" for Kiln/Material.
  const std::string &name(const int i) const { return names_[i]; }
  /// The index of the material of element block `block_id` (a block of the mesh).
  int index_of_block(int block_id) const;
  /// The material of element block `block_id` (a block of the mesh).
  const Material &of_block(const int block_id) const
  {
    return materials_[index_of_block(block_id)];
  }
  /// Whether no property of any material depends on T.
  bool all_constant() const;

  /// The material of the problem's scales (the reference temperature, the contact's modulus):
  /// the first. The physics take each block's material (ThermalPhysics: rho(T), c(T), k(T);
  /// MechanicalPhysics: the elastic constants, expansion, model and the density of the body
  /// force rho(T) g).
  const Material &uniform_material() const;
  /// Block id -> material index, for every block of the mesh.
  const std::map<int, int> &material_of_block() const { return material_of_block_; }

private:
  std::vector<Material> materials_;
  std::vector<std::string> names_;
  std::vector<std::string> paths_;       ///< "in.xml: Kiln/Materials/steel", for messages
  std::vector<std::vector<int>> blocks_; ///< the blocks of each material, as given
  std::map<int, int> material_of_block_; ///< block id -> material index
};
} // namespace kiln
