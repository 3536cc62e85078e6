#include "base/log.hpp"

#include <Teuchos_oblackholestream.hpp>

#include <iostream>

namespace kiln
{
Teuchos::RCP<Teuchos::FancyOStream> rank0_stream(const Teuchos::Comm<int> &comm)
{
  static Teuchos::oblackholestream black_hole;
  std::ostream &target = comm.getRank() == 0 ? std::cout : static_cast<std::ostream &>(black_hole);
  return Teuchos::fancyOStream(Teuchos::rcpFromRef(target));
}
} // namespace kiln
