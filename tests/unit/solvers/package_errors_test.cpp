// Tests src/solvers/package_errors.cpp: package_message() keeps what a Trilinos exception
// says and drops what TEUCHOS_TEST_FOR_EXCEPTION puts around it and Teuchos' list of valid
// parameters; as_input_error() turns an exception on one rank into the same InputError,
// naming the block, on every rank.
// KILN_TEST_NP: 1 2
#include "solvers/package_errors.hpp"

#include "base/errors.hpp"

#include <Teuchos_DefaultComm.hpp>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace
{
using kiln::internal::package_message;

TEST(PackageMessage, DropsTheThrowTestItsLocationAndNumber)
{
  const std::string thrown =
      "/usr/include/trilinos/Teuchos_StandardParameterEntryValidators.hpp:2377:\n"
      "\n"
      "Throw number = 3\n"
      "\n"
      "Throw test that evaluated to true: true\n"
      "\n"
      "Error, the value \"No Such Solver\" is not recognized for the parameter \"Solver Type\".\n"
      "Valid values are: \"Block GMRES\", \"Pseudo Block GMRES\"\n";
  EXPECT_EQ(package_message(thrown),
            "Error, the value \"No Such Solver\" is not recognized for the parameter \"Solver "
            "Type\".\nValid values are: \"Block GMRES\", \"Pseudo Block GMRES\"");
}

TEST(PackageMessage, DropsTheListOfValidParametersButKeepsTheSuggestion)
{
  const std::string thrown = "The parameter name \"smoother: tpye\" is not valid.\n"
                             "\n"
                             "The valid parameters and types are:\n"
                             "  {\n"
                             "    \"smoother: type\" : string\n"
                             "  }\n"
                             "Did you mean \"smoother: type\"?\n";
  EXPECT_EQ(package_message(thrown), "The parameter name \"smoother: tpye\" is not valid.\n\n"
                                     "Did you mean \"smoother: type\"?");
}

TEST(PackageMessage, KeepsAPlainMessage)
{
  EXPECT_EQ(package_message("Invalid choice for \"Method\"\n\n\n\nin \"Direction\"  \n"),
            "Invalid choice for \"Method\"\n\nin \"Direction\"");
  EXPECT_EQ(package_message(""), "");
}

TEST(AsInputError, AnExceptionOnTheLastRankIsAnInputErrorOnEveryRank)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const bool last = comm->getRank() == comm->getSize() - 1;
  EXPECT_NO_THROW(kiln::internal::as_input_error(*comm, "Solver/Linear Solver", [] {}));
  try
  {
    kiln::internal::as_input_error(*comm, "Solver/Linear Solver",
                                   [&]
                                   {
                                     if (last)
                                       throw std::invalid_argument("Throw number = 1\nbad value");
                                   });
    ADD_FAILURE() << "no exception";
  }
  catch (const kiln::InputError &e)
  {
    EXPECT_EQ(std::string(e.what()), "Solver/Linear Solver: bad value");
  }
}
} // namespace
