#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_tools.h>

#include <fgimpact/time/contact_coupler.h>
#include <fgimpact/time/time_stepper.h>

#include <cmath>
#include <map>
#include <sstream>

namespace fgimpact
{
  namespace
  {
    /**
     * Central difference (velocity Verlet form) with a row-sum lumped mass
     * M_L.  Per step: u_{n+1} = u_n + dt v_n + dt^2/2 a_n, then
     * a_{n+1} = M_L^{-1} (-sum_j lambda_j g_j - K u_{n+1}) and
     * v_{n+1} = v_n + dt/2 (a_n + a_{n+1}) (the ContactCoupler moves the
     * impactor alike, with a = -F/m).  The contact forces are explicit: no
     * Newton; predict() is the position update, correct() the rest.
     */
    class CentralDifferenceStepper : public TimeStepper
    {
    public:
      CentralDifferenceStepper(
        const Parameters                           &parameters,
        const PlateModel                           &plate,
        const std::vector<types::global_dof_index> &contact_dofs,
        const double                                contact_stiffness)
        : parameters(parameters)
        , plate(plate)
        , dofs(contact_dofs)
        , k_c(contact_stiffness)
        , no_compliance(dofs.size(), dofs.size())
      {}

      void
      initialize(const bool measure_reference_costs) override
      {
        Timer timer;
        for (auto *vector :
             {&u, &v, &a, &Ku, &inverse_mass, &lumped_mass, &x, &y})
          plate.initialize_vector(*vector);
        setup_lumped_mass();

        // Stability limit 2/omega_max, omega_max^2 the largest eigenvalue
        // of M_L^{-1} (K + k_c sum_j g_j g_j^T), where k_c bounds the
        // contact's stiffening of the contact DoFs.
        const double lambda = largest_eigenvalue(k_c);
        stable_dt           = 2. / std::sqrt(lambda);

        const double requested_dt = parameters.time_step;
        if (requested_dt == 0.)
          dt = parameters.safety_factor * stable_dt;
        else
          {
            AssertThrow(requested_dt <= stable_dt,
                        ExcMessage(
                          "Time integration/Time step = " +
                          std::to_string(requested_dt * 1e6) +
                          " us exceeds the stability limit " +
                          std::to_string(stable_dt * 1e6) +
                          " us of the explicit scheme; use Time step = 0 "
                          "(automatic) or the implicit scheme."));
            dt = requested_dt;
          }

        if (measure_reference_costs)
          {
            x = 1.;
            timer.restart();
            const unsigned int n_spmv = 20;
            for (unsigned int i = 0; i < n_spmv; ++i)
              plate.stiffness_matrix().vmult(y, x);
            measured_costs.spmv = timer.wall_time() / n_spmv;
          }
        x = 0.;
        y = 0.;
      }

      double
      time_step() const override
      {
        return dt;
      }

      bool
      explicit_contact() const override
      {
        return true;
      }

      /// The positions at t_{n+1} and the first velocity half step; the
      /// contact DoFs' z displacement there (m).
      Vector<double>
      predict(const unsigned int, const double, const ContactState &) override
      {
        u.add(dt, v, 0.5 * dt * dt, a);
        v.add(0.5 * dt, a); // half step
        return plate.dof_values(u, dofs);
      }

      /// The forces at t_{n+1} do not move the plate within the step.
      const FullMatrix<double> &
      compliance() const override
      {
        return no_compliance;
      }

      /// Accelerations and the second velocity half step.
      bool
      correct(const unsigned int  step,
              const double        t,
              const ContactState &contact) override
      {
        plate.stiffness_matrix().vmult(Ku, u);
        strain = 0.5 * (u * Ku);
        a.equ(-1., Ku);
        for (unsigned int j = 0; j < dofs.size(); ++j)
          if (a.locally_owned_elements().is_element(dofs[j]))
            a(dofs[j]) -= contact.forces[j];
        a.scale(inverse_mass);
        v.add(0.5 * dt, a);

        // 1/2 v^T M_L v with the diagonal M_L: two vector operations.
        y = v;
        y.scale(lumped_mass);
        kinetic = 0.5 * (v * y);

        AssertThrow(std::isfinite(contact.alpha) && std::isfinite(strain) &&
                      std::abs(contact.alpha) < 1.,
                    ExcMessage("the explicit solution blew up (NaN, Inf or "
                               "an indentation above 1 m) at " +
                               time_step_label(step, t) +
                               "; reduce Time integration/Stable step "
                               "safety factor."));
        return true;
      }

      bool
      has_lumped_mass() const override
      {
        return true;
      }

