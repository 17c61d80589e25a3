#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/numerics/error_estimator.h>

#include <fgimpact/plate/refinement_indicator.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace fgimpact
{
  namespace
  {
    /// E(z) in GPa: the weight that makes Kelly's gradient jump a
    /// traction jump (the scale only sets the indicator's unit).
    class ModulusWeight : public Function<3>
    {
    public:
      explicit ModulusWeight(const FunctionallyGradedMaterial &material)
        : material(material)
      {}

      double
      value(const Point<3> &p, const unsigned int = 0) const override
      {
        return 1e-9 * material.youngs_modulus(p[2]);
      }

    private:
      const FunctionallyGradedMaterial &material;
    };
  } // namespace



  RefinementIndicator::RefinementIndicator(const PlateModel &plate)
    : plate(plate)
    , ghosted(plate.locally_owned_dofs(),
              plate.locally_relevant_dofs(),
              plate.get_mpi_communicator())
    , step_indicator(
        plate.get_dof_handler().get_triangulation().n_active_cells())
    , accumulated(step_indicator.size())
  {}



  void
  RefinementIndicator::add(const TrilinosWrappers::MPI::Vector &u,
                           const double                         weight)
  {
    ghosted = u;
    const ModulusWeight modulus(plate.get_material());
    KellyErrorEstimator<3>::estimate(plate.get_mapping(),
                                     plate.get_dof_handler(),
                                     QGauss<2>(plate.get_fe().degree + 1),
                                     {},
                                     ghosted,
                                     step_indicator,
                                     ComponentMask(),
                                     &modulus);
    for (unsigned int i = 0; i < step_indicator.size(); ++i)
      accumulated[i] += weight * double(step_indicator[i]) * step_indicator[i];
  }



  std::vector<std::string>
  RefinementIndicator::cells_to_refine(const double fraction) const
  {
    // Every rank's (indicator, id): a few MB at 10^5 cells, gathered once
    // per pilot run.
    std::vector<std::pair<double, std::string>> mine;
    for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        mine.emplace_back(accumulated[cell->active_cell_index()],
                          cell->id().to_string());
    std::vector<std::pair<double, std::string>> all;
    for (auto &part :
         Utilities::MPI::all_gather(plate.get_mpi_communicator(), mine))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
      return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
    const std::size_t        n = std::min(all.size(),
                                   static_cast<std::size_t>(
                                     std::ceil(fraction * double(all.size()))));
    std::vector<std::string> ids;
    for (std::size_t i = 0; i < n; ++i)
      ids.push_back(all[i].second);
    return ids;
  }
} // namespace fgimpact
