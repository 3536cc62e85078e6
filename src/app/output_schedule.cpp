#include "app/output_schedule.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"

#include <Teuchos_Array.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <filesystem>
#include <ios>

#include <unistd.h>

namespace kiln
{
namespace internal
{
namespace
{
/// The most interval outputs a run may ask for (each is a stop time the steps land on).
constexpr double max_interval_outputs = 100000;

bool same_output_time(const double a, const double b)
{
  return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b));
}
} // namespace
std::size_t first_non_utf8_byte(const std::string &text)
{
  const auto byte = [&](const std::size_t i) { return static_cast<unsigned char>(text[i]); };
  for (std::size_t i = 0; i < text.size();)
  {
    const unsigned char c = byte(i);
    const std::size_t length = c < 0x80           ? 1
                               : (c >> 5) == 0x6  ? 2
                               : (c >> 4) == 0xE  ? 3
                               : (c >> 3) == 0x1E ? 4
                                                  : 0;
    if (length == 0 || i + length > text.size() || (length == 2 && c < 0xC2))
      return i;
    for (std::size_t k = 1; k < length; ++k)
      if ((byte(i + k) >> 6) != 0x2)
        return i;
    i += length;
  }
  return std::string::npos;
}
} // namespace internal

Teuchos::ParameterList OutputSchedule::valid_parameters()
{
  Teuchos::ParameterList p("Output");
  p.set("File Base", "",
        "path of the results without extension, a file name (not a folder): BASE.h5 and "
        "BASE.xmf, or BASE.exo, are written (see Format), with BASE.history.csv and "
        "BASE.gap-NNNNNN.csv beside them; the default \"\" means results/<input file name "
        "without .xml>");
  p.set("Format", "HDF5",
        "\"HDF5\": BASE.h5 with BASE.xmf for ParaView; \"Exodus\": BASE.exo (Exodus II, named "
        "variables, blocks, side sets and node sets; written by rank 0); \"HDF5 and Exodus\": "
        "both (doc/output-format.md)",
        choice_validator({"HDF5", "Exodus", "HDF5 and Exodus"}));
  p.set("Times", Teuchos::Array<double>(1, 0.0),
        "output times, at least one, increasing, >= 0 [s]: the steps land on each and the state "
        "is written; the run starts at t = 0 (always written) and ends at the last. The default "
        "{0} is the state at t = 0 alone (a steady solve, or the equilibrium of Physics = "
        "\"Elasticity\"); a transient run with a temperature must give them");
  p.set("Every Steps", 0,
        "also write the state after every this many accepted time steps; 0: not by steps [count]",
        nonnegative_int_validator());
  p.set("Interval", 0.0,
        "also write the state at every multiple of this time up to the end (the steps land on "
        "them); 0: not by interval [s]",
        nonnegative_double_validator());
  return p;
}

OutputSchedule::OutputSchedule(const Teuchos::ParameterList &p, const std::string &input_path,
                               const Teuchos::Comm<int> &comm)
    : base_(p.get<std::string>("File Base")), format_(p.get<std::string>("Format")),
      every_steps_(p.get<int>("Every Steps")), interval_(p.get<double>("Interval"))
{
  const std::string where = input_path;
  const auto &times = p.get<Teuchos::Array<double>>("Times");
  KILN_CHECK_INPUT(!times.empty(), parameter_path(where, "Kiln/Output", "Times"),
                   "is empty; give at least one output time (the last is the end of the run), "
                   "e.g. value=\"{0, 100}\"");
  for (int i = 0; i < times.size(); ++i)
    KILN_CHECK_INPUT(times[i] >= 0.0 && (i == 0 || times[i] > times[i - 1]),
                     parameter_path(where, "Kiln/Output", "Times"),
                     "output times must be >= 0 and increasing; entry " << i + 1 << " is "
                                                                        << times[i]);
  times_.assign(times.begin(), times.end());
  KILN_CHECK_INPUT(interval_ == 0.0 || end_time() / interval_ <= internal::max_interval_outputs,
                   parameter_path(where, "Kiln/Output", "Interval"),
                   "= " << interval_ << " s gives " << std::floor(end_time() / interval_)
                        << " output times up to the end, " << end_time() << " s; at most "
                        << internal::max_interval_outputs
                        << " are allowed: give a larger interval");

  const std::string base_where = parameter_path(where, "Kiln/Output", "File Base");
  KILN_CHECK_INPUT(base_.empty() || base_.back() != '/', base_where,
                   "= \"" << base_
                          << "\" ends in '/', so it names a folder; give the results' path "
                             "without extension, a file name in that folder, e.g. \""
                          << base_ << "run\" for " << base_ << "run.h5");
  if (base_.empty())
    base_ = "results/" + std::filesystem::path(input_path).stem().string();
  check_file_name(base_where, input_path);
  std::error_code ignored;
  const bool is_folder = comm.getRank() == 0 && std::filesystem::is_directory(base_, ignored);
  check_collectively(comm, !is_folder, base_where,
                     "= \"" + base_ +
                         "\" is an existing folder; File Base is the results' path without "
                         "extension, a file name: give one inside it, e.g. \"" +
                         base_ + "/run\" for " + base_ + "/run.h5");
}

