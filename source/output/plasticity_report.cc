// What a plastic plate leaves, for summary.txt (plasticity_report.h).

#include <deal.II/base/mpi.h>

#include <fgimpact/output/plasticity_report.h>
#include <fgimpact/output/validity_report.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <set>

namespace fgimpact
{
  PlasticityReport::PlasticityReport(const PlasticPlate &plasticity,
                                     const PlateModel   &plate,
                                     ImpactResults      &results,
                                     const double        whole,
                                     const double        V0,
                                     const Point<3>     &impact_point,
                                     const double        radius)
    : impact_point(impact_point)
    , top(plate.get_geometry().thickness())
    , mpi_communicator(plate.get_mpi_communicator())
    , plasticity(plasticity)
    , results(results)
    , whole(whole)
    , V0(V0)
    , R(radius)
    , material(plate.get_material())
    , degree(plate.get_fe().degree)
    , locking(degree == 1 && !plate.uses_mean_dilatation())
    // First yield is interpolated from the state before the load: a
    // thermal pre-stress's own ratio (0 without).
    , last_ratio(plasticity.initial_yield_ratio())
  {
    results.plastic.modelled                    = true;
    const double                      tolerance = 1e-9 * top;
    const auto                       &owned     = plate.locally_owned_dofs();
    std::set<types::global_dof_index> seen;
    for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const Point<3> &x = cell->vertex(v);
            const double    r = impact_point[0] - x[0];
            if (std::abs(x[2] - top) < tolerance &&
                std::abs(x[1] - impact_point[1]) < tolerance &&
                r > -tolerance && r <= radius)
              {
                const auto dof = cell->vertex_dof_index(v, 2);
                if (owned.is_element(dof) && seen.insert(dof).second)
                  line.emplace_back(dof, std::max(r, 0.));
              }
          }
    line_deflection.assign(line.size(), 0.);
  }



  void
  PlasticityReport::execute(const StepRecord &record)
  {
    const HistorySample &s     = *record.sample;
    const double         ratio = plasticity.max_trial_ratio();
    const double         force = s.contact->force;
    auto                &r     = results.plastic;
    if (std::isnan(r.first_yield_time) &&
        plasticity.max_equivalent_plastic_strain() > 0.)
      {
        // The trial ratio crossed 1 in this step.
        const double theta  = yield_crossing(last_ratio, ratio);
        r.first_yield_time  = last_time + theta * (record.t - last_time);
        r.first_yield_force = last_force + theta * (force - last_force);
      }
    if (record.fields)
      for (unsigned int i = 0; i < line.size(); ++i)
        line_deflection[i] = -record.fields->displacement()(line[i].first);
    W_mid       = s.W_mid;
    last_ratio  = ratio;
    last_time   = record.t;
    last_force  = force;
    indentation = s.W_top - s.W_mid;
  }



  void
  PlasticityReport::save(CheckpointWriter &out, const unsigned int)
  {
    for (const double value : {last_ratio,
                               last_time,
                               last_force,
                               indentation,
                               results.plastic.first_yield_time,
                               results.plastic.first_yield_force})
      out.put(value);
  }



  void
  PlasticityReport::load(CheckpointReader &in)
  {
    for (double *value : {&last_ratio,
                          &last_time,
                          &last_force,
                          &indentation,
                          &results.plastic.first_yield_time,
                          &results.plastic.first_yield_force})
      in.get(*value);
  }



  void
  PlasticityReport::close_output()
  {
    auto      &r          = results.plastic;
    const auto zone       = plasticity.plastic_zone_extent(impact_point, top);
    r.plastic_zone_depth  = zone[0];
    r.plastic_zone_radius = zone[1];
    // The thinning along the line, from every rank, by distance; the rim
    // is its first change of sign (linear between the two nodes).
    std::vector<std::pair<double, double>> local;
    for (unsigned int i = 0; i < line.size(); ++i)
      local.emplace_back(line[i].second, line_deflection[i] - W_mid);
    std::vector<std::pair<double, double>> profile;
    for (const auto &part : Utilities::MPI::all_gather(mpi_communicator, local))
      profile.insert(profile.end(), part.begin(), part.end());
    std::sort(profile.begin(), profile.end());
    r.crater_diameter = std::numeric_limits<double>::quiet_NaN();
    for (unsigned int i = 1; i < profile.size(); ++i)
      if (profile[i - 1].second > 0. && profile[i].second <= 0.)
        {
          const auto [r0, d0] = profile[i - 1];
          const auto [r1, d1] = profile[i];
          r.crater_diameter   = 2. * (r0 + d0 / (d0 - d1) * (r1 - r0));
          break;
        }
  }



  void
  PlasticityReport::finish(const ImpactorState &)
  {
    auto &r                 = results.plastic;
    r.dissipation           = whole * plasticity.plastic_work();
    r.max_plastic_strain    = plasticity.max_equivalent_plastic_strain();
    r.permanent_indentation = indentation;
    // The results accumulator, first in the list, has set it.
    r.restitution = results.departure_velocity / V0;
    r.mean_iterations =
      double(plasticity.n_iterations()) / std::max(results.n_time_steps, 1u);
    r.max_iterations = plasticity.max_increment_iterations();
    judge_first_yield();
    if (locking && r.max_plastic_strain > 0.)
      {
        const std::string text = locking_warning();
        results.warnings.push_back(text);
        if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
          std::cout << "  WARNING: " << text << ".\n";
      }
  }



  void
  PlasticityReport::judge_first_yield()
  {
    // First yield under a ball spans a node or two: the computed force
    // depends on the mesh (default scene, levels 3-6: 115, 28.7, 14.4,
    // 19.2 N against Hertz's 17.1 N).  Hertz's first yield gives the force
    // and the contact radius to judge the mesh by.
    auto        &r = results.plastic;
    const double E = results.contact_modulus;
    const double Y = plasticity.get_strength().yield_strength(top);
    // The node spacing: Q2's mid-side nodes halve it.
    const double h = results.model.element_size_under_ball / degree;
    if (!(E > 0.) || !(Y > 0.) || !(h > 0.))
      return;
    const HertzFirstYield hertz =
      hertz_first_yield(E, Y, material.poissons_ratio(top), R);
    r.first_yield_hertz_force = hertz.force;
    r.first_yield_resolution  = hertz.contact_radius / h;
    if (r.first_yield_resolution >= first_yield_min_resolution ||
        std::isnan(r.first_yield_force))
      return;
    const std::string text = first_yield_warning(r.first_yield_resolution,
                                                 r.first_yield_force,
                                                 r.first_yield_hertz_force,
                                                 /*with_time=*/true);
    results.warnings.push_back(text);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      std::cout << "  WARNING: " << text << ".\n";
    r.first_yield_time  = std::numeric_limits<double>::quiet_NaN();
    r.first_yield_force = std::numeric_limits<double>::quiet_NaN();
  }
} // namespace fgimpact
