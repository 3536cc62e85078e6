// Tests app/results_lock: a second lock on the same file is refused on every rank with a
// message naming the holder's process and the lock file; the file is removed when the lock
// is released, and can then be locked again; a lock file left by a killed run (not locked)
// does not stop a new run.
// KILN_TEST_NP: 1 2
#include "app/results_lock.hpp"

#include "support/parameter_lists.hpp"
#include "support/results_files.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <unistd.h>

using kiln_test::input_error_message;
using testing::HasSubstr;

TEST(ResultsLock, SecondLockRefusedNamingTheHolder)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string path = kiln_test::temporary_base("results_lock", *comm) + ".lock";
  int pid = static_cast<int>(getpid());
  Teuchos::broadcast(*comm, 0, Teuchos::outArg(pid)); // rank 0 holds it
  {
    const kiln::ResultsLock first(path, *comm);
    if (comm->getRank() == 0)
    {
      EXPECT_TRUE(std::filesystem::exists(path));
    }
    // Another open file description of the same file: refused as another process would be.
    const std::string message = input_error_message([&] { kiln::ResultsLock second(path, *comm); });
    EXPECT_THAT(message,
                HasSubstr(path + ": another Kiln run (pid " + std::to_string(pid) + " on "));
    EXPECT_THAT(message, HasSubstr(") is writing results with this File Base and holds this "
                                   "lock file; wait for it to end, or give this run another "
                                   "Kiln/Output/\"File Base\""));
  }
  comm->barrier();
  EXPECT_FALSE(std::filesystem::exists(path)) << "released, the lock file is removed";
  comm->barrier(); // every rank has looked before rank 0 creates it again
  {
    const kiln::ResultsLock again(path, *comm);
    EXPECT_EQ(again.path(), path);
  }
  comm->barrier();
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(ResultsLock, StaleLockFileIsTaken)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string path = kiln_test::temporary_base("results_lock_stale", *comm) + ".lock";
  if (comm->getRank() == 0)
    std::ofstream(path) << "pid 1 on a host that crashed\n";
  comm->barrier();
  EXPECT_EQ(input_error_message([&] { kiln::ResultsLock lock(path, *comm); }), "");
  comm->barrier();
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(ResultsLock, UncreatableLockFile)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  EXPECT_THAT(input_error_message([&] { kiln::ResultsLock lock("/proc/no-such/x.lock", *comm); }),
              HasSubstr("/proc/no-such/x.lock: cannot create the lock file (No such file or "
                        "directory); check that the folder \"/proc/no-such/\" exists and is "
                        "writable"));
}
