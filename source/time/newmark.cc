#include <deal.II/base/exceptions.h>

#include <fgimpact/time/newmark.h>

#include <cmath>

namespace fgimpact
{
  NewmarkIntegrator::NewmarkIntegrator(const Parameters &parameters,
                                       const double      dt)
    : parameters(parameters)
    , dt(dt)
    , a0(1. / (parameters.beta * dt * dt))
    , a1(1. / (parameters.beta * dt))
    , a2(1. / (2. * parameters.beta) - 1.)
  {}
} // namespace fgimpact
