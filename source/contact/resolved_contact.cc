#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <fgimpact/contact/complementarity.h>
#include <fgimpact/contact/contact_law.h>
#include <fgimpact/contact/resolved_contact.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

namespace fgimpact
{
  ResolvedSphereContact::ResolvedSphereContact(
    const PlateModel                             &plate,
    const double                                  sphere_radius,
    const Point<2>                               &impact_point,
    const double                                  candidate_radius,
    const std::shared_ptr<const ImpactorProfile> &surface,
    const double                                  plate_modulus,
    const bool                                    massless_candidates,
    const double                                  ball_modulus)
    : plate(plate)
    , impact_point(impact_point)
    , R(sphere_radius)
    , surface(surface)
    // Hertz's E* of plate and ball (Pa).
    , reference_modulus(
        combined_indentation_modulus(plate_modulus, ball_modulus))
    , massless_candidates(massless_candidates)
    , ball_modulus(ball_modulus)
    , candidate_radius(std::min(candidate_radius, surface->extent()))
    , share(plate.get_geometry().share())
  {
    build_candidates();
  }



  bool
  ResolvedSphereContact::grow_candidates()
  {
    if (candidate_radius >= surface->extent())
      return false; // the whole surface is a candidate already
    candidate_radius = std::min(1.5 * candidate_radius, surface->extent());
    build_candidates();
    return true;
  }



  std::size_t
  ResolvedSphereContact::n_likely_active() const
  {
    // radii is sorted (collect_candidates()).
    const auto end =
      std::upper_bound(radii.begin(),
                       radii.end(),
                       candidate_radius / candidate_radius_factor);
    return std::max<std::size_t>(1, end - radii.begin());
  }



  void
  ResolvedSphereContact::save(CheckpointWriter &out) const
  {
    out.put(candidate_radius);
    out.put(active);
  }



  void
  ResolvedSphereContact::load(CheckpointReader &in)
  {
    double            radius = 0;
    std::vector<bool> stored_active;
    in.get(radius);
    in.get(stored_active);
    AssertThrow(radius == candidate_radius &&
                  stored_active.size() == active.size(),
                ExcMessage("the checkpoint's contact candidate set does not "
                           "match this set-up"));
    active = stored_active;
  }



  void
  ResolvedSphereContact::build_candidates()
  {
    dofs.clear();
    radii.clear();
    points.clear();
    collect_candidates(plate, impact_point, candidate_radius);
    compute_areas(plate);
    profile.resize(radii.size());
    for (unsigned int j = 0; j < radii.size(); ++j)
      profile[j] = surface->height(radii[j]);
    active.assign(dofs.size(), false);
    multiplicity.resize(points.size());
    for (unsigned int j = 0; j < points.size(); ++j)
      multiplicity[j] = plate.get_geometry().multiplicity(points[j]);
    compute_ball_compliance();
  }



  void
  ResolvedSphereContact::compute_ball_compliance()
  {
    ball_matrix.reinit(0, 0);
    if (!std::isfinite(ball_modulus))
      return;
    // Boussinesq: a force F on a half-space of modulus Q = E/(1 - nu^2)
    // moves its surface by F/(pi Q d) at distance d; a uniform pressure on
    // a disc of radius rho moves its centre by 2 F/(pi Q rho).  The ball's
    // surface near the contact is such a half-space (a << R).  A candidate
    // of a symmetric part stands for multiplicity_j nodes of the whole
    // plate, its mirror images, each carrying lambda_j / (share m_j) on a
    // tributary area A_j / (share m_j).
    const auto  &geometry  = plate.get_geometry();
    const double centre[2] = {0.5 * geometry.length(), 0.5 * geometry.width()};
    const double tolerance = 1e-9 * geometry.length();
    const unsigned int m   = points.size();
    ball_matrix.reinit(m, m);
    for (unsigned int j = 0; j < m; ++j)
      {
        std::vector<Point<2>> images{Point<2>(points[j][0], points[j][1])};
        for (unsigned int d = 0; d < 2; ++d)
          if (geometry.is_cut(d) &&
              std::abs(points[j][d] - centre[d]) > tolerance)
            for (unsigned int k = 0, n = images.size(); k < n; ++k)
              {
                Point<2> image = images[k];
                image[d]       = 2. * centre[d] - image[d];
                images.push_back(image);
              }
        const double whole = 1. / (share * multiplicity[j]);
        const double rho   = std::sqrt(whole * areas[j] / numbers::PI);
        for (unsigned int i = 0; i < m; ++i)
          {
            const Point<2> x(points[i][0], points[i][1]);
            double         sum = 0;
            for (const auto &image : images)
              {
                const double d = x.distance(image);
                sum += (d > tolerance ? 1. / d : 2. / rho);
              }
            ball_matrix(i, j) = whole * sum / (numbers::PI * ball_modulus);
          }
      }
  }



