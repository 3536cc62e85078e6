// Tests io/input_reader: strict numbers (Teuchos alone reads "70GPa" as 70),
// malformed XML, and reading a file collectively.
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
              HasSubstr("t.xml: Kiln/Solid/\"E\": value \"70GPa\" is not a double"));
  EXPECT_THAT(error_of("<ParameterList name=\"Kiln\">"
                       "<Parameter name=\"N\" type=\"int\" value=\"4.5\"/></ParameterList>"),
              HasSubstr("Kiln/\"N\": value \"4.5\" is not a int"));
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
