// Newmark (beta = 1/4, gamma = 1/2) on the undamped oscillator
// m u'' + k u = f0 sin(Omega t), u(0) = u0, u'(0) = v0, against its exact
// solution, with the observed order of convergence; and the vector update
// against the scalar one.

#include <deal.II/lac/vector.h>

#include <fgimpact/time/newmark.h>
#include <fgimpact/time/time_stepper.h>

#include <cmath>
#include <cstdio>

namespace fgimpact_unit_tests::newmark_oscillator
{

  using namespace fgimpact;

  namespace
  {
    const double m = 2., k = 8e4, f0 = 30., Omega = 90.; // omega = 200 rad/s
    const double u0 = 1e-3, v0 = 0.1;
    const double omega = std::sqrt(k / m);

    double
    exact(const double t)
    {
      // particular solution F sin(Omega t) with F = f0/(k - m Omega^2)
      const double F = f0 / (k - m * Omega * Omega);
      return u0 * std::cos(omega * t) +
             (v0 - F * Omega) / omega * std::sin(omega * t) +
             F * std::sin(Omega * t);
    }

    /// Returns the max error of u over [0, T].
    double
    run(const double dt, const double T)
    {
      const NewmarkIntegrator newmark(NewmarkIntegrator::Parameters(), dt);
      TimeStepper::Parameters time_control;
      time_control.end_time = T;
      double u = u0, v = v0,
             a         = (0. - k * u0) / m; // a(0) from the equation, f(0) = 0
      double max_error = 0;
      for (unsigned int n = 1; n <= time_control.n_steps(dt); ++n)
        {
          const double t = n * dt;
          const double u_new =
            (f0 * std::sin(Omega * t) + m * newmark.predictor(u, v, a)) /
            (k + newmark.mass_factor() * m);
          newmark.update(u_new, u, v, a);
          max_error = std::max(max_error, std::abs(u - exact(t)));
        }
      return max_error;
    }
  } // namespace

  int
  test_main(int, char **)
  {
    const double T = 2. * 2. * M_PI / omega; // two periods
    std::printf("dt/period   max error/u0   observed order\n");
    double previous = 0;
    bool   ok       = true;
    for (unsigned int level = 0; level < 5; ++level)
      {
        const double dt    = 2. * M_PI / omega / (20. * std::pow(2., level));
        const double error = run(dt, T);
        if (level == 0)
          std::printf("1/%-8.0f  %.1e\n",
                      20. * std::pow(2., level),
                      error / u0);
        else
          {
            const double order = std::log2(previous / error);
            ok                 = ok && std::abs(order - 2.) < 0.05;
            std::printf("1/%-8.0f  %.1e        %.2f\n",
                        20. * std::pow(2., level),
                        error / u0,
                        order);
          }
        previous = error;
      }
    std::printf("second order: %s\n", ok ? "yes" : "NO");

    // Vector version against the scalar one on two uncoupled oscillators.
    const NewmarkIntegrator newmark(NewmarkIntegrator::Parameters(), 1e-3);
    dealii::Vector<double>  u(2), v(2), a(2), r(2), u_new(2);
    double us[2] = {1., -2.}, vs[2] = {0.5, 3.}, as[2] = {-4., 1.};
    for (unsigned int i = 0; i < 2; ++i)
      u(i) = us[i], v(i) = vs[i], a(i) = as[i];
    double diff = 0;
    for (unsigned int n = 0; n < 50; ++n)
      {
        newmark.predictor(u, v, a, r);
        for (unsigned int i = 0; i < 2; ++i)
          {
            const double kk     = (i + 1) * 1e3;
            u_new(i)            = r(i) / (kk + newmark.mass_factor());
            const double us_new = newmark.predictor(us[i], vs[i], as[i]) /
                                  (kk + newmark.mass_factor());
            newmark.update(us_new, us[i], vs[i], as[i]);
          }
        newmark.update(u_new, u, v, a);
        for (unsigned int i = 0; i < 2; ++i)
          diff = std::max({diff,
                           std::abs(u(i) - us[i]),
                           std::abs(v(i) - vs[i]) * 1e-3,
                           std::abs(a(i) - as[i]) * 1e-6});
      }
    const bool same = diff < 1e-12;
    std::printf("vector update equals scalar update: %s\n",
                same ? "yes" : "NO");
    return ok && same ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::newmark_oscillator
