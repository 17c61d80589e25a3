// VTU files with raw appended binary data: see raw_vtu.h.

#include <deal.II/base/exceptions.h>

#include <fgimpact/output/raw_vtu.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace fgimpact
{
  namespace
  {
    using Patch = DataOutBase::Patch<3, 3>;

    /// A data array of the file: its XML attributes and its bytes.
    struct Array
    {
      std::string       type, name;
      unsigned int      n_components;
      std::vector<char> bytes;
    };

    template <typename T>
    void
    append(std::vector<char> &bytes, const T value)
    {
      const char *p = reinterpret_cast<const char *>(&value);
      bytes.insert(bytes.end(), p, p + sizeof(T));
    }

    /// Point j (lexicographic, n per direction) of patch p: stored, or
    /// the trilinear map of its vertices (as deal.II computes it).
    Point<3>
    patch_point(const Patch       &p,
                const unsigned int j,
                const unsigned int n,
                const unsigned int n_sets)
    {
      const unsigned int i[3] = {j % n, (j / n) % n, j / (n * n)};
      Point<3>           x;
      if (p.points_are_available)
        {
          for (unsigned int d = 0; d < 3; ++d)
            x[d] = p.data(n_sets + d, j);
          return x;
        }
      const double s[3] = {n > 1 ? double(i[0]) / (n - 1) : 0.,
                           n > 1 ? double(i[1]) / (n - 1) : 0.,
                           n > 1 ? double(i[2]) / (n - 1) : 0.};
      for (unsigned int v = 0; v < 8; ++v)
        {
          double w = 1.;
          for (unsigned int d = 0; d < 3; ++d)
            w *= ((v >> d) & 1) ? s[d] : 1. - s[d];
          x += w * p.vertices[v];
        }
      return x;
    }

    /// Points, connectivity, offsets and types of all patches' subcells
    /// (VTK_HEXAHEDRON, VTK's vertex order).
    std::vector<Array>
    grid_arrays(const std::vector<Patch> &patches, const unsigned int n_sets)
    {
      Array points{"Float32", "", 3, {}},
        connectivity{"Int32", "connectivity", 1, {}},
        offsets{"Int32", "offsets", 1, {}}, types{"UInt8", "types", 1, {}};
      std::int32_t first = 0, offset = 0;
      // deal.II's lexicographic corner (bit d = side d) of VTK's vertex k.
      const unsigned int vtk_order[8] = {0, 1, 3, 2, 4, 5, 7, 6};
      for (const Patch &p : patches)
        {
          const unsigned int n = p.n_subdivisions + 1;
          for (unsigned int j = 0; j < n * n * n; ++j)
            {
              const Point<3> x = patch_point(p, j, n, n_sets);
              for (unsigned int d = 0; d < 3; ++d)
                append(points.bytes, static_cast<float>(x[d]));
            }
          for (unsigned int c2 = 0; c2 + 1 < n; ++c2)
            for (unsigned int c1 = 0; c1 + 1 < n; ++c1)
              for (unsigned int c0 = 0; c0 + 1 < n; ++c0)
                {
                  for (const unsigned int v : vtk_order)
                    append(connectivity.bytes,
                           static_cast<std::int32_t>(first + (c0 + (v & 1)) +
                                                     n * (c1 + ((v >> 1) & 1)) +
                                                     n * n *
                                                       (c2 + ((v >> 2) & 1))));
                  offset += 8;
                  append(offsets.bytes, offset);
                  append(types.bytes, static_cast<std::uint8_t>(12));
                }
          first += n * n * n;
        }
      return {points, connectivity, offsets, types};
    }
    /// The point data: every nonscalar range as one array, the other
    /// components as scalars (deal.II's order: the ranges first).
    std::vector<Array>
    point_data_arrays(const std::vector<Patch>       &patches,
                      const std::vector<std::string> &names,
                      const NonscalarRanges          &nonscalar_ranges)
    {
      const unsigned int n_sets = names.size();
      std::vector<Array> data;
      std::vector<bool>  in_range(n_sets, false);
      const auto         add = [&](const std::string &name,
                           const unsigned int first,
                           const unsigned int size) {
        Array a{"Float32", name, size, {}};
        for (const Patch &p : patches)
          for (unsigned int j = 0; j < p.data.n_cols(); ++j)
            for (unsigned int c = 0; c < size; ++c)
              append(a.bytes, static_cast<float>(p.data(first + c, j)));
        data.push_back(std::move(a));
      };
      for (const auto &range : nonscalar_ranges)
        {
          const unsigned int first = std::get<0>(range),
                             last  = std::get<1>(range);
          for (unsigned int k = first; k <= last; ++k)
            in_range[k] = true;
          // An unnamed range: its components' names joined by "__", as
          // deal.II names it.
          std::string name = std::get<2>(range);
          if (name.empty())
            for (unsigned int k = first; k <= last; ++k)
              name += (k > first ? "__" : "") + names[k];
          add(name, first, last - first + 1);
        }
      for (unsigned int k = 0; k < n_sets; ++k)
        if (!in_range[k])
          add(names[k], k, 1);
      return data;
    }
  } // namespace



  void
  write_raw_vtu(const std::vector<DataOutBase::Patch<3, 3>> &patches,
                const std::vector<std::string>              &names,
                const NonscalarRanges                       &nonscalar_ranges,
                const double                                 time,
                const unsigned int                           cycle,
                std::ostream                                &out)
  {
    const unsigned int       n_sets = names.size();
    const std::vector<Array> data =
      point_data_arrays(patches, names, nonscalar_ranges);
    const std::vector<Array> grid = grid_arrays(patches, n_sets);

    std::size_t n_points = 0, n_cells = 0;
    for (const Patch &p : patches)
      {
        n_points += std::pow(p.n_subdivisions + 1, 3);
        n_cells += std::pow(p.n_subdivisions, 3);
      }
    std::uint64_t offset = 0;
    const auto    header = [&](const Array &a) {
      std::ostringstream s;
      s << "<DataArray type=\"" << a.type << "\"";
      if (!a.name.empty())
        s << " Name=\"" << a.name << "\"";
      s << " NumberOfComponents=\"" << a.n_components
        << "\" format=\"appended\" offset=\"" << offset << "\"/>\n";
      offset += sizeof(std::uint64_t) + a.bytes.size();
      return s.str();
    };
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" "
           "version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n<UnstructuredGrid>\n";
    if (time != std::numeric_limits<double>::min())
      out << "<FieldData>\n<DataArray type=\"Float32\" Name=\"CYCLE\" "
             "NumberOfTuples=\"1\" format=\"ascii\">"
          << cycle
          << "</DataArray>\n<DataArray type=\"Float32\" Name=\"TIME\" "
             "NumberOfTuples=\"1\" format=\"ascii\">"
          << time << "</DataArray>\n</FieldData>\n";
    out << "<Piece NumberOfPoints=\"" << n_points << "\" NumberOfCells=\""
        << n_cells << "\">\n<PointData>\n";
    for (const Array &a : data)
      out << header(a);
    out << "</PointData>\n<Points>\n"
        << header(grid[0]) << "</Points>\n<Cells>\n";
    for (unsigned int k = 1; k < 4; ++k)
      out << header(grid[k]);
    out << "</Cells>\n</Piece>\n</UnstructuredGrid>\n"
           "<AppendedData encoding=\"raw\">\n_";
    const std::vector<const std::vector<Array> *> all = {&data, &grid};
    for (const std::vector<Array> *arrays : all)
      for (const Array &a : *arrays)
        {
          const std::uint64_t n = a.bytes.size();
          out.write(reinterpret_cast<const char *>(&n), sizeof(n));
          out.write(a.bytes.data(), a.bytes.size());
        }
    out << "\n</AppendedData>\n</VTKFile>\n";
  }
} // namespace fgimpact
