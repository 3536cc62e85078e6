#pragma once
/// Open MPI settings Kiln chooses before MPI starts, where the user and the launcher chose
/// none: what Open MPI probes at start-up that a run on one machine does not use
/// (doc/user-guide.md, Start-up).
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace kiln
{
/// The environment variables (name, value) to set before MPI_Init, given the environment
/// as `getenv` shows it (nullptr for an unset name). Every rank of a run sees the same
/// launcher variables and so chooses alike.
/// - Run by hand (no OMPI_COMM_WORLD_SIZE, no PMI_SIZE): the point-to-point layer ob1
///   (no probing of UCX, OFI, PSM) and no orted daemon for the lone process.
/// - Under Open MPI's mpirun with every rank on one node (OMPI_COMM_WORLD_LOCAL_SIZE equal to
///   OMPI_COMM_WORLD_SIZE): ob1, whose shared-memory transport is what one node uses.
/// - Otherwise (several nodes, another launcher): nothing of the above; the site's choice stands.
/// - Always: OMPI_MCA_sharedfp = "^lockedfile" (that component overflows a 256-byte buffer
///   for a long file path at every MPI_File_open; Kiln uses no shared file pointer).
/// A variable the environment sets already is never in the list.
std::vector<std::pair<std::string, std::string>>
open_mpi_defaults(const std::function<const char *(const char *)> &getenv);
} // namespace kiln
