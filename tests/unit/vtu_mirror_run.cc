// The whole plate from a quarter, as a user opens it: a resolved-sphere
// impact modelled on the quarter (Geometry/Symmetry = quarter, Output/
// Mirror symmetric part = true, the default) against the same impact on
// the whole plate (Symmetry = none), read back from the files both runs
// write at 20 us:
//  (1) vtu/solution_00020.pvtu: the extents (bounding box) and the set of
//      points of the quarter's two pieces equal the whole plate's, and the
//      displacement at every point agrees (float32; relative to the
//      largest |u|);
//  (2) vtu/contact_00020.vtu: the same contact nodes (a node on a cut
//      plane once), with the same nodal force, pressure and z displacement
//      (relative to the largest of each).

#include <deal.II/base/mpi.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <test_tools.h>
#include <vtu_reader.h>

namespace fgimpact_unit_tests::vtu_mirror_run
{

  using namespace dealii;

  namespace
  {
    using Key = std::array<long, 3>;

    /// A point rounded to 0.1 um, as a map key.
    Key
    key(const double x, const double y, const double z)
    {
      return {std::lround(x * 1e7), std::lround(y * 1e7), std::lround(z * 1e7)};
    }

    /// Every point of a run's snapshot (its pieces) with its displacement.
    std::map<Key, std::array<double, 3>>
    plate_points(const std::string &directory, const unsigned int n_pieces)
    {
      std::map<Key, std::array<double, 3>> points;
      for (unsigned int k = 0; k < n_pieces; ++k)
        {
          const std::string file =
            directory + "/vtu/solution_00020." + std::to_string(k) + ".vtu";
          const auto x = fgimpact_tests::read_points(file);
          const auto u = fgimpact_tests::read_array(file, "displacement_m");
          for (std::size_t i = 0; 3 * i + 2 < x.size(); ++i)
            points[key(x[3 * i], x[3 * i + 1], x[3 * i + 2])] = {
              {u[3 * i], u[3 * i + 1], u[3 * i + 2]}};
        }
      return points;
    }


    /// The contact nodes: position -> (force, pressure, u_z).
    std::map<Key, std::array<double, 3>>
    contact_nodes(const std::string &directory)
    {
      const std::string text =
        fgimpact_tests::file_text(directory + "/vtu/contact_00020.vtu");
      const auto x = fgimpact_tests::ascii_array(text, "");
      const auto F = fgimpact_tests::ascii_array(text, "nodal_force_N");
      const auto p = fgimpact_tests::ascii_array(text, "contact_pressure_MPa");
      const auto d = fgimpact_tests::ascii_array(text, "displacement_m");
      std::map<Key, std::array<double, 3>> nodes;
      for (std::size_t i = 0; i < F.size(); ++i)
        nodes[key(x[3 * i], x[3 * i + 1], x[3 * i + 2])] = {
          {F[i], p[i], d[3 * i + 2]}};
      return nodes;
    }

    /// The largest difference of the values of equal keys, relative to the
    /// largest |value| of each component; NaN if the key sets differ.
    std::array<double, 3>
    compare(const std::map<Key, std::array<double, 3>> &a,
            const std::map<Key, std::array<double, 3>> &b)
    {
      std::array<double, 3> worst{{0, 0, 0}}, largest{{0, 0, 0}};
      if (a.size() != b.size())
        return {{NAN, NAN, NAN}};
      for (const auto &[k, value] : a)
        {
          const auto other = b.find(k);
          if (other == b.end())
            return {{NAN, NAN, NAN}};
          for (unsigned int c = 0; c < 3; ++c)
            {
              worst[c] =
                std::max(worst[c], std::abs(value[c] - other->second[c]));
              largest[c] = std::max(largest[c], std::abs(other->second[c]));
            }
        }
      for (unsigned int c = 0; c < 3; ++c)
        worst[c] /= std::max(largest[c], 1e-300);
      return worst;
    }
  } // namespace



  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    fgimpact_tests::remove_output("quarter");
    fgimpact_tests::remove_output("whole");
    const std::string common =
      "subsection Contact\n set Model = resolved sphere\nend\n"
      "subsection Time integration\n set End time = 20e-6\nend\n"
      "subsection Output\n set Log interval = 0\n set Print timing = false\n"
      " set VTU interval = 10\n set Fields = displacement\n"
      " set VTU compression = none\n" // raw data: tests/vtu_reader.h
      " set Snapshot at peak force = false\n";
    fgimpact_tests::run_quietly("",
                                common + " set Directory = quarter\nend\n"
                                         "subsection Geometry\n"
                                         " set Symmetry = quarter\nend\n");
    fgimpact_tests::run_quietly("",
                                common + " set Directory = whole\nend\n"
                                         "subsection Geometry\n"
                                         " set Symmetry = none\nend\n");

    // (1) The plate.
    const auto quarter = plate_points("quarter", 2);
    const auto whole   = plate_points("whole", 1);
    Key        low_q = quarter.begin()->first, high_q = low_q;
    Key        low_w = whole.begin()->first, high_w = low_w;
    for (const auto &[k, u] : quarter)
      for (unsigned int d = 0; d < 3; ++d)
        {
          low_q[d]  = std::min(low_q[d], k[d]);
          high_q[d] = std::max(high_q[d], k[d]);
        }
    for (const auto &[k, u] : whole)
      for (unsigned int d = 0; d < 3; ++d)
        {
          low_w[d]  = std::min(low_w[d], k[d]);
          high_w[d] = std::max(high_w[d], k[d]);
        }
    const auto plate      = compare(quarter, whole);
    const bool extents_ok = low_q == low_w && high_q == high_w;
    const bool plate_ok =
      extents_ok && plate[0] < 1e-5 && plate[1] < 1e-5 && plate[2] < 1e-5;
    // Verdicts, not the differences: those are round-off, whose digits
    // depend on the CPU and the BLAS kernel.
    std::printf("plate: extents (%.1f, %.1f, %.1f)-(%.1f, %.1f, %.1f) mm the "
                "whole plate's: %s; %zu points against %zu, largest "
                "difference of u_x, u_y, u_z / largest below 1e-5: %s\n",
                low_q[0] * 1e-4,
                low_q[1] * 1e-4,
                low_q[2] * 1e-4,
                high_q[0] * 1e-4,
                high_q[1] * 1e-4,
                high_q[2] * 1e-4,
                extents_ok ? "yes" : "NO",
                quarter.size(),
                whole.size(),
                plate_ok ? "yes" : "NO");

    // (2) The contact nodes.
    const auto nodes_q  = contact_nodes("quarter");
    const auto nodes_w  = contact_nodes("whole");
    const auto nodes    = compare(nodes_q, nodes_w);
    const bool nodes_ok = nodes[0] < 1e-6 && nodes[1] < 1e-6 && nodes[2] < 1e-6;
    unsigned int active = 0;
    for (const auto &[k, value] : nodes_w)
      active += value[0] > 0;
    std::printf("contact nodes: %zu against %zu (%u in contact), largest "
                "difference of force, pressure, u_z / largest below 1e-6: "
                "%s\n",
                nodes_q.size(),
                nodes_w.size(),
                active,
                nodes_ok && active > 0 ? "yes" : "NO");
    return plate_ok && nodes_ok && active > 0 ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::vtu_mirror_run
