// Tests io/input_reader: strict numbers (Teuchos alone reads "70GPa" as 70, "1e400" as inf,
// an int that overflows as another int), the structure of the tree (names given once, only
// Parameter and ParameterList elements, types Teuchos knows), the text (empty, binary, too
// large, nested too deep: 100000 levels used to overflow the stack), malformed XML, and
// reading a file collectively.
// KILN_TEST_NP: 1 2
#include "base/errors.hpp"
#include "io/input_reader.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

using testing::HasSubstr;

namespace
{
std::string error_of(const std::string &xml)
{
  try
  {
    kiln::parse_input(xml, "t.xml");
  }
  catch (const kiln::InputError &e)
  {
    return e.what();
  }
  return "";
}
} // namespace

TEST(InputReader, ParsesNumbersAndArrays)
{
  const auto p =
      kiln::parse_input("<ParameterList name=\"Kiln\"><ParameterList name=\"A\">"
                        "<Parameter name=\"E\" type=\"double\" value=\" 6.9e10 \"/>"
                        "<Parameter name=\"N\" type=\"int\" value=\"4\"/>"
                        "<Parameter name=\"V\" type=\"Array(double)\" value=\"{1, -2.5e-3, 3}\"/>"
                        "</ParameterList></ParameterList>",
                        "t.xml");
  EXPECT_EQ(p.sublist("A").get<double>("E"), 6.9e10);
  EXPECT_EQ(p.sublist("A").get<int>("N"), 4);
  EXPECT_EQ(p.sublist("A").get<Teuchos::Array<double>>("V")[1], -2.5e-3);
}

TEST(InputReader, RejectsNumbersWithUnits)
{
  EXPECT_THAT(error_of("<ParameterList name=\"Kiln\"><ParameterList name=\"Solid\">"
                       "<Parameter name=\"E\" type=\"double\" value=\"70GPa\"/>"
                       "</ParameterList></ParameterList>"),
              HasSubstr("t.xml:1: Kiln/Solid/\"E\": value \"70GPa\" is not a double"));
  EXPECT_THAT(error_of("<ParameterList name=\"Kiln\">"
                       "<Parameter name=\"N\" type=\"int\" value=\"4.5\"/></ParameterList>"),
              HasSubstr("Kiln/\"N\": value \"4.5\" is not an int"));
  EXPECT_THAT(error_of("<ParameterList name=\"Kiln\">"
                       "<Parameter name=\"V\" type=\"Array(int)\" value=\"{1, 2x}\"/>"
                       "</ParameterList>"),
              HasSubstr("is not an Array(int)"));
}

TEST(InputReader, RejectsMalformedXml)
{
  EXPECT_THAT(error_of("<ParameterList name=\"Kiln\"><ParameterList name=\"A\">"),
              HasSubstr("t.xml: not a well-formed XML file: XML parse error"));
  EXPECT_THAT(error_of("<Other/>"), HasSubstr("the root element is <Other>"));
}

TEST(InputReader, ReadsFileOnEveryRankAndFailsAlike)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string path = "input_reader_test.xml";
  if (comm->getRank() == 0)
    std::ofstream(path) << "<ParameterList name=\"Kiln\">"
                           "<Parameter name=\"X\" type=\"double\" value=\"2\"/></ParameterList>";
  comm->barrier();
  EXPECT_EQ(kiln::read_input(path, *comm).get<double>("X"), 2.0);
  comm->barrier();
  if (comm->getRank() == 0)
    std::remove(path.c_str());
  try
  {
    kiln::read_input("no-such-file.xml", *comm);
    FAIL() << "no error for a missing file";
  }
  catch (const kiln::InputError &e)
  {
    EXPECT_THAT(e.what(), HasSubstr("no-such-file.xml: cannot open the input file"));
  }
}

namespace
{
/// A deck with one parameter of `type` and `value` in Kiln/A.
std::string deck(const std::string &type, const std::string &value)
{
  return "<ParameterList name=\"Kiln\"><ParameterList name=\"A\"><Parameter name=\"P\" type=\"" +
         type + "\" value=\"" + value + "\"/></ParameterList></ParameterList>";
}

std::string value_error(const std::string &type, const std::string &value)
{
  return error_of(deck(type, value));
}
} // namespace

TEST(InputReader, AcceptsNumbersWrittenInFull)
{
  for (const char *v : {"1", "-2.5e-3", " 6.9e10 ", "+3", ".5", "5.", "1E5", "0", "-0.0", "1e-300",
                        "1.7976931348623157e308"})
    EXPECT_EQ(value_error("double", v), "") << v;
  for (const char *v : {"4", "-2147483648", "2147483647", "+7", "007"})
    EXPECT_EQ(value_error("int", v), "") << v;
  EXPECT_EQ(value_error("long long", "9223372036854775807"), "");
  EXPECT_EQ(value_error("unsigned int", "4294967295"), "");
  for (const char *v : {"true", "False", "YES", "no", "1", "0"})
    EXPECT_EQ(value_error("bool", v), "") << v;
  EXPECT_EQ(value_error("string", "anything, {even} 1e400"), "");
  EXPECT_EQ(value_error("Array(double)", "{}"), "");
  EXPECT_EQ(value_error("Array(double)", " { 1 , -2.5e3 } "), "");
  EXPECT_EQ(value_error("Array(string)", "{x, y}"), "");
  const auto p = kiln::parse_input(deck("double", "-2.5e-3"), "t.xml");
  EXPECT_EQ(p.sublist("A").get<double>("P"), -2.5e-3);
}

