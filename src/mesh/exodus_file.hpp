#pragma once
/// Private to src/mesh: an open Exodus file id that closes itself (exodus_reader.cpp,
/// exodus_writer.cpp).
#include <exodusII.h>

namespace kiln
{
namespace internal
{
/// Owns an open Exodus file id; closes it when the scope ends (also on a throw).
class ExodusFile
{
public:
  explicit ExodusFile(const int id) : id_(id) {}
  ~ExodusFile()
  {
    if (id_ >= 0)
      ex_close(id_);
  }
  ExodusFile(const ExodusFile &) = delete;
  ExodusFile &operator=(const ExodusFile &) = delete;
  int id() const { return id_; }
  /// Closes now; returns the Exodus return code (< 0: the file may not be complete).
  int close()
  {
    const int status = ex_close(id_);
    id_ = -1;
    return status;
  }

private:
  int id_;
};
} // namespace internal
} // namespace kiln
