#include <fgimpact/output/mirrored_data_out.h>
#include <fgimpact/output/raw_vtu.h>

#include <array>

namespace fgimpact
{
  namespace
  {
    /// Whether a scalar data set named like a tensor component ("_ab" with
    /// a, b in x, y, z, followed by '_' or the end) changes sign under the
    /// reflection normal to axis d: exactly one of a, b is that axis.
    bool
    odd_component_name(const std::string &name, const unsigned int d)
    {
      const auto is_axis = [](const char c) {
        return c == 'x' || c == 'y' || c == 'z';
      };
      const char axis = "xyz"[d];
      for (std::size_t i = 0; i + 2 < name.size(); ++i)
        if (name[i] == '_' && is_axis(name[i + 1]) && is_axis(name[i + 2]) &&
            (i + 3 == name.size() || name[i + 3] == '_'))
          return (name[i + 1] == axis) != (name[i + 2] == axis);
      return false;
    }



    /// The reflection of patch p across x_d = plane, with the data set
    /// signs `signs` (the point coordinates, if stored, are reflected).
    DataOutBase::Patch<3, 3>
    reflect(const DataOutBase::Patch<3, 3> &p,
            const unsigned int              d,
            const double                    plane,
            const std::vector<float>       &signs)
    {
      DataOutBase::Patch<3, 3> q = p;
      // Vertices in lexicographic order (bit d of the index = side in
      // direction d): swapping the two sides keeps the orientation.
      for (unsigned int v = 0; v < GeometryInfo<3>::vertices_per_cell; ++v)
        {
          q.vertices[v]    = p.vertices[v ^ (1u << d)];
          q.vertices[v][d] = 2 * plane - q.vertices[v][d];
        }
      q.neighbors.fill(DataOutBase::Patch<3, 3>::no_neighbor);

      const unsigned int n      = p.n_subdivisions + 1;
      const unsigned int stride = (d == 0 ? 1 : n);
      const unsigned int n_sets = signs.size();
      for (unsigned int j = 0; j < p.data.n_cols(); ++j)
        {
          // Point j = i0 + n i1 + n^2 i2; its image has i_d -> n - 1 - i_d.
          const unsigned int i_d    = (j / stride) % n;
          const unsigned int source = j + (n - 1 - 2 * i_d) * stride;
          for (unsigned int r = 0; r < p.data.n_rows(); ++r)
            q.data(r, j) = (r < n_sets ? signs[r] : 1.f) * p.data(r, source);
          if (p.points_are_available)
            q.data(n_sets + d, j) = 2 * plane - p.data(n_sets + d, source);
        }
      return q;
    }
  } // namespace



  MirroredDataOut::MirroredDataOut(const PlateGeometry &geometry)
    : geometry(geometry)
  {}



  std::vector<float>
  MirroredDataOut::reflection_signs(const unsigned int d) const
  {
    const std::vector<std::string> names = get_dataset_names();
    std::vector<float>             signs(names.size(), 1.f);
    std::vector<bool>              in_range(names.size(), false);
    for (const auto &range : get_nonscalar_data_ranges())
      {
        const unsigned int first = std::get<0>(range),
                           last  = std::get<1>(range);
        const unsigned int size  = last - first + 1;
        for (unsigned int k = first; k <= last; ++k)
          in_range[k] = true;
        const auto kind = std::get<3>(range);
        if (kind == DataComponentInterpretation::component_is_part_of_vector &&
            size == 3)
          signs[first + d] = -1.f;
        else if (kind ==
                   DataComponentInterpretation::component_is_part_of_tensor &&
                 size == 9) // row by row
          for (unsigned int i = 0; i < 3; ++i)
            for (unsigned int k = 0; k < 3; ++k)
              if ((i == d) != (k == d))
                signs[first + 3 * i + k] = -1.f;
      }
    for (unsigned int k = 0; k < names.size(); ++k)
      if (!in_range[k] && odd_component_name(names[k], d))
        signs[k] = -1.f;
    return signs;
  }



  void
  MirroredDataOut::mirror()
  {
    first    = DataOut<3>::get_patches();
    mirrored = true;
    second.clear();
    whole.clear();
    const std::array<double, 2> centre = {
      {0.5 * geometry.length(), 0.5 * geometry.width()}};
    const int last_cut = geometry.is_cut(1) ? 1 : geometry.is_cut(0) ? 0 : -1;
    split              = last_cut >= 0;
    for (int d = 0; d <= last_cut; ++d)
      if (geometry.is_cut(d))
        {
          const std::vector<float> signs = reflection_signs(d);
          const std::size_t        n     = first.size();
          // The last reflection is a piece of its own (numbered from 0 in
          // it), the others extend the first piece.
          auto &target = (d == last_cut ? second : first);
          target.reserve(target.size() + n);
          for (std::size_t i = 0; i < n; ++i)
            {
              target.push_back(reflect(first[i], d, centre[d], signs));
              target.back().patch_index = (d == last_cut ? i : n + i);
            }
        }
  }



  const std::vector<DataOutBase::Patch<3, 3>> &
  MirroredDataOut::get_patches() const
  {
    if (!mirrored)
      return DataOut<3>::get_patches();
    if (!split)
      return first;
    if (whole.empty())
      {
        whole = first;
        for (const auto &p : second)
          {
            whole.push_back(p);
            whole.back().patch_index += first.size();
          }
      }
    return whole;
  }



  void
  MirroredDataOut::write_vtu_piece(const unsigned int k,
                                   std::ostream      &out) const
  {
    AssertIndexRange(k, n_pieces());
    const auto &patches = n_pieces() == 1 ? get_patches() :
                          k == 0          ? first :
                                            second;
    // No compression: raw binary (deal.II would still deflate and encode).
    if (vtk.compression_level == DataOutBase::VtkFlags::no_compression)
      write_raw_vtu(patches,
                    get_dataset_names(),
                    get_nonscalar_data_ranges(),
                    vtk.time,
                    vtk.cycle,
                    out);
    else if (n_pieces() == 1)
      write_vtu(out);
    else
      DataOutBase::write_vtu(
        patches, get_dataset_names(), get_nonscalar_data_ranges(), vtk, out);
  }
} // namespace fgimpact