TEST(InputReader, RejectsNumbersTeuchosMisreads)
{
  const auto expect = [](const std::string &type, const std::string &value, const std::string &part)
  {
    const std::string message = value_error(type, value);
    EXPECT_THAT(message, HasSubstr("t.xml:1: Kiln/A/\"P\": value \"" + value + "\" " + part))
        << type << " " << value;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  };
  expect("double", "1e400", "is beyond the range of a double (magnitudes up to about 1.8e308)");
  expect("double", "-1e400", "is beyond the range of a double");
  expect("double", "1e-400", "is too small for a double");
  expect("double", "inf", "is not a finite number");
  expect("double", "-Infinity", "is not a finite number");
  expect("double", "NaN", "is not a finite number");
  expect("double", "0x10", "is written in hexadecimal");
  expect("double", "1,5", "is not a double; write the number alone");
  expect("double", "1e", "is not a double");
  expect("double", "", "is not a double");
  expect("double", "2.7e3 kg/m^3", "is not a double");
  expect("float", "1e39", "is beyond the range of a float (magnitudes up to about 3.4e38)");
  expect("int", "4294967306", "is outside the range of an int, -2147483648 to 2147483647");
  expect("int", "-2147483649", "is outside the range of an int");
  expect("int", "1e3", "is not an int; write a whole number");
  expect("int", "0x10", "is written in hexadecimal");
  expect("unsigned int", "-1", "is outside the range of an unsigned int, 0 to 4294967295");
  expect("short", "40000", "is outside the range of a short");
  expect("bool", "MAYBE", "is not a bool; write true or false");
  expect("bool", "", "is not a bool");
  expect("Array(double)", "{1, nan}", "is not an Array(double): entry 2, \"nan\", is not a finite");
  expect("Array(double)", "{1e400}", "is not an Array(double): entry 1, \"1e400\", is beyond");
  expect("Array(int)", "{0x10}", "is not an Array(int): entry 1, \"0x10\", is written in hex");
  expect("Array(int)", "{1, 2,}",
         "is not an Array(int): entry 3 is empty; remove the trailing comma");
  expect("Array(int)", "{,1}", "is not an Array(int): entry 1 is empty; remove the leading comma");
  expect("Array(int)", "{1,,2}", "is not an Array(int): entry 2 is empty; remove the extra comma");
  expect("Array(string)", "{a, }",
         "is not an Array(string): entry 2 is empty; remove the trailing comma");
  expect("Array(double)", "1, 2", "is not an Array(double): write the entries in braces");
  expect("Array(double)", "{1, {2}}", "is not an Array(double): entry 2, \"{2}\", holds a brace");
}

TEST(InputReader, RejectsNamesGivenTwiceWithTheirLines)
{
  const std::string message = error_of("<ParameterList name=\"Kiln\">\n"
                                       "  <!-- a comment\n over two lines -->\n"
                                       "  <ParameterList name=\"A\">\n"
                                       "    <Parameter name=\"P\" type=\"double\" value=\"1\"/>\n"
                                       "    <Parameter name=\"P\" type=\"double\" value=\"2\"/>\n"
                                       "  </ParameterList>\n"
                                       "</ParameterList>\n");
  EXPECT_THAT(message,
              HasSubstr("t.xml:6: Kiln/A/\"P\": is given twice in Kiln/A (lines 5 and 6)"));
  EXPECT_THAT(error_of("<?xml version=\"1.0\"?>\n<ParameterList name=\"Kiln\">\n"
                       "<ParameterList name=\"A\"/>\n<ParameterList name=\"A\"/>\n"
                       "</ParameterList>"),
              HasSubstr("t.xml:4: Kiln/\"A\": is given twice in Kiln (lines 3 and 4); only one "
                        "can apply: merge the two lists into one"));
}