      std::string
      description() const override
      {
        std::ostringstream s;
        s << "explicit central difference, lumped mass, stability limit "
          << stable_dt * 1e6 << " us";
        return s.str();
      }

      void
      save(CheckpointWriter &out) const override
      {
        TimeStepper::save(out);
        out.put(a);
      }

      void
      load(CheckpointReader &in) override
      {
        TimeStepper::load(in);
        in.get(a);
      }

    private:
      /// Row-sum lumping M_L = M 1 (positive for FE_Q(1) and FE_Q(2));
      /// constrained DoFs stay at rest: zero inverse mass.
      void
      setup_lumped_mass()
      {
        x = 1.;
        plate.mass_matrix().vmult(inverse_mass, x);
        // A symmetric part: the couplings to the cut's constrained DoFs
        // too, so the part's lumped mass is the whole plate's.
        if (plate.cut_mass_coupling().size() > 0)
          inverse_mass += plate.cut_mass_coupling();
        const auto &constraints = plate.get_constraints();
        for (const auto i : inverse_mass.locally_owned_elements())
          {
            AssertThrow(inverse_mass(i) > 0.,
                        ExcMessage("the lumped mass matrix has a "
                                   "non-positive entry"));
            const bool constrained = constraints.is_constrained(i);
            lumped_mass(i)         = constrained ? 0. : inverse_mass(i);
            inverse_mass(i)        = constrained ? 0. : 1. / inverse_mass(i);
          }
        inverse_mass.compress(VectorOperation::insert);
        lumped_mass.compress(VectorOperation::insert);
      }

      /// A deterministic start vector with all frequencies present, a
      /// function of the DoFs' positions and components rather than of
      /// their numbers, so that every partition (MPI rank count) finds the
      /// same time step to round-off.
      void
      fill_start_vector()
      {
        const auto &dof_handler = plate.get_dof_handler();
        std::map<types::global_dof_index, Point<3>> support;
        DoFTools::map_dofs_to_support_points(plate.get_mapping(),
                                             dof_handler,
                                             support);
        std::vector<types::global_dof_index> local_dofs(
          dof_handler.get_fe().n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(local_dofs);
              for (unsigned int k = 0; k < local_dofs.size(); ++k)
                if (x.locally_owned_elements().is_element(local_dofs[k]))
                  {
                    const Point<3>    &p = support.at(local_dofs[k]);
                    const unsigned int c =
                      dof_handler.get_fe().system_to_component_index(k).first;
                    // Positions in mm: O(1-100) arguments of the sine.
                    x(local_dofs[k]) =
                      (inverse_mass(local_dofs[k]) > 0. ?
                         std::sin(1.0 + 12.9898e3 * p[0] + 78.233e3 * p[1] +
                                  37.719e3 * p[2] + 2.3 * c) :
                         0.);
                  }
            }
        x.compress(VectorOperation::insert);
      }

      /// Power iteration with Rayleigh quotients on
      /// M_L^{-1} (K + k_c sum_j g_j g_j^T), unconstrained DoFs only.
      double
      largest_eigenvalue(const double k_c)
      {
        fill_start_vector();
        double lambda = 0;
        for (unsigned int it = 0; it < 1000; ++it)
          {
            plate.stiffness_matrix().vmult(y, x); // y = (K + k_c g g^T) x
            for (const auto dof : dofs)
              if (y.locally_owned_elements().is_element(dof))
                y(dof) += k_c * x(dof);
            Ku = x; // scratch: M_L x
            Ku.scale(lumped_mass);
            const double new_lambda = (x * y) / (x * Ku);
            y.scale(inverse_mass);
            x = y;
            x /= x.l2_norm();
            const bool converged =
              it > 20 && std::abs(new_lambda - lambda) < 1e-6 * new_lambda;
            lambda = new_lambda;
            if (converged)
              break;
          }
        Ku = 0.;
        return lambda;
      }

      const Parameters                           parameters;
      const PlateModel                          &plate;
      const std::vector<types::global_dof_index> dofs;
      const double                               k_c; // N/m
      const FullMatrix<double>                   no_compliance;
      double                                     dt = 0, stable_dt = 0;
      TrilinosWrappers::MPI::Vector Ku, inverse_mass, lumped_mass, x, y;
    };
  } // namespace



  std::unique_ptr<TimeStepper>
  create_central_difference_stepper(
    const TimeStepper::Parameters              &parameters,
    const PlateModel                           &plate,
    const std::vector<types::global_dof_index> &contact_dofs,
    const double                                contact_stiffness)
  {
    return std::make_unique<CentralDifferenceStepper>(parameters,
                                                      plate,
                                                      contact_dofs,
                                                      contact_stiffness);
  }
} // namespace fgimpact
