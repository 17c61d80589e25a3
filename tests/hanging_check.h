// The hanging vertices of a run's VTU snapshot, found from the cells'
// boxes in the file (not from the library), against the interpolation of
// their coarser cell's corners (hanging_fields, adaptive_mesh).

#ifndef fgimpact_tests_hanging_check_h
#define fgimpact_tests_hanging_check_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>
#include <vtu_reader.h>

namespace fgimpact_tests::hanging
{
  using namespace dealii;

  inline constexpr unsigned int n_fields = 4; // u, v, a (3 each), sigma_zz
  inline const char *const      field_names[n_fields] = {"displacement_m",
                                                         "velocity_m_s",
                                                         "acceleration_m_s2",
                                                         "sigma_zz_MPa"};
  inline constexpr unsigned int field_size[n_fields]  = {3, 3, 3, 1};

  /// One point of a snapshot: position and the 10 field values.
  struct PointValues
  {
    std::array<double, 3>  x;
    std::array<double, 10> f;
  };

  /// A position rounded to 1e-7 m (the float32 coordinates are exact to
  /// about 1e-8 m; the finest cell here is 625 um).
  using Key = std::array<long long, 3>;
  inline Key
  key_of(const std::array<double, 3> &x)
  {
    return {{std::llround(x[0] * 1e7),
             std::llround(x[1] * 1e7),
             std::llround(x[2] * 1e7)}};
  }

  /// Every cell of a snapshot (all pieces): its 8 points in file order.
  inline std::vector<std::array<PointValues, 8>>
  read_snapshot(const std::string &directory,
                const unsigned int step,
                const unsigned int n_pieces)
  {
    std::vector<std::array<PointValues, 8>> cells;
    for (unsigned int piece = 0; piece < n_pieces; ++piece)
      {
        const std::string file = directory + "/vtu/solution_" +
                                 Utilities::int_to_string(step, 5) + "." +
                                 std::to_string(piece) + ".vtu";
        const auto                      xyz = fgimpact_tests::read_points(file);
        std::vector<std::vector<float>> data;
        for (const char *name : field_names)
          data.push_back(fgimpact_tests::read_array(file, name));
        const std::size_t n_points = xyz.size() / 3;
        AssertThrow(n_points % 8 == 0, ExcMessage("not 8 points per cell"));
        for (std::size_t c = 0; c < n_points / 8; ++c)
          {
            std::array<PointValues, 8> cell;
            for (unsigned int k = 0; k < 8; ++k)
              {
                const std::size_t p = 8 * c + k;
                for (unsigned int d = 0; d < 3; ++d)
                  cell[k].x[d] = xyz[3 * p + d];
                unsigned int j = 0;
                for (unsigned int f = 0; f < n_fields; ++f)
                  for (unsigned int d = 0; d < field_size[f]; ++d)
                    cell[k].f[j++] = data[f][field_size[f] * p + d];
              }
            cells.push_back(cell);
          }
      }
    return cells;
  }

  struct HangingCheck
  {
    std::set<Key>            vertices;      // the hanging vertices found
    unsigned int             n_checked = 0; // (vertex, fine cell) pairs
    std::array<double, 4>    largest{};     // |difference| per field
    std::array<double, 4>    scale{};       // largest |value| per field
    std::vector<PointValues> top;           // hanging vertices on z = h
  };

  /// Check every hanging vertex of one snapshot against its coarse cell.
  inline void
  check_hanging(const std::vector<std::array<PointValues, 8>> &cells,
                const double                                   h,
                HangingCheck                                  &check)
  {
    std::map<Key, std::vector<const PointValues *>> points;
    for (const auto &cell : cells)
      for (const auto &p : cell)
        {
          points[key_of(p.x)].push_back(&p);
          unsigned int j = 0;
          for (unsigned int f = 0; f < n_fields; ++f)
            for (unsigned int d = 0; d < field_size[f]; ++d, ++j)
              check.scale[f] = std::max(check.scale[f], std::abs(p.f[j]));
        }
    for (const auto &cell : cells)
      {
        // The box, and the corner at each (i, j, k) in {0, 1}^3.
        std::array<double, 3> lo = cell[0].x, hi = cell[0].x;
        for (const auto &p : cell)
          for (unsigned int d = 0; d < 3; ++d)
            {
              lo[d] = std::min(lo[d], p.x[d]);
              hi[d] = std::max(hi[d], p.x[d]);
            }
        std::array<const PointValues *, 8> corner{};
        for (const auto &p : cell)
          {
            unsigned int index = 0;
            for (unsigned int d = 0; d < 3; ++d)
              index |= (p.x[d] > 0.5 * (lo[d] + hi[d]) ? 1u : 0u) << d;
            corner[index] = &p;
          }
        // Edge midpoints (one coordinate 1/2) and face centres (two): the
        // interpolation is the average of the corners they lie between.
        for (unsigned int m = 0; m < 27; ++m)
          {
            const unsigned int t[3]  = {m % 3, (m / 3) % 3, m / 9};
            const unsigned int halfs = (t[0] == 1) + (t[1] == 1) + (t[2] == 1);
            if (halfs == 0 || halfs == 3)
              continue;
            std::array<double, 3> x;
            for (unsigned int d = 0; d < 3; ++d)
              x[d] = lo[d] + 0.5 * t[d] * (hi[d] - lo[d]);
            const auto found = points.find(key_of(x));
            if (found == points.end())
              continue;
            std::array<double, 10> expected{};
            unsigned int           n = 0;
            for (unsigned int c = 0; c < 8; ++c)
              {
                bool between = true;
                for (unsigned int d = 0; d < 3; ++d)
                  between =
                    between && (t[d] == 1 || ((c >> d) & 1u) == t[d] / 2);
                if (!between)
                  continue;
                ++n;
                for (unsigned int j = 0; j < 10; ++j)
                  expected[j] += corner[c]->f[j];
              }
            if (check.vertices.insert(found->first).second &&
                std::abs(x[2] - h) < 1e-7)
              check.top.push_back(*found->second[0]);
            for (const PointValues *p : found->second)
              {
                ++check.n_checked;
                unsigned int j = 0;
                for (unsigned int f = 0; f < n_fields; ++f)
                  for (unsigned int d = 0; d < field_size[f]; ++d, ++j)
                    check.largest[f] =
                      std::max(check.largest[f],
                               std::abs(p->f[j] - expected[j] / n));
              }
          }
      }
  }

} // namespace fgimpact_tests::hanging

#endif
