// Small-strain J2 plasticity, radial return (plasticity.h).

#include <fgimpact/material/plasticity.h>

#include <cmath>

namespace fgimpact
{
  PlasticUpdate
  J2Plasticity::update(const double                 lambda,
                       const double                 mu,
                       const double                 Y,
                       const double                 H,
                       const SymmetricTensor<2, 3> &strain,
                       const PlasticState          &old_state,
                       const bool                   with_tangent)
  {
    const double                kappa = lambda + 2. / 3. * mu; // bulk
    const SymmetricTensor<2, 3> one   = unit_symmetric_tensor<3>();
    SymmetricTensor<4, 3>       I_dev, one_one;
    if (with_tangent)
      {
        I_dev   = deviator_tensor<3>();
        one_one = outer_product(one, one);
      }

    PlasticUpdate result;
    result.state = old_state;
    const SymmetricTensor<2, 3> elastic_strain =
      strain - old_state.plastic_strain;
    const SymmetricTensor<2, 3> s_trial    = 2. * mu * deviator(elastic_strain);
    const double                norm_trial = s_trial.norm();
    const double yield_stress = Y + H * old_state.equivalent_plastic_strain;
    // f = |s| - sqrt(2/3) sigma_y (Box 3.1).
    const double f_trial  = norm_trial - std::sqrt(2. / 3.) * yield_stress;
    const double pressure = kappa * trace(elastic_strain);
    if (!(f_trial > 0.))
      {
        result.stress = pressure * one + s_trial;
        if (with_tangent)
          result.tangent = kappa * one_one + 2. * mu * I_dev;
        return result;
      }
    // Linear hardening: the consistency condition is linear in the
    // multiplier, so the return is exact in one step.
    const double                delta_gamma = f_trial / (2. * mu + 2. / 3. * H);
    const SymmetricTensor<2, 3> n           = s_trial / norm_trial;
    result.yielding                         = true;
    result.state.plastic_strain += delta_gamma * n;
    result.state.equivalent_plastic_strain += std::sqrt(2. / 3.) * delta_gamma;
    const SymmetricTensor<2, 3> s = s_trial - 2. * mu * delta_gamma * n;
    result.stress                 = pressure * one + s;
    // sigma : d eps_p = sigma_y d eps_bar along the return; the mean of
    // the yield stress over the increment makes the sum exact for linear
    // hardening (Y eps_bar + H eps_bar^2 / 2 on a monotonic path).
    const double d_eps_bar = std::sqrt(2. / 3.) * delta_gamma;
    result.plastic_work =
      (Y + H * (old_state.equivalent_plastic_strain + 0.5 * d_eps_bar)) *
      d_eps_bar;
    // Box 3.2: theta = 1 - 2 mu dgamma/|s_trial|,
    // theta_bar = 1/(1 + H/(3 mu)) - (1 - theta).
    if (!with_tangent)
      return result;
    const double theta     = 1. - 2. * mu * delta_gamma / norm_trial;
    const double theta_bar = 1. / (1. + H / (3. * mu)) - (1. - theta);
    result.tangent         = kappa * one_one + 2. * mu * theta * I_dev -
                     2. * mu * theta_bar * outer_product(n, n);
    return result;
  }



  SymmetricTensor<2, 3>
  J2Plasticity::admissible_stress(const SymmetricTensor<2, 3> &sigma,
                                  const double                 yield_stress)
  {
    const SymmetricTensor<2, 3> s  = deviator(sigma);
    const double                vm = std::sqrt(1.5) * s.norm();
    if (!(vm > yield_stress))
      return sigma;
    return sigma - (1. - yield_stress / vm) * s;
  }
} // namespace fgimpact