  double
  ResolvedSphereContact::potential(const ContactState &state) const
  {
    if (ball_matrix.m() == 0 || state.forces.size() != ball_matrix.m())
      return 0.;
    const Vector<double> lambda(state.forces.begin(), state.forces.end());
    return 0.5 * ball_matrix.matrix_norm_square(lambda);
  }



  void
  ResolvedSphereContact::collect_candidates(const PlateModel &plate,
                                            const Point<2>   &impact_point,
                                            const double      candidate_radius)
  {
    const auto  &dof_handler = plate.get_dof_handler();
    const auto  &constraints = plate.get_constraints();
    const double h           = plate.get_geometry().thickness();
    std::map<types::global_dof_index, Point<3>> support;
    DoFTools::map_dofs_to_support_points(plate.get_mapping(),
                                         dof_handler,
                                         support);
    // (r, x, y, dof) of this rank's owned, unconstrained top-face z DoFs
    // inside the candidate radius; sorted the same way on every partition.
    using Candidate = std::array<double, 4>;
    std::vector<Candidate>               local_z;
    std::set<types::global_dof_index>    seen;
    const auto                          &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        {
          cell->get_dof_indices(cell_dofs);
          for (unsigned int k = 0; k < cell_dofs.size(); ++k)
            {
              const types::global_dof_index dof = cell_dofs[k];
              if (fe.system_to_component_index(k).first != 2 ||
                  !plate.locally_owned_dofs().is_element(dof) ||
                  constraints.is_constrained(dof) || !seen.insert(dof).second)
                continue;
              const Point<3> &p = support.at(dof);
              const double    r = Point<2>(p[0], p[1]).distance(impact_point);
              if (std::abs(p[2] - h) <= 1e-9 * h && r <= candidate_radius)
                local_z.push_back({{r, p[0], p[1], static_cast<double>(dof)}});
            }
        }

    std::vector<Candidate> all;
    for (const auto &part :
         Utilities::MPI::all_gather(plate.get_mpi_communicator(), local_z))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end());
    AssertThrow(!all.empty(),
                ExcMessage(
                  "Contact/Candidate radius: no unconstrained top-face "
                  "node lies within " +
                  std::to_string(candidate_radius * 1e3) +
                  " mm of the impact point."));
    for (const auto &c : all)
      {
        dofs.push_back(static_cast<types::global_dof_index>(c[3]));
        radii.push_back(c[0]);
        points.emplace_back(c[1], c[2], h);
      }
    smallest_spacing = (all.size() > 1 ? all[1][0] : 0.);
  }



  void
  ResolvedSphereContact::compute_areas(const PlateModel &plate)
  {
    // A_j = int_top N_j dA, assembled like a unit pressure load (through
    // the constraints, so hanging nodes pass their share to their masters).
    const auto                   &fe = plate.get_fe();
    const QGauss<2>               quadrature(fe.degree + 1);
    FEFaceValues<3>               fe_face(plate.get_mapping(),
                            fe,
                            quadrature,
                            update_values | update_JxW_values);
    TrilinosWrappers::MPI::Vector area;
    plate.initialize_vector(area);
    Vector<double>                       cell_area(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() && cell->at_boundary())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && face->boundary_id() == 5)
            {
              fe_face.reinit(cell, face);
              cell_area = 0;
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                  if (fe.system_to_component_index(i).first == 2)
                    cell_area[i] +=
                      fe_face.shape_value_component(i, q, 2) * fe_face.JxW(q);
              cell->get_dof_indices(cell_dofs);
              plate.get_constraints().distribute_local_to_global(cell_area,
                                                                 cell_dofs,
                                                                 area);
            }
    area.compress(VectorOperation::add);
    const Vector<double> values = plate.dof_values(area, dofs);
    areas.assign(values.begin(), values.end());
  }



  void
  ResolvedSphereContact::solve_implicit(const Vector<double>     &u_free,
                                        const FullMatrix<double> &C,
                                        const ColumnRequest      &columns,
                                        const double              w_free,
                                        const double              c_b,
                                        const NewtonControl &,
                                        ContactState &state) const
  {
    const unsigned int m = dofs.size();
    // A = C + c_b 1 1^T (+ H), filled in the valid columns of C only and
    // as more become valid; the others hold zeros or an earlier step's
    // values, finite as solve_lcp needs.  Kept between steps: allocating
    // and zeroing the m x m matrix every step was 5.8 MB at level 7.
    if (delassus.m() != m)
      delassus.reinit(m, m);
    FullMatrix<double> &A = delassus;
    const auto fill = [&](const unsigned int first, const unsigned int last) {
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = first; j < last; ++j)
          {
            A(i, j) = C(i, j) + c_b;
            if (ball_matrix.m() == m)
              A(i, j) += 1. * ball_matrix(i, j);
          }
    };
    unsigned int valid = (columns ? columns(0) : m);
    fill(0, valid);
    const ColumnRequest request = [&](const unsigned int n) {
      const unsigned int now = columns(n);
      fill(valid, now);
      valid = now;
      return valid;
    };
    Vector<double> q(m);
    for (unsigned int i = 0; i < m; ++i)
      q[i] = profile[i] - w_free - u_free[i];
    Vector<double>      lambda;
    const LcpStatistics statistics =
      solve_lcp(A, q, lambda, active, 50, columns ? request : ColumnRequest());
    // Not solved: the time stepper reports the step (as for Newton).
    state.newton_iterations    = statistics.converged ?
                                   statistics.iterations :
                                   numbers::invalid_unsigned_int;
    state.used_lcp_fallback    = statistics.used_fallback;
    state.residual_penetration = statistics.penetration;
    state.forces.assign(lambda.begin(), lambda.end());
    state.force = std::accumulate(lambda.begin(), lambda.end(), 0.);
    describe_solution(A, q, lambda, u_free, C, state);
  }



  void
  ResolvedSphereContact::describe_solution(const FullMatrix<double> &A,
                                           const Vector<double>     &q,
                                           const Vector<double>     &lambda,
                                           const Vector<double>     &u_free,
                                           const FullMatrix<double> &C,
                                           ContactState &state) const
  {
    // Gaps and the contact's extent.
    const unsigned int m = lambda.size();
    Vector<double>     g(m);
    A.vmult(g, lambda);
    g += q;
    const double smallest_gap = describe_extent(lambda, g, state);
    state.node_displacement   = u_free[0];
    for (unsigned int k = 0; k < m; ++k)
      state.node_displacement -= C(0, k) * lambda[k];
    // The indentation column: while in contact the half-space Hertz
    // approach (F/K)^{2/3}, K = 4/3 Q_ref sqrt(R), after separation minus
    // the smallest gap; continuous through 0, so the monitor's zero
    // crossing gives the separation time.  F is the whole plate's force
    // (the forces here are the symmetric part's share of it).
    const double K = 4. / 3. * reference_modulus * std::sqrt(R);
    state.alpha =
      (state.force > 0. ? std::pow(state.force / share / K, 2. / 3.) :
                          -std::max(smallest_gap, 0.));
  }



  double
  ResolvedSphereContact::describe_extent(const Vector<double> &lambda,
                                         const Vector<double> &g,
                                         ContactState         &state) const
  {
    const unsigned int m = dofs.size();
    state.n_active       = 0;
    state.contact_radius = 0;
    state.max_pressure   = 0;
    double smallest_gap  = std::numeric_limits<double>::max();
    for (unsigned int j = 0; j < m; ++j)
      {
        smallest_gap = std::min(smallest_gap, g[j]);
        if (lambda[j] > 0.)
          {
            state.n_active += multiplicity[j];
            state.max_pressure =
              std::max(state.max_pressure, lambda[j] / areas[j]);
          }
      }
    // The farthest node in contact (the discrete edge lies between it and
    // the next node out; the circle of the active nodes' area would
    // overestimate it by about half an element).
    double farthest = 0;
    for (unsigned int j = 0; j < m; ++j)
      if (lambda[j] > 0.)
        farthest = std::max(farthest, radii[j]);
    state.contact_radius = farthest;
    // The candidate set must contain the contact circle with a ring of
    // inactive nodes to spare; otherwise the solution is that of a smaller
    // sphere cap.
    state.candidates_exhausted =
      (state.n_active > 0 && farthest >= reach() - 0.5 * smallest_spacing);
    return smallest_gap;
  }



  void
  ResolvedSphereContact::evaluate_explicit(const Vector<double> &,
                                           const double,
                                           ContactState &) const
  {
    AssertThrow(false,
                ExcMessage("Contact/Model = resolved sphere needs Time "
                           "integration/Scheme = implicit."));
  }



  double
  ResolvedSphereContact::stiffness_bound(const double, const double) const
  {
    return std::numeric_limits<double>::infinity();
  }



  std::string
  ResolvedSphereContact::description() const
  {
    std::ostringstream s;
    s << "resolved " << (ball_matrix.m() > 0 ? "elastic" : "rigid")
      << " sphere, R = " << R * 1e3 << " mm, " << surface->name() << " gap, "
      << dofs.size() << " candidate nodes within " << reach() * 1e3
      << " mm (nearest neighbour " << smallest_spacing * 1e3 << " mm)";
    return s.str();
  }



  std::string
  ResolvedSphereContact::warning() const
  {
    if (radii.front() <= 1e-9 * R)
      return "";
    std::ostringstream s;
    s << "note: no node lies at the impact point; the nearest is "
      << radii.front() * 1e3 << " mm away";
    return s.str();
  }



  ContactConstants
  ResolvedSphereContact::constants() const
  {
    ContactConstants c;
    c.contact_modulus     = reference_modulus;
    c.contact_stiffness   = 4. / 3. * reference_modulus * std::sqrt(R);
    c.contact_node_offset = radii.front();
    c.contact_node_owner  = 0;
    c.n_contact_candidates =
      std::accumulate(multiplicity.begin(), multiplicity.end(), 0u);
    return c;
  }
} // namespace fgimpact
