#include <deal.II/dofs/dof_tools.h>

#include <fgimpact/plate/plate_model.h>

#include <algorithm>
#include <array>
#include <map>

namespace fgimpact
{
  namespace
  {
    /// One normal-component DoF of a side: (position along the side, z,
    /// DoF).
    using EdgeNode = std::array<double, 3>;

    /// The weights of the mean over [0, h] of a field given at the sorted
    /// heights z of one column of nodes: the trapezoid rule for linear
    /// elements, Simpson's rule on each element's three nodes for
    /// quadratic ones (the element's own integration of its shape
    /// functions).
    std::vector<double>
    column_weights(const std::vector<double> &z, const unsigned int degree)
    {
      std::vector<double> w(z.size(), 0.);
      const unsigned int  step = (degree == 2 ? 2 : 1);
      for (unsigned int i = 0; i + step < z.size(); i += step)
        {
          const double dz = z[i + step] - z[i];
          if (step == 1)
            {
              w[i] += dz / 2;
              w[i + 1] += dz / 2;
            }
          else
            {
              w[i] += dz / 6;
              w[i + 1] += 4 * dz / 6;
              w[i + 2] += dz / 6;
            }
        }
      return w;
    }
  } // namespace



  void
  PlateModel::collect_edge_columns(const AffineConstraints<double> &c)
  {
    const PlateGeometry::Parameters &g = geometry.get_parameters();
    edge_columns.clear();
    if (!g.immovable_edges)
      return;
    std::map<types::global_dof_index, Point<3>> points;
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, points);
    for (unsigned int face = 0; face < 4; ++face)
      {
        if (g.supports[face] != SideSupport::simply_supported ||
            (face == 1 && geometry.is_cut(0)) ||
            (face == 3 && geometry.is_cut(1)))
          continue;
        const unsigned int normal = face / 2, along = 1 - normal;
        ComponentMask      mask(3, false);
        mask.set(normal, true);
        // The owners' unconstrained nodes, gathered: every rank sees every
        // column whole and the same.
        std::vector<EdgeNode> mine;
        for (const auto dof :
             DoFTools::extract_boundary_dofs(dof_handler, mask, {face}))
          if (locally_owned.is_element(dof) && !c.is_constrained(dof))
            mine.push_back({points.at(dof)[along],
                            points.at(dof)[2],
                            static_cast<double>(dof)});
        std::map<double, std::vector<std::pair<double, double>>> columns;
        for (const auto &part :
             Utilities::MPI::all_gather(mpi_communicator, mine))
          for (const EdgeNode &node : part)
            columns[node[0]].emplace_back(node[1], node[2]);
        for (auto &[position, column] : columns)
          {
            std::sort(column.begin(), column.end());
            edge_columns.push_back(column);
          }
      }
    // A column may span ranks: its DoFs join the relevant set, so that
    // its line can be stored and condensed on every rank.
    IndexSet columns_dofs(dof_handler.n_dofs());
    for (const auto &column : edge_columns)
      for (const auto &node : column)
        columns_dofs.add_index(
          static_cast<types::global_dof_index>(node.second));
    locally_relevant.add_indices(columns_dofs);
  }



  void
  PlateModel::add_immovable_edges(AffineConstraints<double> &c) const
  {
    for (const auto &column : edge_columns)
      add_mean_constraint(column, c);
  }



  void
  PlateModel::add_mean_constraint(
    const std::vector<std::pair<double, double>> &column,
    AffineConstraints<double>                    &c) const
  {
    // A column that misses a face (a support holds its end, or a hanging
    // node) is held there already, or is not one element's nodes.
    const double h = geometry.get_parameters().thickness;
    if (column.size() < 2 || column.front().first > 1e-9 * h ||
        column.back().first < h * (1 - 1e-9))
      return;
    std::vector<double> z;
    for (const auto &node : column)
      z.push_back(node.first);
    const std::vector<double> w = column_weights(z, fe.degree);
    // The node nearest the mid-plane follows the others: sum w_j u_j = 0.
    unsigned int k = 0;
    for (unsigned int j = 0; j < z.size(); ++j)
      if (std::abs(z[j] - h / 2) < std::abs(z[k] - h / 2))
        k = j;
    const auto dof = static_cast<types::global_dof_index>(column[k].second);
    if (!c.can_store_line(dof) || w[k] == 0.)
      return;
    c.add_line(dof);
    for (unsigned int j = 0; j < z.size(); ++j)
      if (j != k && w[j] != 0.)
        c.add_entry(dof,
                    static_cast<types::global_dof_index>(column[j].second),
                    -w[j] / w[k]);
  }
} // namespace fgimpact
