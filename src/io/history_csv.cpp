#include "io/history_csv.hpp"

#include "base/errors.hpp"
#include "io/collective_checks.hpp"
#include "io/write_room.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <utility>

namespace kiln
{
namespace internal
{
namespace
{
/// "step [-],time [s],...", or without the units as Kiln wrote it before changelog 0032.
std::string header_line(const std::vector<HistoryColumn> &columns, const bool units = true)
{
  std::string line;
  for (const HistoryColumn &c : columns)
    line += (line.empty() ? "" : ",") + c.name + (units ? " [" + c.unit + "]" : "");
  return line;
}

std::string row_line(const std::vector<double> &row)
{
  std::string line;
  for (std::size_t i = 0; i < row.size(); ++i)
    line += (i == 0 ? "" : ",") + history_number(row[i]);
  return line;
}

/// The values of a CSV line, or false if it has another number of values or a bad one.
bool parse_row(const std::string &line, const std::size_t n_columns, std::vector<double> &row)
{
  row.clear();
  std::istringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ','))
  {
    char *end = nullptr;
    const double value = std::strtod(cell.c_str(), &end);
    if (cell.empty() || end != cell.c_str() + cell.size())
      return false;
    row.push_back(value);
  }
  return row.size() == n_columns;
}
} // namespace

/// A history file as read back: its rows up to the first line that cannot be read.
struct HistoryRows
{
  bool opened = false;
  bool known_columns = false; ///< the header of this Kiln (or of one before changelog 0032)
  bool cut_short = false;     ///< a line that cannot be read ended the rows
  std::vector<std::vector<double>> rows;
};

/// The history at `path`, if it has `columns`.
HistoryRows read_history(const std::string &path, const std::vector<HistoryColumn> &columns)
{
  HistoryRows result;
  std::ifstream in(path);
  std::string line;
  result.opened = static_cast<bool>(in);
  result.known_columns = result.opened && std::getline(in, line) &&
                         (line == header_line(columns) || line == header_line(columns, false));
  std::vector<double> row;
  while (result.known_columns && std::getline(in, line))
  {
    if (!parse_row(line, columns.size(), row))
    {
      result.cut_short = true;
      break;
    }
    result.rows.push_back(row);
  }
  return result;
}
} // namespace internal

const std::vector<HistoryColumn> &history_columns()
{
  static const std::vector<HistoryColumn> columns = {
      {"step", "-", "accepted time steps so far (0: the start of the run)"},
      {"time", "s", "simulated time"},
      {"dt", "s", "the step that led here (0 at the start)"},
      {"newton_iterations", "-", "Newton iterations of this step"},
      {"linear_iterations", "-", "linear (Krylov) iterations of this step"},
      {"T_min", "K", "lowest nodal temperature"},
      {"T_max", "K", "highest nodal temperature"},
      {"T_mean", "K", "volume average of the temperature"},
      {"thermal_energy", "J",
       "integral of H(T) = ∫ rho c dT (rho c T) over the body; its change is the heat gained"},
      {"max_displacement", "m", "largest nodal |u|"},
      {"min_gap", "m", "smallest gap opening over the gap pairs (negative: penetration)"},
      {"max_gap", "m", "largest gap opening over the gap pairs"},
      {"active_pairs", "-", "gap pairs in contact"},
      {"contact_area", "m^2", "area of the gap pairs in contact"},
      {"normal_force", "N", "normal force across the gap, compression > 0"},
      {"wall_time", "s", "wall-clock time since this run (or its restart) started"}};
  return columns;
}

std::vector<std::string> gap_history_columns(const int id)
{
  const std::string suffix = "_gap" + std::to_string(id);
  return {"min_gap" + suffix,      "max_gap" + suffix,      "active_pairs" + suffix,
          "contact_area" + suffix, "normal_force" + suffix, "gap_heat_flow" + suffix};
}

std::vector<std::string> pair_history_columns(const std::string &pair)
{
  return {"normal_force_" + pair, "contact_area_" + pair, "heat_flow_" + pair};
}

std::vector<HistoryColumn> history_columns(const std::vector<int> &gap_side_sets,
                                           const std::vector<std::string> &pairs)
{
  std::vector<HistoryColumn> columns = history_columns();
  if (gap_side_sets.size() >= 2)
    for (const int id : gap_side_sets)
    {
      const std::vector<std::string> names = gap_history_columns(id);
      const std::string of = " of gap side set " + std::to_string(id);
      columns.push_back({names[0], "m", "smallest gap opening over the pairs" + of});
      columns.push_back({names[1], "m", "largest gap opening over the pairs" + of});
      columns.push_back({names[2], "-", "pairs in contact" + of});
      columns.push_back({names[3], "m^2", "area of the pairs in contact" + of});
      columns.push_back({names[4], "N", "normal force across the gap" + of + ", compression > 0"});
      columns.push_back({names[5], "W", "heat across the gap" + of + " from side a to side b"});
    }
  for (const std::string &pair : pairs)
  {
    const std::vector<std::string> names = pair_history_columns(pair);
    const std::string of = " of the contact pair \"" + pair + "\"";
    columns.push_back({names[0], "N", "normal force sum_j D_jj P_j" + of + ", compression > 0"});
    columns.push_back({names[1], "m^2", "area in contact sum_(j active) D_jj" + of});
    columns.push_back({names[2], "W",
                       "heat across the gap" + of +
                           " from the secondary to the primary side (nan without Heat Transfer)"});
  }
  return columns;
}

