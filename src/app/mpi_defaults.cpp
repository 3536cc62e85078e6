#include "app/mpi_defaults.hpp"

#include <cstring>

namespace kiln
{
std::vector<std::pair<std::string, std::string>>
open_mpi_defaults(const std::function<const char *(const char *)> &getenv)
{
  const char *world = getenv("OMPI_COMM_WORLD_SIZE");
  const char *local = getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  const bool by_hand = world == nullptr && getenv("PMI_SIZE") == nullptr;
  const bool one_node = world != nullptr && local != nullptr && std::strcmp(world, local) == 0;
  std::vector<std::pair<std::string, std::string>> chosen;
  const auto choose = [&](const char *name, const char *value)
  {
    if (getenv(name) == nullptr)
      chosen.emplace_back(name, value);
  };
  if (by_hand || one_node)
    choose("OMPI_MCA_pml", "ob1");
  if (by_hand)
    choose("OMPI_MCA_ess_singleton_isolated", "1");
  // OMPIO's "lockedfile" shared-file-pointer component, queried at every MPI_File_open,
  // sprintf()s the file's path and a suffix into a 256-byte buffer (Open MPI 4.1): a results
  // path of about 230 bytes aborted the run in glibc's overflow check. Kiln uses no shared
  // file pointer; the other components ("sm", "individual") allocate their names.
  choose("OMPI_MCA_sharedfp", "^lockedfile");
  return chosen;
}
} // namespace kiln
