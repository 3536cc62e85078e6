#pragma once
/// Result files in tests: paths that no other test (or the same test at another rank count)
/// uses, removing them, reading a step of a Kiln HDF5 results file back (doc/output-format.md),
/// and the step attributes the writer tests write.
#include <Teuchos_Comm.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace kiln_test
{
/// A results path (without extension) in the temp folder, kiln_<name>_np<ranks>_<pid>: named
/// after the test, the number of ranks and rank 0's process id (collective).
std::string temporary_base(const std::string &name, const Teuchos::Comm<int> &comm);
/// Removes every file of the run, base.* (results, XDMF, checkpoints, gap and history CSV),
/// on rank 0 once every rank is done (collective).
void remove_results(const std::string &base, const Teuchos::Comm<int> &comm);

/// Output step `step` of an HDF5 results file (-1: the last): its time and one node or cell
/// field (rows in global id order, components interleaved; a symmetric tensor in Kiln's Voigt
/// order xx yy zz xy xz yz whatever order the file stores). Serial read on the calling rank;
/// a missing file, step or field is a test failure (and an empty result).
std::vector<double> read_step(const std::string &h5_path, const std::string &field, int step,
                              double &time);
/// The last output step of an HDF5 results file: see read_step.
std::vector<double> read_last_step(const std::string &h5_path, const std::string &field,
                                   double &time);

/// The values of the dataset `path` ("/history/time", "/gap/coordinates") as doubles, row after
/// row; a missing file or dataset is a test failure (and an empty result). Serial read.
std::vector<double> read_dataset(const std::string &h5_path, const std::string &path);
/// The text attribute `name` of the object `path` ("/" for the root), or "" (a test failure)
/// if it is missing.
std::string read_text_attribute(const std::string &h5_path, const std::string &path,
                                const std::string &name);

/// The numbers of column `name` of the CSV table `path` (a header "NAME [UNIT]" line, then
/// rows; "nan" is NaN); a missing file or column is a test failure.
std::vector<double> csv_column(const std::string &path, const std::string &name);

/// The attributes of output step `step` in the writer tests: time, dt, cycle.
inline double step_time(const int step)
{
  return 0.5 + 1.25 * step;
}
inline double step_dt(const int step)
{
  return 0.125 * (step + 1);
}
inline int step_cycle(const int step)
{
  return 10 * step + 3;
}

/// a == b, or both NaN (Kiln writes NaN where a field has no value).
inline bool same(const double a, const double b)
{
  return (std::isnan(a) && std::isnan(b)) || a == b;
}
} // namespace kiln_test