std::string history_number(const double value)
{
  if (std::isnan(value))
    return "nan";
  char text[64];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

HistoryCsv::HistoryCsv(const MPI_Comm comm, const std::string &path,
                       std::vector<HistoryColumn> columns)
    : comm_(comm), path_(path), columns_(std::move(columns)),
      kept_end_(-std::numeric_limits<double>::infinity())
{
  start({});
}

HistoryCsv::HistoryCsv(const MPI_Comm comm, const std::string &path, const int step,
                       std::vector<HistoryColumn> columns, const std::string &running_path)
    : comm_(comm), path_(path), columns_(std::move(columns)),
      kept_end_(-std::numeric_limits<double>::infinity())
{
  int rank = 0;
  MPI_Comm_rank(comm_, &rank);
  std::vector<double> flat;
  int running = 0;
  if (rank == 0)
  {
    std::error_code ignored;
    const bool cut_off = !running_path.empty() && std::filesystem::exists(running_path, ignored);
    const std::string source = cut_off ? running_path : path_;
    const internal::HistoryRows earlier = internal::read_history(source, columns_);
    bool later = false; // rows after `step` in the file continued
    if (!earlier.opened)
      warning_ = source +
                 " (the earlier run's history) is missing; the history starts at the "
                 "restart, step " +
                 std::to_string(step);
    else if (!earlier.known_columns)
    {
      std::filesystem::rename(source, source + ".old", ignored);
      warning_ = source + " has other columns than this Kiln writes; it is kept as " + source +
                 ".old and the history starts at the restart, step " + std::to_string(step);
    }
    else
    {
      int last = -1;
      for (const std::vector<double> &row : earlier.rows)
      {
        if (row[0] > step)
        {
          later = true;
          break;
        }
        last = static_cast<int>(row[0]);
        flat.insert(flat.end(), row.begin(), row.end());
      }
      if (!later && earlier.cut_short)
        warning_ = source + ": a line after step " + std::to_string(last) +
                   " cannot be read; the rows from there are dropped";
      else if (last < step)
        warning_ = source + " ends at step " + std::to_string(last) + ", before the restart at " +
                   std::to_string(step) + "; the rows in between are missing";
    }
    // The earlier history stays whole while this run has not passed it.
    if (!running_path.empty() && (cut_off || later))
    {
      running = 1;
      const internal::HistoryRows complete =
          cut_off ? internal::read_history(path_, columns_) : earlier;
      if (complete.known_columns && !complete.rows.empty())
        kept_end_ = complete.rows.back()[1]; // the column "time"
    }
  }
  MPI_Bcast(&running, 1, MPI_INT, 0, comm_);
  MPI_Bcast(&kept_end_, 1, MPI_DOUBLE, 0, comm_);
  running_ = running == 1;
  if (running_)
    path_ = running_path;
  // Every rank gets the warning and the kept rows (the HDF5 history is written collectively).
  int length = static_cast<int>(warning_.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, comm_);
  warning_.resize(static_cast<std::size_t>(length));
  MPI_Bcast(warning_.data(), length, MPI_CHAR, 0, comm_);
  long long n_values = static_cast<long long>(flat.size());
  MPI_Bcast(&n_values, 1, MPI_LONG_LONG, 0, comm_);
  flat.resize(static_cast<std::size_t>(n_values));
  MPI_Bcast(flat.data(), static_cast<int>(n_values), MPI_DOUBLE, 0, comm_);
  const std::size_t n_columns = columns_.size();
  for (std::size_t i = 0; i < flat.size(); i += n_columns)
    kept_.emplace_back(flat.begin() + static_cast<std::ptrdiff_t>(i),
                       flat.begin() + static_cast<std::ptrdiff_t>(i + n_columns));
  start(kept_);
}

void HistoryCsv::start(const std::vector<std::vector<double>> &rows)
{
  internal::run_on_rank_zero(
      comm_,
      [&]
      {
        const std::string temporary = path_ + ".tmp";
        errno = 0;
        std::ofstream out(temporary, std::ios::trunc);
        out << internal::header_line(columns_) << "\n";
        for (const auto &row : rows)
          out << internal::row_line(row) << "\n";
        out.close();
        const int error = errno;
        const bool ok = out && std::rename(temporary.c_str(), path_.c_str()) == 0;
        if (!ok)
          std::remove(temporary.c_str());
        internal::check_text_write(static_cast<bool>(out), error, path_, "the time history");
        KILN_CHECK_INPUT(ok, path_,
                         "cannot write the time history; check that the folder is "
                         "writable and the disk is not full");
      });
}

void HistoryCsv::finish(const std::string &final_path)
{
  if (!running_ || final_path == path_)
    return;
  internal::run_on_rank_zero(comm_,
                             [&]
                             {
                               KILN_CHECK_INPUT(std::rename(path_.c_str(), final_path.c_str()) == 0,
                                                final_path,
                                                "cannot rename " << path_
                                                                 << " to its final name; check the "
                                                                    "folder's permissions");
                             });
  path_ = final_path;
  running_ = false;
}

void HistoryCsv::append(const std::vector<double> &row)
{
  internal::run_on_rank_zero(comm_,
                             [&]
                             {
                               std::error_code ignored;
                               const std::uintmax_t before =
                                   std::filesystem::file_size(path_, ignored);
                               errno = 0;
                               std::ofstream out(path_, std::ios::app);
                               out << internal::row_line(row) << "\n";
                               out.close();
                               const int error = errno;
                               // A row cut short goes: the rows before stay a complete table.
                               if (!out && !ignored)
                                 std::filesystem::resize_file(path_, before, ignored);
                               internal::check_text_write(static_cast<bool>(out), error, path_,
                                                          "a row of the time history");
                               KILN_CHECK_INPUT(static_cast<bool>(out), path_,
                                                "cannot append to the time history; check that "
                                                "the disk is not full");
                             });
}
} // namespace kiln
