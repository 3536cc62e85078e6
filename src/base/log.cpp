#include "base/log.hpp"

#include <Teuchos_oblackholestream.hpp>
#include <mpi.h>

#include <iostream>
#include <mutex>
#include <set>
#include <streambuf>

namespace kiln
{
namespace internal
{
namespace
{
/// Forwards every character to std::cout (looked up at each write, so a temporary
/// std::cout.rdbuf() swap still applies) and flushes std::cout at each '\n'.
class LineFlushingBuffer final : public std::streambuf
{
protected:
  int_type overflow(const int_type c) override
  {
    if (traits_type::eq_int_type(c, traits_type::eof()))
      return traits_type::not_eof(c);
    const char ch = traits_type::to_char_type(c);
    std::cout.put(ch);
    if (ch == '\n')
      std::cout.flush();
    return std::cout ? c : traits_type::eof();
  }
  std::streamsize xsputn(const char *s, const std::streamsize n) override
  {
    std::cout.write(s, n);
    if (std::char_traits<char>::find(s, static_cast<std::size_t>(n), '\n') != nullptr)
      std::cout.flush();
    return std::cout ? n : 0;
  }
  int sync() override
  {
    std::cout.flush();
    return std::cout ? 0 : -1;
  }
};

int world_rank()
{
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  int rank = 0;
  if (initialized && !finalized)
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}
} // namespace
} // namespace internal

Teuchos::RCP<Teuchos::FancyOStream> rank0_stream(const Teuchos::Comm<int> &comm)
{
  static Teuchos::oblackholestream black_hole;
  static internal::LineFlushingBuffer line_flushing_buffer;
  static std::ostream line_flushing_cout(&line_flushing_buffer);
  std::ostream &target =
      comm.getRank() == 0 ? line_flushing_cout : static_cast<std::ostream &>(black_hole);
  return Teuchos::fancyOStream(Teuchos::rcpFromRef(target));
}

bool warn_once(const std::string &message)
{
  static std::mutex mutex;
  static std::set<std::string> printed;
  const std::lock_guard<std::mutex> lock(mutex);
  if (!printed.insert(message).second || internal::world_rank() != 0)
    return false;
  std::cout << "kiln: warning: " << message << std::endl;
  return true;
}
} // namespace kiln
