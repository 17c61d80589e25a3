#ifndef fgimpact_newmark_h
#define fgimpact_newmark_h

#include <deal.II/base/config.h>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The Newmark family for M a + K u = f(t), written in displacement form.
   * It knows nothing about finite elements (ExaDG's way): it works on any
   * vector type with deal.II's vector interface (equ, add, sadd) and on plain
   * doubles, so the plate and the impactor's scalar unknown use the same
   * formulas, and it can be unit tested on a one-degree-of-freedom oscillator.
   *
   * With the predictor
   *   r_n = a0 u_n + a1 v_n + a2 a_n,
   *   a0 = 1/(beta dt^2), a1 = 1/(beta dt), a2 = 1/(2 beta) - 1,
   * the step is (K + a0 M) u_{n+1} = f_{n+1} + M r_n, and then
   *   a_{n+1} = a0 (u_{n+1} - u_n) - a1 v_n - a2 a_n,
   *   v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1}).
   * beta = 1/4, gamma = 1/2 is the average acceleration (trapezoidal) rule:
   * unconditionally stable, second order, energy conserving for linear
   * systems.
   */
  class NewmarkIntegrator
  {
  public:
    /// Newmark's two parameters (dimensionless). The time step and the
    /// end time are time control (TimeStepper::Parameters), not part of
    /// the scheme; the ParameterHandler entries are declared there.
    struct Parameters
    {
      double beta  = 0.25;
      double gamma = 0.5;
    };

    /// The scheme with time step dt (s).
    NewmarkIntegrator(const Parameters &parameters, const double dt);

    double
    time_step() const
    {
      return dt;
    }
    double
    beta() const
    {
      return parameters.beta;
    }
    double
    gamma() const
    {
      return parameters.gamma;
    }

    /// The factor a0 = 1/(beta dt^2) of M in the effective matrix K + a0 M.
    double
    mass_factor() const
    {
      return a0;
    }

    /// The predictor r = a0 u + a1 v + a2 a (scalar version).
    double
    predictor(const double u, const double v, const double a) const
    {
      return a0 * u + a1 * v + a2 * a;
    }

    /// The predictor r = a0 u + a1 v + a2 a (vector version).
    template <typename VectorType>
    void
    predictor(const VectorType &u,
              const VectorType &v,
              const VectorType &a,
              VectorType       &r) const
    {
      r.equ(a0, u);
      r.add(a1, v, a2, a);
    }

    /**
     * Given the new displacement u_new, overwrite u, v, a at t_n with their
     * values at t_{n+1} (scalar version).
     */
    void
    update(const double u_new, double &u, double &v, double &a) const
    {
      const double a_new = a0 * (u_new - u) - a1 * v - a2 * a;
      v += dt * ((1. - parameters.gamma) * a + parameters.gamma * a_new);
      a = a_new;
      u = u_new;
    }

    /// Vector version of update().  No temporaries are allocated.
    template <typename VectorType>
    void
    update(const VectorType &u_new,
           VectorType       &u,
           VectorType       &v,
           VectorType       &a) const
    {
      // v <- v + dt (1-gamma) a, using a_n before it is overwritten
      v.add(dt * (1. - parameters.gamma), a);
      // a <- a0 (u_new - u) - a1 v_n - a2 a_n; v_n = v - dt(1-gamma) a_n
      a.sadd(-a2 + a1 * dt * (1. - parameters.gamma), -a1, v);
      a.add(a0, u_new, -a0, u);
      // v <- v + dt gamma a_new
      v.add(dt * parameters.gamma, a);
      u = u_new;
    }

  private:
    const Parameters parameters;
    const double     dt;
    const double     a0, a1, a2;
  };
} // namespace fgimpact

#endif
