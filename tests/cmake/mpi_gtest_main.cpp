// GoogleTest main for Kiln's tests: MPI initialised, full output from rank 0
// (failures only from the others),
// and a test fails on every rank if it failed on any (the exit code is reduced).
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_GlobalMPISession.hpp>
#include <gtest/gtest.h>

int main(int argc, char **argv)
{
  Teuchos::GlobalMPISession session(&argc, &argv, nullptr);
  ::testing::InitGoogleTest(&argc, argv);
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  if (comm->getRank() != 0)
    GTEST_FLAG_SET(brief, true); // other ranks print their failures only
  const int local = RUN_ALL_TESTS();
  int global = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, local, Teuchos::outArg(global));
  if (global != 0 && local == 0 && comm->getRank() == 0)
    std::cout << "a test failed on another rank\n";
  return global;
}
