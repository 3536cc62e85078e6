// Tests ExodusResultsWriter: a split box written from 1 or 2 ranks, read back with the
// Exodus library (names, times, values with NaN, blocks, side sets, node sets), each step on
// disk after end_step(), and the errors: misuse is an InternalError and a missing folder an
// InputError, on every rank.
// KILN_TEST_NP: 1 2
#include "io/exodus_results_writer.hpp"

#include "base/errors.hpp"
#include "io/history_csv.hpp"
#include "mesh/box_mesh_generator.hpp"
#include "mesh/exodus_io.hpp"
#include "mesh/gap_splitter.hpp"
#include "mesh/metis_partitioner.hpp"
#include "support/parallel.hpp"
#include "support/parameter_lists.hpp"
#include "support/results_files.hpp"

#include <Teuchos_Array.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_Tuple.hpp>
#include <exodusII.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <mpi.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace
{
using kiln::Mesh;
using kiln_test::rank_of;
using kiln_test::same;
using kiln_test::shared_test_folder;
using kiln_test::step_cycle;
using kiln_test::step_dt;
using kiln_test::step_time;
using testing::HasSubstr;

constexpr int n_steps = 2;
const double nan = std::numeric_limits<double>::quiet_NaN();

/// The contact box, 4 x 2 x 2 cells, split at side set 10; side set 1 named "left" and side
/// set 3 named "gap" (a clash with the gap's name).
Mesh split_box()
{
  Teuchos::ParameterList p = kiln::BoxMeshGenerator::valid_parameters();
  p.set("Cells", Teuchos::Array<int>(Teuchos::tuple(4, 2, 2)));
  p.set("Phi", 30.0);
  Mesh mesh = kiln::BoxMeshGenerator(p, "test/Box").generate();
  for (auto &set : mesh.side_sets)
  {
    if (set.id == 1)
      set.name = "left";
    if (set.id == 3)
      set.name = "gap";
  }
  kiln::split_gap(mesh, 10, "test");
  return mesh;
}

struct Ownership
{
  std::vector<int> cell_rank;
  std::vector<int> owned_cells;
  std::vector<int> owned_nodes;
};

Ownership make_ownership(const Mesh &mesh)
{
  const auto comm = Teuchos::DefaultComm<int>::getComm();
  Ownership o;
  o.cell_rank = kiln::partition_cells(mesh, *comm, "test");
  const std::vector<int> node_rank = kiln::node_owners(mesh, o.cell_rank);
  for (int c = 0; c < mesh.n_cells(); ++c)
    if (o.cell_rank[c] == comm->getRank())
      o.owned_cells.push_back(c);
  for (int n = 0; n < mesh.n_nodes(); ++n)
    if (node_rank[n] == comm->getRank())
      o.owned_nodes.push_back(n);
  return o;
}

// The field values, as functions of the step (step_time, step_dt, step_cycle), the global id
// and the coordinates.
double temperature(const int step, const int node, const kiln::Point &x)
{
  return 300.0 + x[0] + 10.0 * x[1] + 100.0 * x[2] + 1000.0 * step + 1e-3 * node;
}
double displacement(const int step, const int node, const int component)
{
  return 1e-3 * (step + 1) * node + 1e-6 * component;
}
/// NaN off the gap, as Kiln's gap fields.
double gap_opening(const Mesh &mesh, const int step, const int node)
{
  const bool on_gap =
      std::any_of(mesh.gap_pairs.begin(), mesh.gap_pairs.end(),
                  [&](const kiln::GapPair &p) { return p.node_a == node || p.node_b == node; });
  return on_gap ? 1e-5 * (step + 1) + 1e-8 * node : nan;
}
/// Component v (the written order xx yy zz xy yz xz) of cell c: 100 v + c + 0.5 step.
double stress(const int step, const int cell, const int v)
{
  if (cell == 3 && v == 2)
    return nan;
  return 100.0 * v + cell + 0.5 * step;
}

/// The history row of step s: its cycle, time and dt, then 10 s + column index.
std::vector<double> history_row(const int s)
{
  std::vector<double> row(kiln::history_columns().size());
  for (std::size_t k = 0; k < row.size(); ++k)
    row[k] = 10.0 * s + static_cast<double>(k);
  row[0] = step_cycle(s);
  row[1] = step_time(s);
  row[2] = step_dt(s);
  return row;
}

/// Step 0 comes as in a run: its history row, then the step. Step 1 as a continued run's
/// earlier step: the row of another step first, the step, then its own row (after the step).
void write_step(kiln::ExodusResultsWriter &writer, const Mesh &mesh, const Ownership &o,
                const int s)
{
  writer.write_history(history_row(0));
  writer.begin_step(step_time(s), step_cycle(s), step_dt(s));
  std::vector<double> t, u, g, sigma;
  for (const int n : o.owned_nodes)
  {
    t.push_back(temperature(s, n, mesh.coordinates[n]));
    for (int d = 0; d < 3; ++d)
      u.push_back(displacement(s, n, d));
    g.push_back(gap_opening(mesh, s, n));
  }
  for (const int c : o.owned_cells)
    for (int v = 0; v < 6; ++v)
      sigma.push_back(stress(s, c, v));
  // The second step writes the fields in another order: allowed.
  if (s == 0)
  {
    writer.write_node_field("temperature", 1, t);
    writer.write_node_field("displacement", 3, u);
    writer.write_cell_field("stress", 6, sigma);
    writer.write_node_field("gap_opening", 1, g);
  }
  else
  {
    writer.write_node_field("gap_opening", 1, g);
    writer.write_cell_field("stress", 6, sigma);
    writer.write_node_field("displacement", 3, u);
    writer.write_node_field("temperature", 1, t);
  }
  writer.end_step();
}

// ---- serial read-back (rank 0) ----

/// An Exodus file open for reading, names up to their stored length.
class ExodusReader
{
public:
  explicit ExodusReader(const std::string &path)
  {
    int comp_ws = sizeof(double), io_ws = 0;
    float version = 0.0F;
    id_ = ex_open(path.c_str(), EX_READ, &comp_ws, &io_ws, &version);
    if (id_ >= 0)
    {
      name_length_ = static_cast<int>(ex_inquire_int(id_, EX_INQ_DB_MAX_USED_NAME_LENGTH));
      ex_set_max_name_length(id_, name_length_);
    }
  }
  ~ExodusReader()
  {
    if (id_ >= 0)
      ex_close(id_);
  }
  ExodusReader(const ExodusReader &) = delete;
  ExodusReader &operator=(const ExodusReader &) = delete;
  int id() const { return id_; }

  /// Names of the n objects of a type (blocks, sets), or of its n variables.
  std::vector<std::string> names(const ex_entity_type type, const int n, const bool variables) const
  {
    std::vector<std::vector<char>> buffers(n, std::vector<char>(name_length_ + 1, '\0'));
    std::vector<char *> pointers;
    for (auto &b : buffers)
      pointers.push_back(b.data());
    const int status = variables ? ex_get_variable_names(id_, type, n, pointers.data())
                                 : ex_get_names(id_, type, pointers.data());
    EXPECT_GE(status, 0);
    std::vector<std::string> result;
    for (const auto &b : buffers)
      result.emplace_back(b.data());
    return result;
  }
  int n_variables(const ex_entity_type type) const
  {
    int n = 0;
    EXPECT_GE(ex_get_variable_param(id_, type, &n), 0);
    return n;
  }
  std::vector<double> variable(const int step, const ex_entity_type type, const int index,
                               const int object, const int n) const
  {
    std::vector<double> values(n);
    EXPECT_GE(ex_get_var(id_, step, type, index, object, n, values.data()), 0);
    return values;
  }

private:
  int id_ = -1;
  int name_length_ = 32;
};

using Names = std::vector<std::string>;

/// The nodes of a side set's faces, 1-based, increasing, each once (computed here, not with
/// the writer's helper).
std::vector<int> face_nodes(const Mesh &mesh, const kiln::SideSet &set)
{
  std::vector<int> nodes;
  for (int i = 0; i < set.n_sides(); ++i)
    for (int k = 0; k < 4; ++k)
      nodes.push_back(mesh.face_node(set.cells[i], set.faces[i], k) + 1);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

void check_mesh_records(const ExodusReader &file, const Mesh &mesh,
                        const std::vector<int> &cell_rank)
{
  const int exo = file.id();
  char title[MAX_LINE_LENGTH + 1] = {};
  int n_dim = 0, n_nodes = 0, n_elems = 0, n_blocks = 0, n_node_sets = 0, n_side_sets = 0;
  ASSERT_GE(
      ex_get_init(exo, title, &n_dim, &n_nodes, &n_elems, &n_blocks, &n_node_sets, &n_side_sets),
      0);
  EXPECT_STREQ(title, "Kiln results");
  EXPECT_EQ(n_dim, 3);
  ASSERT_EQ(n_nodes, mesh.n_nodes());
  ASSERT_EQ(n_nodes, 54); // 5 x 3 x 3 nodes + the 9 twins of the gap
  ASSERT_EQ(n_elems, mesh.n_cells());
  ASSERT_EQ(n_blocks, 2);
  ASSERT_EQ(n_side_sets, 7);
  ASSERT_EQ(n_node_sets, 7);

  std::vector<double> x(n_nodes), y(n_nodes), z(n_nodes);
  ASSERT_GE(ex_get_coord(exo, x.data(), y.data(), z.data()), 0);
  for (int n = 0; n < n_nodes; ++n)
    EXPECT_EQ((kiln::Point{x[n], y[n], z[n]}), mesh.coordinates[n]) << "node " << n;

  // Blocks: ids, names, connectivity, the cell_rank attribute; cells in increasing order.
  std::vector<int> block_ids(n_blocks);
  ASSERT_GE(ex_get_elem_blk_ids(exo, block_ids.data()), 0);
  EXPECT_EQ(block_ids, (std::vector<int>{1, 2}));
  EXPECT_EQ(file.names(EX_ELEM_BLOCK, n_blocks, false), (Names{"block_1", "block_2"}));
  for (const int id : block_ids)
  {
    std::vector<int> cells;
    for (int c = 0; c < mesh.n_cells(); ++c)
      if (mesh.block_id[c] == id)
        cells.push_back(c);
    char type[MAX_STR_LENGTH + 1] = {};
    int n_in_block = 0, n_per_elem = 0, n_attr = 0;
    ASSERT_GE(ex_get_elem_block(exo, id, type, &n_in_block, &n_per_elem, &n_attr), 0);
    EXPECT_STREQ(type, "HEX8");
    ASSERT_EQ(n_in_block, static_cast<int>(cells.size()));
    ASSERT_EQ(n_attr, 1);
    std::vector<int> conn(8 * cells.size());
    ASSERT_GE(ex_get_elem_conn(exo, id, conn.data()), 0);
    std::vector<double> attribute(cells.size());
    ASSERT_GE(ex_get_elem_attr(exo, id, attribute.data()), 0);
    for (std::size_t e = 0; e < cells.size(); ++e)
    {
      for (int k = 0; k < 8; ++k)
        EXPECT_EQ(conn[8 * e + k], mesh.cell_nodes(cells[e])[k] + 1) << "cell " << cells[e];
      EXPECT_EQ(attribute[e], cell_rank[cells[e]]) << "cell " << cells[e];
    }
    std::vector<char> attribute_name(64, '\0');
    char *attribute_names[] = {attribute_name.data()};
    ASSERT_GE(ex_get_attr_names(exo, EX_ELEM_BLOCK, id, attribute_names), 0);
    EXPECT_STREQ(attribute_name.data(), "cell_rank");
  }

  // Side sets and node sets: the same ids and names; the node sets hold the face nodes.
  // The box's own names, but where the test renamed them.
  const Names set_names = {"left", "x_max", "gap_3", "y_max", "z_min", "z_max", "gap"};
  std::vector<int> side_set_ids(n_side_sets), node_set_ids(n_node_sets);
  ASSERT_GE(ex_get_side_set_ids(exo, side_set_ids.data()), 0);
  ASSERT_GE(ex_get_node_set_ids(exo, node_set_ids.data()), 0);
  EXPECT_EQ(side_set_ids, (std::vector<int>{1, 2, 3, 4, 5, 6, 10}));
  EXPECT_EQ(node_set_ids, side_set_ids);
  EXPECT_EQ(file.names(EX_SIDE_SET, n_side_sets, false), set_names);
  EXPECT_EQ(file.names(EX_NODE_SET, n_node_sets, false), set_names);
  for (const auto &set : mesh.side_sets)
  {
    int n_in_set = 0, n_dist = 0;
    ASSERT_GE(ex_get_node_set_param(exo, set.id, &n_in_set, &n_dist), 0);
    std::vector<int> nodes(n_in_set);
    ASSERT_GE(ex_get_node_set(exo, set.id, nodes.data()), 0);
    EXPECT_EQ(nodes, face_nodes(mesh, set)) << "node set " << set.id;
    if (set.id == 10) // the gap from both sides: 3 x 3 nodes of side a and their 9 twins
    {
      EXPECT_EQ(n_in_set, 18);
    }
    else if (set.id == 1 || set.id == 2) // an end face, 3 x 3 nodes
    {
      EXPECT_EQ(n_in_set, 9);
    }
    ASSERT_GE(ex_get_side_set_param(exo, set.id, &n_in_set, &n_dist), 0);
    EXPECT_EQ(n_in_set, set.n_sides()) << "side set " << set.id;
  }

  // The records: QA by kiln, the coordinates in metres.
  ASSERT_EQ(ex_inquire_int(exo, EX_INQ_QA), 1);
  std::vector<std::vector<char>> qa(4, std::vector<char>(MAX_STR_LENGTH + 1, '\0'));
  char *qa_record[1][4] = {{qa[0].data(), qa[1].data(), qa[2].data(), qa[3].data()}};
  ASSERT_GE(ex_get_qa(exo, qa_record), 0);
  EXPECT_STREQ(qa[0].data(), "kiln");
  ASSERT_EQ(ex_inquire_int(exo, EX_INQ_INFO), 1);
  std::vector<char> info(MAX_LINE_LENGTH + 1, '\0');
  char *info_records[] = {info.data()};
  ASSERT_GE(ex_get_info(exo, info_records), 0);
  EXPECT_STREQ(info.data(), kiln::exodus_metres_record);
}

/// Checks the time steps 1..n_written and every value in them.
void check_steps(const ExodusReader &file, const Mesh &mesh, const int n_written)
{
  const int exo = file.id();
  ASSERT_EQ(ex_inquire_int(exo, EX_INQ_TIME), n_written);
  std::vector<double> times(n_written);
  ASSERT_GE(ex_get_all_times(exo, times.data()), 0);
  for (int s = 0; s < n_written; ++s)
    EXPECT_EQ(times[s], step_time(s));

  // The history columns, named as in the CSV.
  const auto &columns = kiln::history_columns();
  const int n_globals = static_cast<int>(columns.size());
  Names global_names;
  for (const auto &c : columns)
    global_names.push_back(c.name);
  ASSERT_EQ(file.n_variables(EX_GLOBAL), n_globals);
  EXPECT_EQ(file.names(EX_GLOBAL, n_globals, true), global_names);
  const Names node_variables = {"temperature", "displacement_x", "displacement_y", "displacement_z",
                                "gap_opening"};
  const Names cell_variables = {"stress_xx", "stress_yy", "stress_zz",
                                "stress_xy", "stress_yz", "stress_xz"};
  ASSERT_EQ(file.n_variables(EX_NODAL), 5);
  EXPECT_EQ(file.names(EX_NODAL, 5, true), node_variables);
  ASSERT_EQ(file.n_variables(EX_ELEM_BLOCK), 6);
  EXPECT_EQ(file.names(EX_ELEM_BLOCK, 6, true), cell_variables);
  std::vector<int> truth(2 * 6, 0);
  ASSERT_GE(ex_get_truth_table(exo, EX_ELEM_BLOCK, 2, 6, truth.data()), 0);
  EXPECT_EQ(truth, std::vector<int>(2 * 6, 1));

  const int n_nodes = mesh.n_nodes();
  for (int s = 0; s < n_written; ++s)
  {
    const int step = s + 1;
    EXPECT_EQ(file.variable(step, EX_GLOBAL, 1, 0, n_globals), history_row(s)) << "step " << s;

    const auto t = file.variable(step, EX_NODAL, 1, 1, n_nodes);
    const auto g = file.variable(step, EX_NODAL, 5, 1, n_nodes);
    int n_nan = 0;
    for (int n = 0; n < n_nodes; ++n)
    {
      EXPECT_EQ(t[n], temperature(s, n, mesh.coordinates[n])) << "step " << s << " node " << n;
      EXPECT_PRED2(same, g[n], gap_opening(mesh, s, n)) << "step " << s << " node " << n;
      n_nan += std::isnan(g[n]) ? 1 : 0;
    }
    EXPECT_EQ(n_nan, n_nodes - 18); // NaN everywhere but at the 9 pairs
    for (int d = 0; d < 3; ++d)
    {
      const auto u = file.variable(step, EX_NODAL, 2 + d, 1, n_nodes);
      for (int n = 0; n < n_nodes; ++n)
        EXPECT_EQ(u[n], displacement(s, n, d)) << "step " << s << " node " << n << " dir " << d;
    }
    // stress_xx yy zz xy yz xz hold the components in the order written.
    const int voigt[6] = {0, 1, 2, 3, 4, 5};
    for (const int id : {1, 2})
    {
      std::vector<int> cells;
      for (int c = 0; c < mesh.n_cells(); ++c)
        if (mesh.block_id[c] == id)
          cells.push_back(c);
      for (int k = 0; k < 6; ++k)
      {
        const auto values =
            file.variable(step, EX_ELEM_BLOCK, k + 1, id, static_cast<int>(cells.size()));
        for (std::size_t e = 0; e < cells.size(); ++e)
          EXPECT_PRED2(same, values[e], stress(s, cells[e], voigt[k]))
              << "step " << s << " " << cell_variables[k] << " cell " << cells[e];
      }
    }
  }
}
} // namespace

TEST(ExodusResultsWriter, VariableNamesAndTheirComponents)
{
  using W = kiln::ExodusResultsWriter;
  EXPECT_EQ(W::variable_names("temperature", 1), (Names{"temperature"}));
  EXPECT_EQ(W::variable_names("u", 3), (Names{"u_x", "u_y", "u_z"}));
  EXPECT_EQ(W::variable_names("s", 6), (Names{"s_xx", "s_yy", "s_zz", "s_xy", "s_yz", "s_xz"}));
  EXPECT_EQ(W::variable_names("q", 2), (Names{"q_0", "q_1"}));
  EXPECT_EQ(W::variable_components(6), (std::vector<int>{0, 1, 2, 3, 4, 5}));
  // A field of the catalog names its components.
  EXPECT_EQ(W::variable_names("principal_stress", 3),
            (Names{"principal_stress_1", "principal_stress_2", "principal_stress_3"}));
  EXPECT_EQ(W::variable_components(3), (std::vector<int>{0, 1, 2}));
}

TEST(ExodusResultsWriter, SplitBoxReadBackWithTheExodusLibrary)
{
  const MPI_Comm comm = MPI_COMM_WORLD;
  const Mesh mesh = split_box();
  const Ownership o = make_ownership(mesh);
  const std::string folder = shared_test_folder(comm, "exodus_results");
  const std::string base = folder + "/out";
  {
    kiln::ExodusResultsWriter writer(comm, base, mesh, o.owned_nodes, o.owned_cells, o.cell_rank);
    EXPECT_EQ(writer.exo_path(), base + ".running.exo");
    for (int s = 0; s < n_steps; ++s)
    {
      write_step(writer, mesh, o, s);
      if (s > 0)
      {
        // Before its row: step, time and dt, NaN for the rest; the row completes it.
        MPI_Barrier(comm);
        if (rank_of(comm) == 0)
        {
          const ExodusReader file(base + ".running.exo");
          const auto globals = file.variable(s + 1, EX_GLOBAL, 1, 0, 4);
          EXPECT_EQ(globals[0], step_cycle(s));
          EXPECT_EQ(globals[1], step_time(s));
          EXPECT_EQ(globals[2], step_dt(s));
          EXPECT_TRUE(std::isnan(globals[3]));
        }
        MPI_Barrier(comm);
        writer.write_history(history_row(s));
      }
      // The step is on disk while the writer is still open.
      MPI_Barrier(comm);
      if (rank_of(comm) == 0)
      {
        const ExodusReader file(base + ".running.exo");
        ASSERT_GE(file.id(), 0);
        check_steps(file, mesh, s + 1);
      }
      MPI_Barrier(comm);
    }
    writer.finish("complete");
    EXPECT_EQ(writer.exo_path(), base + ".exo");
  }
  if (rank_of(comm) == 0)
  {
    EXPECT_FALSE(std::filesystem::exists(base + ".running.exo"));
  }
  MPI_Barrier(comm);
  if (rank_of(comm) == 0)
  {
    const ExodusReader file(base + ".exo");
    ASSERT_GE(file.id(), 0);
    check_mesh_records(file, mesh, o.cell_rank);
    check_steps(file, mesh, n_steps);
    EXPECT_TRUE(kiln::exodus_file_in_metres(base + ".exo"));
    // Kiln's mesh reader reads the results file as a mesh (the split one, gap named).
    const Mesh back = kiln::read_exodus_mesh(base + ".exo", 1.0);
    EXPECT_EQ(back.cell_node_ids, mesh.cell_node_ids);
    EXPECT_TRUE(back.cell_types == mesh.cell_types);
    EXPECT_EQ(back.side_sets.back().name, "gap");
    if (!::testing::Test::HasFailure())
      std::filesystem::remove_all(folder);
  }
  MPI_Barrier(comm);
}

/// Runs `body` and returns the InternalError's message (empty if none was thrown).
template <typename Body> std::string internal_error_of(Body &&body)
{
  try
  {
    body();
  }
  catch (const kiln::InternalError &e)
  {
    return e.what();
  }
  return "";
}

TEST(ExodusResultsWriter, StepsThatDoNotMatchTheFirstAreInternalErrorsOnEveryRank)
{
  const MPI_Comm comm = MPI_COMM_WORLD;
  const int rank = rank_of(comm);
  const Mesh mesh = split_box();
  const Ownership o = make_ownership(mesh);
  const std::string folder = shared_test_folder(comm, "exodus_results_misuse");
  const std::vector<double> t(o.owned_nodes.size(), 1.0);
  const std::vector<double> u(3 * o.owned_nodes.size(), 2.0);
  {
    kiln::ExodusResultsWriter writer(comm, folder + "/out", mesh, o.owned_nodes, o.owned_cells,
                                     o.cell_rank);
    EXPECT_THAT(internal_error_of([&] { writer.write_node_field("temperature", 1, t); }),
                HasSubstr("called outside begin_step()/end_step()"));
    EXPECT_THAT(internal_error_of([&] { writer.end_step(); }),
                HasSubstr("end_step() called without begin_step()"));
    writer.begin_step(0.0, 0, 0.0);
    writer.write_node_field("temperature", 1, t);
    EXPECT_THAT(internal_error_of([&] { writer.write_node_field("temperature", 1, t); }),
                HasSubstr("\"temperature\" is written twice in step 0"));
    EXPECT_THAT(internal_error_of([&] { writer.write_node_field("bad/name", 1, t); }),
                HasSubstr("\"bad/name\" is not valid"));
    // Only rank 0 passes a wrong number of values: every rank throws.
    const std::vector<double> wrong(3 * o.owned_nodes.size() + (rank == 0 ? 1 : 0), 0.0);
    EXPECT_THAT(internal_error_of([&] { writer.write_node_field("displacement", 3, wrong); }),
                HasSubstr("node field \"displacement\" has"));
    writer.write_node_field("displacement", 3, u);
    EXPECT_THAT(internal_error_of([&] { writer.write_node_field("displacement_x", 1, t); }),
                HasSubstr("\"displacement_x\" of node field \"displacement_x\" is also a "
                          "variable of an earlier field"));
    writer.end_step();

    // Later steps: a new field, another number of components, a missing field.
    writer.begin_step(1.0, 1, 1.0);
    EXPECT_THAT(internal_error_of([&] { writer.write_node_field("pressure", 1, t); }),
                HasSubstr("node field \"pressure\" with 1 components does not match the fields "
                          "of the first step"));
    EXPECT_THAT(internal_error_of([&] { writer.write_node_field("displacement", 1, t); }),
                HasSubstr("does not match the fields of the first step"));
    writer.write_node_field("temperature", 1, t);
    EXPECT_THAT(internal_error_of([&] { writer.end_step(); }),
                HasSubstr("step 1 does not write \"displacement\", written in the first step"));
    // The failed step is not in the file; a complete one is.
    writer.begin_step(1.0, 1, 1.0);
    writer.write_node_field("displacement", 3, u);
    writer.write_node_field("temperature", 1, t);
    writer.end_step();
  }
  MPI_Barrier(comm);
  if (rank == 0)
  {
    const ExodusReader file(folder + "/out.running.exo"); // not finished: its running name
    EXPECT_EQ(ex_inquire_int(file.id(), EX_INQ_TIME), 2);
    EXPECT_EQ(file.names(EX_NODAL, 4, true),
              (Names{"temperature", "displacement_x", "displacement_y", "displacement_z"}));
    EXPECT_EQ(file.n_variables(EX_ELEM_BLOCK), 0);
    if (!::testing::Test::HasFailure())
      std::filesystem::remove_all(folder);
  }
  MPI_Barrier(comm);
}

TEST(ExodusResultsWriter, MissingFolderIsAnInputErrorNamingThePathOnEveryRank)
{
  const MPI_Comm comm = MPI_COMM_WORLD;
  const Mesh mesh = split_box();
  const Ownership o = make_ownership(mesh);
  const std::string base = "/nonexistent_kiln_folder/sub/out";
  const std::string message = kiln_test::input_error_message(
      [&] {
        kiln::ExodusResultsWriter writer(comm, base, mesh, o.owned_nodes, o.owned_cells,
                                         o.cell_rank);
      });
  if (message.empty())
    ADD_FAILURE() << "no exception";
  EXPECT_THAT(message, HasSubstr(base + ".running.exo"));
  EXPECT_THAT(message, HasSubstr("does not exist"));
  MPI_Barrier(comm); // every rank got here: the test did not hang
}
