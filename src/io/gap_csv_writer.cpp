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
    : comm_(comm), base_(base_path), gap_(std::make_unique<internal::GapSurface>(mesh)),
      gather_(std::make_unique<internal::RowGather>(comm, owned_nodes, mesh.n_nodes())),
      step_(first_step)
{
}

GapCsvWriter::~GapCsvWriter() = default;

std::string GapCsvWriter::path(const int step) const
{
  char number[16];
  std::snprintf(number, sizeof number, "%06d", step);
  return base_ + ".gap-" + number + ".csv";
}

void GapCsvWriter::begin_step(const double time, int, double)
{
  time_ = time;
  fields_.clear();
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
  const std::string file = path(step_);
  internal::run_on_rank_zero(
      comm_,
      [&]
      {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const auto value = [&](const char *field, const std::int64_t node)
        {
          const auto it = fields_.find(field);
          return it == fields_.end() ? nan : it->second[static_cast<std::size_t>(node)];
        };
        const std::string temporary = file + ".tmp";
        errno = 0;
        std::ofstream out(temporary, std::ios::trunc);
        out << "time [s],pair [-],x [m],y [m],z [m],s [m],t [m],gap_opening [m],"
               "contact_pressure [Pa],gap_heat_flux [W/m^2],contact_active [-],"
               "temperature_a [K],temperature_b [K]\n";
        const std::string time = history_number(time_);
        for (int p = 0; p < gap_->n_points(); ++p)
        {
          const std::int64_t a = gap_->node_a[p], b = gap_->node_b[p];
          out << time << "," << p;
          for (const double v :
               {gap_->points[p][0], gap_->points[p][1], gap_->points[p][2], gap_->s[p], gap_->t[p],
                value("gap_opening", a), value("contact_pressure", a), value("gap_heat_flux", a),
                value("contact_active", a), value("temperature", a), value("temperature", b)})
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
  fields_.clear();
  ++step_;
}
} // namespace kiln
