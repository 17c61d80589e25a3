#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_generator.h>

#include <fgimpact/base/parameter_table.h>
#include <fgimpact/base/selection.h>
#include <fgimpact/plate/geometry.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace fgimpact
{
  namespace
  {
    /// The names of a face's support (Boundary conditions/*).
    const SelectionTable<SideSupport> &
    support_names()
    {
      static const SelectionTable<SideSupport> names = {
        {"simply supported", SideSupport::simply_supported},
        {"clamped", SideSupport::clamped},
        {"free", SideSupport::free}};
      return names;
    }

    /// The names of Geometry/Symmetry.
    const SelectionTable<Symmetry> &
    symmetry_names()
    {
      static const SelectionTable<Symmetry> names = {
        {"auto", Symmetry::automatic},
        {"none", Symmetry::none},
        {"half", Symmetry::half},
        {"quarter", Symmetry::quarter}};
      return names;
    }
  } // namespace


  const std::array<std::string, 4> PlateGeometry::side_names = {
    {"Face x min", "Face x max", "Face y min", "Face y max"}};



  namespace
  {
    /// Subsection "Boundary conditions": the supports of the six faces.
    void
    declare_supports(ParameterHandler &prm)
    {
      const PlateGeometry::Parameters defaults;
      prm.enter_subsection("Boundary conditions");
      {
        for (unsigned int f = 0; f < 4; ++f)
          prm.declare_entry(
            PlateGeometry::side_names[f],
            support_names().name(defaults.supports[f]),
            support_names().pattern(),
            "Support of this whole side face (x min: x = 0, x max: x = a, y "
            "min: y = 0, y max: y = b). simply supported (Eq. 2.15): "
            "w = 0 and the tangential in-plane displacement = 0 on the face "
            "(v on x = const, u on y = const); the normal in-plane "
            "displacement is free. clamped: u = v = w = 0. free: traction "
            "free.");
        prm.declare_entry(
          "Face z min",
          support_names().name(defaults.bottom_support),
          support_names().pattern(),
          "Support of the bottom face z = 0: free (a plate), clamped "
          "(u = v = w = 0: bonded to a rigid base) or simply supported "
          "(w = 0 only: resting on a frictionless rigid base, which can pull "
          "as well as push).");
        prm.declare_entry(
          "In-plane edges",
          defaults.immovable_edges ? "immovable" : "movable",
          Patterns::Selection("movable|immovable"),
          "The in-plane displacement normal to a simply supported side. "
          "movable: free (Eq. 2.15), so a uniform heating expands the plate "
          "between the sides. immovable: its mean over the thickness "
          "vanishes on every line of nodes through the thickness (a "
          "distributed coupling: the side may rotate about its mid-plane, "
          "not translate), so a uniform Delta T gives sigma = -E alpha "
          "Delta T / (1 - nu) in a homogeneous plate, as in plate theory "
          "(doc/thermal.md). A clamped side holds every component on the "
          "whole face, immovable either way.");
      }
      prm.leave_subsection();
    }
  } // namespace



  namespace
  {
    /// Geometry/Contact refinement levels (in the subsection already
    /// entered): `auto` or a number, two members.
    void
    declare_refinement_levels(ParameterHandler &prm)
    {
      const PlateGeometry::Parameters defaults;
      prm.declare_entry(
        "Contact refinement levels",
        defaults.contact_refinement_auto ?
          std::string("auto") :
          prm_string(defaults.contact_refinement_levels),
        Patterns::Selection("auto|0|1|2|3|4|5|6|7|8|9|10|11|12"),
        "Times the cells near the impact point are split in two in each "
        "direction (graded, with hanging-node constraints): the element "
        "size under the ball is the base size / 2^levels. 0 = uniform "
        "mesh. auto = 0 for the Hertz-law contact models; for Contact/Model "
        "= resolved sphere and Static/Load = sphere the fewest levels that "
        "put 4 element sizes across the half-space Hertz estimate of the "
        "largest contact radius (doc/contact.md: about 1 % in the peak "
        "force); the log gives the choice.");
    }
  } // namespace



  namespace
  {
    /// The entries of PlateGeometry::Parameters that set a member as they
    /// stand.
    const ParameterTable<PlateGeometry::Parameters> &
    geometry_table()
    {
      using P                              = PlateGeometry::Parameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add("Length a",
              &P::length,
              Patterns::Double(1e-6, 1e3),
              "Plate length a along x. Unit: m.");
        t.add("Width b",
              &P::width,
              Patterns::Double(1e-6, 1e3),
              "Plate width b along y. Unit: m.");
        t.add("Thickness h",
              &P::thickness,
              Patterns::Double(1e-6, 1e3),
              "Plate thickness h along z; z = 0 is the (ceramic) "
              "bottom face, z = h the (metal) top face that the "
              "impactor strikes. Unit: m.");
        t.add("Subdivisions x",
              &P::subdivisions_x,
              Patterns::Integer(1, 100000),
              "Number of elements along x. Even, so that a node "
              "lies under a central impact.");
        t.add("Subdivisions y",
              &P::subdivisions_y,
              Patterns::Integer(1, 100000),
              "Number of elements along y.");
        t.add("Subdivisions z",
              &P::subdivisions_z,
              Patterns::Integer(1, 100000),
              "Number of elements through the thickness.");
        t.add(
          "Contact refinement radius",
          &P::contact_refinement_radius,
          Patterns::Double(0., 10.),
          "Radius of the core around the impact point that gets the finest "
          "cells; each coarser level reaches two of its cells further. 0 = "
          "automatic: 1.5 times the largest contact radius of the ball on a "
          "half-space of the top face's modulus. Unit: m.");
        t.add(
          "Symmetry",
          &P::symmetry,
          symmetry_names(),
          "Model a part of a symmetric scene: quarter = the part x <= a/2, "
          "y <= b/2 with u_x = 0 on x = a/2 and u_y = 0 on y = b/2; half = "
          "the part x <= a/2 (or y <= b/2 if only that plane is a symmetry "
          "plane); none = the whole plate; auto = the smallest part the scene "
          "allows (none, with a log line, if none). A plane is a symmetry "
          "plane if the impact point lies on it, the supports of the two "
          "faces parallel to it are equal and the subdivisions across it are "
          "even; modal problems and explicit runs with the automatic time "
          "step (Time step = 0) are never cut. history.csv and summary.txt "
          "report the whole plate; the VTU files hold the whole plate too "
          "(Output/Mirror symmetric part = true) or the part.");
        return t;
      }();
      return table;
    }
  } // namespace



  namespace
  {
    /// The adaptive mesh's entries of Geometry.
    const ParameterTable<PlateGeometry::Parameters> &
    adaptive_table()
    {
      using P                              = PlateGeometry::Parameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add("Adaptive refinement cycles",
              &P::adaptive_cycles,
              Patterns::Integer(0, 6),
              "Pilot runs that adapt the mesh before the run whose "
              "outputs are written (Contact/Model = resolved sphere, "
              "Problem type = impact): each runs the whole impact on the "
              "mesh so far and integrates over time Kelly's indicator (the "
              "jump of E(z) du/dn across the cells' faces); the Adaptive "
              "refinement fraction of the cells with the largest value are "
              "split in eight (hanging nodes) for the next run. The pilot "
              "runs write history.csv and summary.txt into "
              "Output/Directory/convergence/adaptive_cycle_K, and "
              "adaptation.csv lists "
              "every run. 0 = none.");
        t.add("Adaptive refinement fraction",
              &P::adaptive_fraction,
              Patterns::Double(0.01, 1.),
              "The fraction of the cells (by count) each adaptive cycle "
              "refines: each cycle adds about 7 times this fraction of the "
              "cells. 1 = uniform refinement.");
        t.add("Adaptive refinement estimate",
              &P::adaptive_estimate,
              Patterns::Bool(),
              "With Adaptive refinement cycles > 0: bound the final run's "
              "error by three more runs into Output/Directory/convergence, "
              "one per source: adaptive_check_contact_zone (the final mesh "
              "with the cells one more contact level would split split), "
              "adaptive_check_rest_of_plate (every other cell split: about "
              "8 times the DoFs, the costliest), adaptive_check_time_step "
              "(half the time step). Each source's relative estimate is a "
              "two-grid grid convergence index of the coarser run, "
              "3 |q_check - q| r^p / (r^p - 1) / |q| (p = 1 for the mesh, 2 "
              "for Newmark's time step); summary.txt gets each headline "
              "number's and each probe's peak stress's KEY_error_estimate "
              "(their sum) and its three parts, adaptive_estimate.csv the "
              "check runs.");
        return t;
      }();
      return table;
    }
  } // namespace



  void
  PlateGeometry::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      geometry_table().declare(prm);
      adaptive_table().declare(prm);
      declare_refinement_levels(prm);
    }
    prm.leave_subsection();

    declare_supports(prm);
  }



  void
  PlateGeometry::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      geometry_table().parse(prm, *this);
      adaptive_table().parse(prm, *this);
      const std::string levels = prm.get("Contact refinement levels");
      contact_refinement_auto  = (levels == "auto");
      contact_refinement_levels =
        contact_refinement_auto ? 0 : Utilities::string_to_int(levels);
    }
    prm.leave_subsection();

    prm.enter_subsection("Boundary conditions");
    {
      for (unsigned int f = 0; f < 4; ++f)
        supports[f] = support_names().value(prm.get(side_names[f]));
      bottom_support  = support_names().value(prm.get("Face z min"));
      immovable_edges = (prm.get("In-plane edges") == "immovable");
    }
    prm.leave_subsection();
  }



  PlateGeometry::PlateGeometry(const Parameters          &parameters,
                               const std::array<bool, 2> &cut)
    : parameters(parameters)
    , cut(cut)
  {}



  void
  PlateGeometry::create_triangulation(Triangulation<3> &triangulation) const
  {
    unsigned int k = 0;
    // The part modelled: the cut directions have half the extent and half
    // the (even) subdivisions, the same cells as the whole plate's there.
    const bool                cut_x = cut[0], cut_y = cut[1];
    std::vector<unsigned int> coarse{parameters.subdivisions_x /
                                       (cut_x ? 2 : 1),
                                     parameters.subdivisions_y /
                                       (cut_y ? 2 : 1),
                                     parameters.subdivisions_z};
    while (coarse[0] % 2 == 0 && coarse[1] % 2 == 0 && coarse[2] % 2 == 0)
      {
        for (auto &n : coarse)
          n /= 2;
        ++k;
      }
    // Boundary ids (colorize) pass to the children of refined faces.
    GridGenerator::subdivided_hyper_rectangle(
      triangulation,
      coarse,
      Point<3>(),
      Point<3>(cut_x ? 0.5 * parameters.length : parameters.length,
               cut_y ? 0.5 * parameters.width : parameters.width,
               parameters.thickness),
      /*colorize=*/true);
    triangulation.refine_global(k);
  }



  namespace
  {
    /// Whether refine_locally() splits cell in a pass whose finest level
    /// is `finest`: a cell of that level whose distance from the centre is
    /// below radius + 2 h_cell.
    bool
    in_contact_core(const Triangulation<3>::active_cell_iterator &cell,
                    const LocalRefinement                        &refinement,
                    const unsigned int                            finest)
    {
      if (static_cast<unsigned int>(cell->level()) != finest)
        return false;
      // Distance from the centre to the brick (axis-aligned).
      const BoundingBox<3> box = cell->bounding_box();
      double               d2  = 0;
      for (unsigned int d = 0; d < 3; ++d)
        {
          const double c = refinement.centre[d];
          const double dd =
            std::max({box.lower_bound(d) - c, 0., c - box.upper_bound(d)});
          d2 += dd * dd;
        }
      const double h = cell->extent_in_direction(0);
      return std::sqrt(d2) < refinement.radius + 2. * h;
    }
  } // namespace



  void
  PlateGeometry::refine_locally(Triangulation<3>      &triangulation,
                                const LocalRefinement &refinement)
  {
    for (unsigned int pass = 0; pass < refinement.levels; ++pass)
      {
        const unsigned int finest = triangulation.n_global_levels() - 1;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() &&
              in_contact_core(cell, refinement, finest))
            cell->set_refine_flag();
        triangulation.execute_coarsening_and_refinement();
      }
  }



  void
  PlateGeometry::split_cells(Triangulation<3>      &triangulation,
                             const LocalRefinement &refinement,
                             const MeshSplit        split)
  {
    if (split == MeshSplit::none)
      return;
    const unsigned int finest = triangulation.n_global_levels() - 1;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() &&
          in_contact_core(cell, refinement, finest) ==
            (split == MeshSplit::contact_zone))
        cell->set_refine_flag();
    triangulation.execute_coarsening_and_refinement();
  }



  void
  PlateGeometry::refine_cells(
    Triangulation<3>                            &triangulation,
    const std::vector<std::vector<std::string>> &cycles)
  {
    for (const auto &ids : cycles)
      {
        const std::set<std::string> refine(ids.begin(), ids.end());
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() &&
              refine.count(cell->id().to_string()) > 0)
            cell->set_refine_flag();
        triangulation.execute_coarsening_and_refinement();
      }
  }



  Point<3>
  PlateGeometry::centre(const double z) const
  {
    return Point<3>(parameters.length / 2, parameters.width / 2, z);
  }



  unsigned int
  PlateGeometry::multiplicity(const Point<3> &p) const
  {
    const double centre[2] = {0.5 * parameters.length, 0.5 * parameters.width};
    unsigned int n         = 1;
    for (unsigned int d = 0; d < 2; ++d)
      if (cut[d] && std::abs(p[d] - centre[d]) > 1e-9 * parameters.length)
        n *= 2;
    return n;
  }



  bool
  PlateGeometry::contains(const Point<3> &p) const
  {
    const double tol = 1e-12 * parameters.length;
    return p[0] >= -tol && p[0] <= parameters.length + tol && p[1] >= -tol &&
           p[1] <= parameters.width + tol && p[2] >= -tol &&
           p[2] <= parameters.thickness + tol;
  }
} // namespace fgimpact
