#pragma once
/// Reads a Teuchos XML input file: rank 0 reads the text, every rank parses
/// the same text, so every rank raises the same error for a bad file.
///
/// Teuchos alone accepts much that Kiln does not: it reads value="70GPa" as 70,
/// "1e400" and "inf" as infinity, "0x10" and "nan" inside arrays as 0, an int that
/// overflows as another int, keeps the last of two parameters of the same name
/// without a word, ignores elements it does not know (<Paramter>), and a deeply
/// nested file overflows the stack. parse_input() checks the text and the XML tree
/// before Teuchos converts it, so that each of these is one InputError naming the
/// file, the line, the parameter path, what was expected and what to do.
#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include <chrono>
#include <cstddef>
#include <string>

namespace kiln
{
/// Inputs larger than this are refused before they are parsed (a Kiln input is a
/// few kB; a large file is most likely the wrong one, and Teuchos' parser keeps
/// every character of text as a string of its own).
constexpr std::size_t max_input_bytes = std::size_t(1) << 20;
/// Elements nested deeper than this are refused before they are parsed (a Kiln
/// input nests about 8 lists; Teuchos' reader recurses once per level).
constexpr int max_input_depth = 64;
/// How long rank 0 waits for an input that is not a regular file (a FIFO, a
/// device) to send its text and its end; a FIFO nobody writes is refused after it.
constexpr std::chrono::seconds input_wait{5};

/// The unvalidated parameter list in `path`. Throws InputError naming the file
/// when it cannot be read, is a directory, is empty or binary, is not well-formed
/// XML, or breaks one of the rules of parse_input().
Teuchos::ParameterList read_input(const std::string &path, const Teuchos::Comm<int> &comm);

/// The same for XML text; `where` names it in messages. The rules: the root is
/// <ParameterList name="Kiln">; a list holds only <Parameter name type value/> and
/// <ParameterList name> elements, each name once; a type Teuchos knows; numbers
/// written in full, in decimal, finite and in the range of their type (also in
/// arrays, which are written {a, b, c} without empty entries); bools true or false.
Teuchos::ParameterList parse_input(const std::string &xml, const std::string &where);

namespace internal
{
/// Reads at most max_input_bytes + 1 bytes of `path` (of any kind of file) into
/// `text`, waiting at most input_wait; returns "" or what is wrong (with the
/// system's reason when the file cannot be opened).
std::string read_input_text(const std::string &path, std::string &text);
} // namespace internal
} // namespace kiln