void OutputSchedule::check_file_name(const std::string &base_where,
                                     const std::string &input_path) const
{
  const std::string name = std::filesystem::path(base_).filename().string();
  const std::string source =
      base_where + " = \"" + base_ + "\"" +
      (base_.rfind("results/", 0) == 0 && name == std::filesystem::path(input_path).stem().string()
           ? " (the default, from the input's name)"
           : "");
  // The longest name Kiln writes beside BASE: BASE.checkpoint-NNNNNN.h5.tmp.
  const std::string longest = ".checkpoint-000000.h5.tmp";
  const std::filesystem::path folder = std::filesystem::path(base_).parent_path();
  long limit = ::pathconf(folder.empty() ? "." : folder.c_str(), _PC_NAME_MAX);
  if (limit <= 0)
    limit = NAME_MAX;
  KILN_CHECK_INPUT(name.size() + longest.size() <= static_cast<std::size_t>(limit), source,
                   "the file name is " << name.size() << " bytes; Kiln writes names up to "
                                       << longest.size() << " bytes longer (" << longest
                                       << "), and this file system allows " << limit
                                       << " bytes per name: give Kiln/Output/\"File Base\" a "
                                          "name of at most "
                                       << limit - static_cast<long>(longest.size()) << " bytes");
  const std::size_t bad = internal::first_non_utf8_byte(name);
  KILN_CHECK_INPUT(!writes_hdf5() || bad == std::string::npos, source,
                   "the file name holds the byte 0x"
                       << std::hex << static_cast<int>(static_cast<unsigned char>(name[bad]))
                       << std::dec << " at position " << bad + 1
                       << ", which is not UTF-8 (a Latin-1 name?): the XDMF index, UTF-8 XML, "
                          "could not name the results for ParaView. Give Kiln/Output/\"File "
                          "Base\" a name in ASCII or UTF-8 (or rename the input)");
}

std::string OutputSchedule::results_files(const bool with_index) const
{
  std::string files;
  if (writes_hdf5())
    files = base_ + ".h5" + (with_index ? " and " + base_ + ".xmf" : "");
  if (writes_exodus())
    files += (files.empty() ? "" : " and ") + base_ + ".exo";
  return files;
}

std::vector<double> OutputSchedule::stop_times(const double start, const bool include_start) const
{
  std::vector<double> all(times_.begin(), times_.end());
  all.push_back(0.0);
  if (interval_ > 0.0)
    for (int k = 1; k * interval_ <= end_time() * (1.0 + 1e-12); ++k)
      all.push_back(std::min(k * interval_, end_time()));
  std::sort(all.begin(), all.end());
  std::vector<double> stops;
  for (const double t : all)
  {
    const bool at_start = internal::same_output_time(t, start);
    if ((t < start && !at_start) || (at_start && !include_start))
      continue;
    if (stops.empty() || !internal::same_output_time(t, stops.back()))
      stops.push_back(t);
  }
  return stops;
}

bool OutputSchedule::due_at_time(const double t) const
{
  if (t == 0.0 || std::any_of(times_.begin(), times_.end(),
                              [t](const double o) { return internal::same_output_time(o, t); }))
    return true;
  if (interval_ <= 0.0 || t > end_time() * (1.0 + 1e-12))
    return false;
  const double k = std::round(t / interval_);
  return k >= 1.0 && internal::same_output_time(k * interval_, t);
}
} // namespace kiln
