// Tests base/errors: a Trilinos exception's text on one line (no source path, no "Throw
// number", no "Throw test that evaluated to true"), check_collectively, and
// check_run_collectively with step failures (StepFailure only if every failure is one).
// KILN_TEST_NP: 1 2
#include "base/errors.hpp"

#include <Teuchos_Assert.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <stdexcept>

using testing::HasSubstr;
using testing::Not;

TEST(Errors, LibraryMessageOnOneLine)
{
  const std::string teuchos =
      "./packages/teuchos/parameterlist/src/Teuchos_XMLObject.cpp:137:\n\n"
      "Throw number = 1\n\n"
      "Throw test that evaluated to true: val!=\"TRUE\" && val!=\"YES\"\n\n"
      "XMLObject::getRequiredBool value [MAYBE] should have been {TRUE|FALSE|YES|NO|0|1}\n";
  EXPECT_EQ(kiln::one_line_library_message(teuchos),
            "XMLObject::getRequiredBool value [MAYBE] should have been {TRUE|FALSE|YES|NO|0|1}");
  EXPECT_EQ(kiln::one_line_library_message("/usr/include/trilinos/X.hpp:12: first\n  second  \n"),
            "first; second");
  EXPECT_EQ(kiln::one_line_library_message("plain text"), "plain text");
  EXPECT_EQ(kiln::one_line_library_message(""), "");
}

TEST(Errors, LibraryMessageOfARealTeuchosException)
{
  try
  {
    TEUCHOS_TEST_FOR_EXCEPTION(true, std::runtime_error, "the package's own words");
  }
  catch (const std::exception &e)
  {
    const std::string line = kiln::one_line_library_message(e.what());
    EXPECT_EQ(line, "the package's own words");
    EXPECT_THAT(line, Not(HasSubstr("Throw")));
  }
}

TEST(Errors, CheckCollectivelyThrowsTheSameTextOnEveryRank)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const bool ok = comm->getRank() != comm->getSize() - 1; // fails on the last rank only
  try
  {
    kiln::check_collectively(*comm, ok, "in.xml", "rank " + std::to_string(comm->getRank()));
    FAIL() << "no InputError";
  }
  catch (const kiln::InputError &e)
  {
    EXPECT_EQ(std::string(e.what()), "in.xml: rank " + std::to_string(comm->getSize() - 1));
  }
}

TEST(Errors, AStepFailureOnSomeRanksIsTheSameStepFailureOnEveryRank)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const int last = comm->getSize() - 1;
  const bool ok = comm->getRank() != last;
  EXPECT_NO_THROW(kiln::check_run_collectively(*comm, true, "", true));
  try
  {
    kiln::check_run_collectively(*comm, ok, ok ? "" : "local solve on rank " + std::to_string(last),
                                 !ok);
    FAIL() << "no StepFailure";
  }
  catch (const kiln::StepFailure &e)
  {
    EXPECT_EQ(std::string(e.what()), "local solve on rank " + std::to_string(last));
  }
}

TEST(Errors, AnotherFailureAmongStepFailuresIsARunErrorWithItsMessage)
{
  // Every rank fails: rank 0 with a step failure, the others (and rank 0 alone on one rank:
  // then its failure is not a step failure) otherwise.
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const int rank = comm->getRank();
  const bool step = comm->getSize() > 1 && rank == 0;
  try
  {
    kiln::check_run_collectively(*comm, false, (step ? "step " : "fatal ") + std::to_string(rank),
                                 step);
    FAIL() << "no RunError";
  }
  catch (const kiln::StepFailure &)
  {
    FAIL() << "a StepFailure where a rank failed otherwise";
  }
  catch (const kiln::RunError &e)
  {
    // The message of the lowest rank whose failure was not a step failure.
    EXPECT_EQ(std::string(e.what()), comm->getSize() > 1 ? "fatal 1" : "fatal 0");
  }
}
