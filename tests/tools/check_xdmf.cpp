// kiln_check_xdmf: checks that an XDMF file and the HDF5 data it refers to agree
// (see tests/cmake/xdmf_check.hpp). Usage: check_xdmf FILE.xmf; prints OK and exits 0,
// or prints the problem and exits 1.
#include "cmake/xdmf_check.hpp"

#include <iostream>

int main(int argc, char **argv)
{
  if (argc != 2)
  {
    std::cerr << "usage: " << argv[0] << " FILE.xmf\n";
    return 1;
  }
  const std::string problem = kiln::check_xdmf(argv[1]);
  if (!problem.empty())
  {
    std::cout << problem << "\n";
    return 1;
  }
  std::cout << "OK\n";
  return 0;
}
