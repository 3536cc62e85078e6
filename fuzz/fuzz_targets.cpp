#include "fuzz_targets.hpp"

#include "app/simulation.hpp"
#include "base/errors.hpp"
#include "io/input_reader.hpp"
#include "mesh/exodus_io.hpp"
#include "mesh/mesh_checks.hpp"

#include <Teuchos_DefaultSerialComm.hpp>

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

namespace kiln::fuzz
{
void input_deck(const std::uint8_t *data, const std::size_t size)
{
  const std::string xml(reinterpret_cast<const char *>(data), size);
  // A serial communicator: the constructor only asks for the rank; no MPI_Init needed.
  static const Teuchos::RCP<const Teuchos::Comm<int>> comm =
      Teuchos::rcp(new Teuchos::SerialComm<int>());
  try
  {
    const Simulation simulation(parse_input(xml, "fuzz.xml"), "fuzz.xml", comm);
  }
  catch (const InputError &)
  {
  }
}

void exodus_mesh(const std::uint8_t *data, const std::size_t size)
{
  // One scratch file per process, in memory where /dev/shm exists.
  static const std::string path =
      (access("/dev/shm", W_OK) == 0 ? std::string("/dev/shm/") : std::string("./")) +
      "kiln-fuzz-exodus-" + std::to_string(getpid()) + ".exo";
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char *>(data), static_cast<std::streamsize>(size));
  try
  {
    const Mesh mesh = read_exodus_mesh(path, 1.0);
    check_mesh(mesh, path);
  }
  catch (const InputError &)
  {
  }
  std::remove(path.c_str());
}
} // namespace kiln::fuzz
