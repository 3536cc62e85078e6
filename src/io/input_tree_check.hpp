#pragma once
/// The checks of an input's text and XML tree before Teuchos converts it (io/input_reader.hpp
/// says which): the text's size and content, how deeply it nests, and the tree's elements,
/// attributes, names and values, each a one-line InputError naming the file and line.
#include <Teuchos_XMLObject.hpp>

#include <string>
#include <vector>

namespace kiln::internal
{
/// One start tag as the pre-scan saw it: its line and attribute names, in document
/// order, which is also the pre-order of the tree Teuchos builds from the same text.
struct StartTag
{
  int line = 0;
  std::vector<std::string> attributes;
};

/// Throws InputError (naming `where`) if `xml` is larger than max_input_bytes, empty or
/// binary.
void check_text(const std::string &xml, const std::string &where);
/// The start tags of `xml` (scan_start_tags' rules in its source); throws InputError if the
/// elements nest deeper than max_input_depth.
std::vector<StartTag> scan_start_tags(const std::string &xml, const std::string &where);
/// Throws InputError naming the file, line and parameter path unless `root` (parsed from the
/// text `tags` were scanned from) is <ParameterList name="Kiln"> holding only
/// <ParameterList name> and <Parameter name type value/>, each name once, with values of
/// their types.
void check_tree(const Teuchos::XMLObject &root, const std::vector<StartTag> &tags,
                const std::string &where);
} // namespace kiln::internal
