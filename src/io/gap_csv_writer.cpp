#include "io/gap_csv_writer.hpp"

#include "base/errors.hpp"
#include "io/collective_checks.hpp"
#include "io/gap_surface.hpp"
#include "io/history_csv.hpp"
#include "io/row_gather.hpp"
#include "io/write_room.hpp"

#include <cerrno>
#include <cstdio>
#include <fstream>
#include <limits>

namespace kiln
{
GapCsvWriter::GapCsvWriter(const MPI_Comm comm, const std::string &base_path, const Mesh &mesh,
                           const std::vector<int> &owned_nodes, const int first_step)
    : comm_(comm), base_(base_path),
      gather_(std::make_unique<internal::RowGather>(comm, owned_nodes, mesh.n_nodes())),
      step_(first_step)
{
  for (int g = 0; g < static_cast<int>(mesh.gap_side_sets.size()); ++g)
  {
    names_.push_back(mesh.gap_name(g));
    gaps_.push_back(std::make_unique<internal::GapSurface>(mesh, g));
  }
  for (const ContactPairSurface &pair : mesh.contact_pairs)
    for (const SideSet &side_set : mesh.side_sets)
      if (side_set.id == pair.secondary_side_set)
      {
        names_.push_back(pair.surface_name());
        gaps_.push_back(std::make_unique<internal::GapSurface>(mesh, side_set));
      }
}

GapCsvWriter::~GapCsvWriter() = default;

std::string GapCsvWriter::path(const int step, const int gap) const
{
  char number[16];
  std::snprintf(number, sizeof number, "%06d", step);
  return base_ + "." + (names_.empty() ? std::string("gap") : names_[gap]) + "-" + number + ".csv";
}

void GapCsvWriter::begin_step(const double time, int, double)
{
  time_ = time;
  fields_.clear();
  pair_fields_.clear();
}

void GapCsvWriter::write_gap_field(const std::string &name, const std::vector<double> &per_pair)
{
  pair_fields_[name] = per_pair;
}

void GapCsvWriter::write_node_field(const std::string &name, const int n_components,
                                    const std::vector<double> &values)
{
  static const char *kept[] = {"gap_opening", "contact_pressure", "gap_heat_flux", "contact_active",
                               "temperature"};
  for (const char *k : kept)
    if (name == k && n_components == 1)
      fields_[name] = gather_->to_rank_zero(values, 1);
}

void GapCsvWriter::end_step()
{
  for (int g = 0; g < n_gaps(); ++g)
    write_table(*gaps_[g], path(step_, g));
  fields_.clear();
  pair_fields_.clear();
  ++step_;
}

void GapCsvWriter::write_table(const internal::GapSurface &gap, const std::string &file) const
{
  internal::run_on_rank_zero(
      comm_,
      [&]
      {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        // The pair's value where write_gap_field() gave it, else its node's (none: NaN).
        const auto value = [&](const char *field, const int point, const std::int64_t node)
        {
          if (const auto it = pair_fields_.find(field);
              it != pair_fields_.end() && gap.pair[point] >= 0)
            return it->second[static_cast<std::size_t>(gap.pair[point])];
          const auto it = fields_.find(field);
          return it == fields_.end() || node < 0 ? nan : it->second[static_cast<std::size_t>(node)];
        };
        const std::string temporary = file + ".tmp";
        errno = 0;
        std::ofstream out(temporary, std::ios::trunc);
        out << "time [s],pair [-],x [m],y [m],z [m],s [m],t [m],gap_opening [m],"
               "contact_pressure [Pa],gap_heat_flux [W/m^2],contact_active [-],"
               "temperature_a [K],temperature_b [K],area [m^2]\n";
        const std::string time = history_number(time_);
        for (int p = 0; p < gap.n_points(); ++p)
        {
          const std::int64_t a = gap.node_a[p], b = gap.node_b[p];
          out << time << "," << p;
          for (const double v :
               {gap.points[p][0], gap.points[p][1], gap.points[p][2], gap.s[p], gap.t[p],
                value("gap_opening", p, a), value("contact_pressure", p, a),
                value("gap_heat_flux", p, a), value("contact_active", p, a),
                value("temperature", p, a), value("temperature", p, b), gap.area[p]})
            out << "," << history_number(v);
          out << "\n";
        }
        out.close();
        const int error = errno;
        const bool ok = out && std::rename(temporary.c_str(), file.c_str()) == 0;
        if (!ok)
          std::remove(temporary.c_str());
        internal::check_text_write(static_cast<bool>(out), error, file, "the gap table");
        KILN_CHECK_INPUT(ok, file,
                         "cannot write the gap table; check that the folder is writable and the "
                         "disk is not full");
      });
}
} // namespace kiln