TEST(InputReader, RejectsWhatTeuchosIgnoresOrDumps)
{
  const auto in_list = [](const std::string &body)
  { return error_of("<ParameterList name=\"Kiln\">" + body + "</ParameterList>"); };
  EXPECT_THAT(in_list("<Paramter name=\"P\" type=\"int\" value=\"1\"/>"),
              HasSubstr("Kiln: unexpected element <Paramter> (did you mean <Parameter>?)"));
  EXPECT_THAT(in_list("<Parameter name=\"P\" type=\"int\" vale=\"1\"/>"),
              HasSubstr("Kiln/\"P\": unknown attribute \"vale\" on <Parameter> (did you mean "
                        "\"value\"?)"));
  EXPECT_THAT(in_list("<Parameter name=\"P\" type=\"float64\" value=\"1\"/>"),
              HasSubstr("unknown type \"float64\" (did you mean \"double\"?)"));
  EXPECT_THAT(in_list("<Parameter name=\"P\" type=\"integer\" value=\"1\"/>"),
              HasSubstr("(did you mean \"int\"?)"));
  EXPECT_THAT(in_list("<Parameter name=\"P\" value=\"1\"/>"), HasSubstr("has no type attribute"));
  EXPECT_THAT(in_list("<Parameter type=\"int\" value=\"1\"/>"),
              HasSubstr("a <Parameter> without a name attribute"));
  EXPECT_THAT(in_list("<Parameter name=\"\" type=\"int\" value=\"1\"/>"),
              HasSubstr("a <Parameter> with an empty name"));
  EXPECT_THAT(in_list("<Parameter name=\"P\" type=\"int\"/>"), HasSubstr("has no value attribute"));
  EXPECT_THAT(in_list("<Parameter name=\"P\" type=\"int\" value=\"1\"><a/></Parameter>"),
              HasSubstr("holds a <a> element"));
  EXPECT_THAT(in_list("oops"), HasSubstr("Kiln: stray text \"oops\" in the list"));
  EXPECT_THAT(error_of("<ParameterList><Parameter name=\"P\" type=\"int\" value=\"1\"/>"
                       "</ParameterList>"),
              HasSubstr("the root <ParameterList> has no name"));
  EXPECT_THAT(error_of("<ParameterList name=\"Kiln\" id=\"3\"></ParameterList>"),
              HasSubstr("unknown attribute \"id\" on <ParameterList>"));
  // Teuchos' own attributes, entities and pass-through types are read.
  const auto p = kiln::parse_input(
      "<ParameterList name=\"Kiln\"><Parameter name=\"S\" type=\"string\" value=\"a &amp; b\" "
      "docString=\"d\" isDefault=\"false\" isUsed=\"true\"/>"
      "<Parameter name=\"U\" type=\"unsigned int\" value=\"3\"/></ParameterList>",
      "t.xml");
  EXPECT_EQ(p.get<std::string>("S"), "a & b");
  EXPECT_EQ(p.get<unsigned int>("U"), 3U);
}

TEST(InputReader, RejectsEmptyBinaryHugeAndDeepTexts)
{
  EXPECT_THAT(error_of(""), HasSubstr("t.xml: the file is empty"));
  EXPECT_THAT(error_of(" \n\t\n"), HasSubstr("t.xml: the file is empty"));
  EXPECT_THAT(error_of("<!-- nothing -->"), HasSubstr("t.xml: the file holds no XML element"));
  EXPECT_THAT(error_of(std::string("CDF\x01\0\0\0\0", 8)),
              HasSubstr("t.xml: the file holds binary data (a zero byte at offset 4)"));
  EXPECT_THAT(error_of("<ParameterList name=\"Kiln\">" + std::string(kiln::max_input_bytes, ' ') +
                       "</ParameterList>"),
              HasSubstr("more than the 1048576 an input may have"));
  // 100000 levels overflowed the stack (a segmentation fault without a message).
  const int depth = 100000;
  std::string deep = "<ParameterList name=\"Kiln\">";
  for (int i = 0; i < depth; ++i)
    deep += "<a>";
  for (int i = 0; i < depth; ++i)
    deep += "</a>";
  deep += "</ParameterList>";
  EXPECT_THAT(error_of(deep), HasSubstr("t.xml:1: elements are nested more than 64 deep here"));
  // At the limit the deck is read (and the unexpected elements reported).
  std::string at_limit = "<ParameterList name=\"Kiln\">\n";
  for (int i = 1; i < kiln::max_input_depth; ++i)
    at_limit += "<ParameterList name=\"L" + std::to_string(i) + "\">\n";
  for (int i = 1; i < kiln::max_input_depth; ++i)
    at_limit += "</ParameterList>\n";
  at_limit += "</ParameterList>";
  EXPECT_NO_THROW(kiln::parse_input(at_limit, "t.xml"));
  EXPECT_THAT(error_of("<ParameterList name=\"Kiln\">\n<ParameterList name=\"A\">"),
              HasSubstr("t.xml: not a well-formed XML file: XML parse error at line 2"));
}

TEST(InputReader, ReadsDirectoriesAndMissingFilesAsOneLine)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  try
  {
    kiln::read_input(".", *comm);
    FAIL() << "no error for a directory";
  }
  catch (const kiln::InputError &e)
  {
    EXPECT_STREQ(e.what(), ".: is a directory, not an input file; give the path of the XML input");
  }
}
