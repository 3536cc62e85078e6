// Tests app/mpi_defaults: the Open MPI settings Kiln chooses before MPI starts, for a run by
// hand, under mpirun on one node and on several, and never over the user's.
#include "app/mpi_defaults.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>
#include <string>

namespace
{
using Chosen = std::vector<std::pair<std::string, std::string>>;
using testing::ElementsAre;
using testing::IsEmpty;
using testing::Pair;

/// open_mpi_defaults() in the environment `env`.
Chosen chosen_in(const std::map<std::string, std::string> &env)
{
  return kiln::open_mpi_defaults(
      [&env](const char *name) -> const char *
      {
        const auto it = env.find(name);
        return it == env.end() ? nullptr : it->second.c_str();
      });
}
} // namespace

TEST(OpenMpiDefaults, ByHandOb1AndNoDaemon)
{
  EXPECT_THAT(chosen_in({}),
              ElementsAre(Pair("OMPI_MCA_pml", "ob1"), Pair("OMPI_MCA_ess_singleton_isolated", "1"),
                          Pair("OMPI_MCA_sharedfp", "^lockedfile")));
}

TEST(OpenMpiDefaults, UnderMpirunOnOneNodeOb1)
{
  EXPECT_THAT(chosen_in({{"OMPI_COMM_WORLD_SIZE", "2"}, {"OMPI_COMM_WORLD_LOCAL_SIZE", "2"}}),
              ElementsAre(Pair("OMPI_MCA_pml", "ob1"), Pair("OMPI_MCA_sharedfp", "^lockedfile")));
}

TEST(OpenMpiDefaults, OnSeveralNodesOrUnderAnotherLauncherOnlyTheSharedFilePointer)
{
  EXPECT_THAT(chosen_in({{"OMPI_COMM_WORLD_SIZE", "4"}, {"OMPI_COMM_WORLD_LOCAL_SIZE", "2"}}),
              ElementsAre(Pair("OMPI_MCA_sharedfp", "^lockedfile")));
  EXPECT_THAT(chosen_in({{"OMPI_COMM_WORLD_SIZE", "4"}}),
              ElementsAre(Pair("OMPI_MCA_sharedfp", "^lockedfile")));
  EXPECT_THAT(chosen_in({{"PMI_SIZE", "2"}}),
              ElementsAre(Pair("OMPI_MCA_sharedfp", "^lockedfile")));
}

TEST(OpenMpiDefaults, NeverOverTheUsersChoice)
{
  EXPECT_THAT(chosen_in({{"OMPI_COMM_WORLD_SIZE", "2"},
                         {"OMPI_COMM_WORLD_LOCAL_SIZE", "2"},
                         {"OMPI_MCA_pml", "ucx"},
                         {"OMPI_MCA_sharedfp", "sm"}}),
              IsEmpty());
  EXPECT_THAT(chosen_in({{"OMPI_MCA_pml", "cm"}}),
              ElementsAre(Pair("OMPI_MCA_ess_singleton_isolated", "1"),
                          Pair("OMPI_MCA_sharedfp", "^lockedfile")));
  EXPECT_THAT(chosen_in({{"OMPI_MCA_ess_singleton_isolated", "0"}}),
              ElementsAre(Pair("OMPI_MCA_pml", "ob1"), Pair("OMPI_MCA_sharedfp", "^lockedfile")));
}
