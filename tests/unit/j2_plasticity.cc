// The J2 return map (material/plasticity.h) against closed forms:
//  1. A uniaxial stress path (the lateral strains found by Newton's method
//     with the consistent tangent, so sigma_22 = sigma_33 = 0), loaded to
//     5 times the yield strain and unloaded to zero stress: sigma_11
//     against Y + E_t (eps - eps_y), E_t = E H / (E + H), the unloading
//     slope E, the residual plastic strain eps_max - sigma_max / E, and
//     the plastic work Y eps_p + H eps_p^2 / 2; Newton on the lateral
//     strain takes one iteration (the path is radial, so the return map
//     is linear in it and the consistent tangent exact).
//  2. The consistent tangent against central differences of the return
//     map at a plastic state (limit 1e-6 relative).
//  3. Perfect plasticity (H = 0): the stress stays on the yield surface.

#include <deal.II/base/symmetric_tensor.h>

#include <fgimpact/material/plasticity.h>

#include <cmath>
#include <cstdio>

namespace fgimpact_unit_tests::j2_plasticity
{

  using namespace dealii;
  using namespace fgimpact;

  namespace
  {
    const double E = 70e9, nu = 0.3, Y = 275e6;
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)),
                 mu     = E / (2 * (1 + nu));

    struct UniaxialPoint
    {
      PlasticUpdate update;
      unsigned int  iterations;
    };

    /// The state at axial strain e11 with sigma_22 = sigma_33 = 0 (the
    /// lateral strain by Newton's method), from `old`.
    UniaxialPoint
    uniaxial(const double        H,
             const double        e11,
             double             &lateral,
             const PlasticState &old)
    {
      UniaxialPoint p{};
      for (p.iterations = 0; p.iterations < 20; ++p.iterations)
        {
          SymmetricTensor<2, 3> eps;
          eps[0][0] = e11;
          eps[1][1] = eps[2][2] = lateral;
          p.update       = J2Plasticity::update(lambda, mu, Y, H, eps, old);
          const double r = p.update.stress[1][1];
          if (std::abs(r) < 1e-9 * Y)
            break;
          // d sigma_22 / d lateral = C_2222 + C_2233.
          lateral -=
            r / (p.update.tangent[1][1][1][1] + p.update.tangent[1][1][2][2]);
        }
      return p;
    }
  } // namespace

  int
  test_main(int, char **)
  {
    bool ok = true;

    // 1. Uniaxial loading and unloading.
    for (const double H : {7e9, 0.})
      {
        const double       E_t = E * H / (E + H), eps_y = Y / E;
        PlasticState       state;
        double             lateral = 0, worst = 0, work = 0, sigma_max = 0;
        unsigned int       most_iterations = 0;
        const unsigned int n               = 100;
        for (unsigned int k = 1; k <= n; ++k) // load to 5 eps_y
          {
            const double e = 5 * eps_y * k / n;
            const auto   p = uniaxial(H, e, lateral, state);
            state          = p.update.state;
            work += p.update.plastic_work;
            most_iterations    = std::max(most_iterations, p.iterations);
            const double exact = e <= eps_y ? E * e : Y + E_t * (e - eps_y);
            worst = std::max(worst, std::abs(p.update.stress[0][0] - exact));
            sigma_max = p.update.stress[0][0];
          }
        // Unload elastically to zero stress.
        const double e_end = 5 * eps_y - sigma_max / E;
        const auto   p     = uniaxial(H, e_end, lateral, state);
        worst              = std::max(worst, std::abs(p.update.stress[0][0]));
        const double eps_p = state.equivalent_plastic_strain;
        const double exact_work = Y * eps_p + 0.5 * H * eps_p * eps_p;
        // Verdicts for the round-off-sized errors and the iteration count
        // (their digits depend on the CPU).
        std::printf("uniaxial, H = %.0f GPa: largest |sigma_11 - closed form| "
                    "below 1e-6 MPa: %s, plastic strain %.6e (closed form "
                    "%.6e), plastic work error below 1e-12: %s, Newton at most "
                    "1 iteration: %s\n",
                    H * 1e-9,
                    worst < 1. ? "yes" : "NO",
                    eps_p,
                    5 * eps_y - sigma_max / E,
                    std::abs(work / exact_work - 1) < 1e-12 ? "yes" : "NO",
                    most_iterations <= 1 ? "yes" : "NO");
        ok = ok && worst < 1. && std::abs(p.update.stress[0][0]) < 1. &&
             std::abs(eps_p / (5 * eps_y - sigma_max / E) - 1) < 1e-9 &&
             std::abs(work / exact_work - 1) < 1e-12 && most_iterations <= 1;
      }

    // 2. The consistent tangent against central differences.
    {
      SymmetricTensor<2, 3> eps;
      eps[0][0] = 0.006;
      eps[1][1] = -0.001;
      eps[0][1] = 0.002;
      eps[1][2] = -0.0015;
      PlasticState old;
      old.plastic_strain[0][0]      = 0.001;
      old.plastic_strain[1][1]      = -0.0005;
      old.plastic_strain[2][2]      = -0.0005;
      old.equivalent_plastic_strain = 0.001;
      const double H                = 7e9;
      const auto   exact = J2Plasticity::update(lambda, mu, Y, H, eps, old);
      double       worst = 0;
      const double h     = 1e-9;
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int l = k; l < 3; ++l)
          {
            SymmetricTensor<2, 3> d;
            d[k][l] = h; // symmetric: eps_kl = eps_lk += h
            const auto plus =
              J2Plasticity::update(lambda, mu, Y, H, eps + d, old);
            const auto minus =
              J2Plasticity::update(lambda, mu, Y, H, eps - d, old);
            const SymmetricTensor<2, 3> fd =
              (plus.stress - minus.stress) / (2 * h);
            // C : d eps with d eps_kl = d eps_lk = h counts C_ijkl twice
            // off the diagonal.
            const SymmetricTensor<2, 3> from_tangent = exact.tangent * d / h;
            worst                                    = std::max(worst,
                             (fd - from_tangent).norm() / exact.tangent.norm());
          }
      std::printf("consistent tangent at a plastic state (yielding %s): "
                  "relative difference to central differences below 1e-6: "
                  "%s\n",
                  exact.yielding ? "yes" : "no",
                  worst < 1e-6 ? "yes" : "NO");
      ok = ok && exact.yielding && worst < 1e-6;
    }

    // 3. Perfect plasticity: on the yield surface.
    {
      SymmetricTensor<2, 3> eps;
      eps[0][1]      = 0.02;
      eps[2][2]      = -0.01;
      const auto   p = J2Plasticity::update(lambda, mu, Y, 0., eps, {});
      const double q = std::sqrt(1.5) * deviator(p.stress).norm();
      std::printf("perfectly plastic: von Mises %.6f MPa against Y %.6f MPa\n",
                  q * 1e-6,
                  Y * 1e-6);
      ok = ok && std::abs(q / Y - 1) < 1e-12;
    }
    std::printf("%s\n", ok ? "OK" : "FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::j2_plasticity
