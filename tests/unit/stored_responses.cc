// StoredResponse and add_weighted_responses() (contact/compliance.h), the
// back-substitution u += sum_k w_k c_k of the implicit stepper:
//  (1) double responses: the blocked sum is bitwise the sequential axpys'
//      (u.add(w_k, c_k), k = 0, 1, ...), for 1 to 9 terms (the 4-term
//      passes and the rest);
//  (2) single-precision responses (a resolved contact's): every entry
//      within the rounding bound of the narrowed data,
//      |u_float - u_double|_i <= 2^-24 sum_k |w_k| |c_k,i| (float's unit
//      round-off) plus both double sums' own round-off, 2 (m + 1) 2^-53
//      (|u_i| + sum_k |w_k c_k,i|), and not equal to the double sum
//      (narrowed at all);
//  (3) the memory: a float response is half a double one.
// The vectors are random (fixed seed), 100003 entries (four blocks of the
// kernel's 32768 rows and a partial one).

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/contact/compliance.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace fgimpact_unit_tests::stored_responses
{
  using namespace fgimpact;

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const std::size_t                n = 100003;
    IndexSet                         owned(n);
    owned.add_range(0, n);
    std::mt19937                           random(38);
    std::uniform_real_distribution<double> uniform(-1., 1.);
    TrilinosWrappers::MPI::Vector          start(owned, MPI_COMM_WORLD);
    for (std::size_t i = 0; i < n; ++i)
      start[i] = 1e-6 * uniform(random);
    bool ok = true;
    for (unsigned int m = 1; m <= 9; ++m)
      {
        std::vector<double>                        w(m);
        std::vector<TrilinosWrappers::MPI::Vector> c(m);
        std::vector<StoredResponse>                wide(m), narrow;
        narrow.assign(m, StoredResponse(true));
        for (unsigned int k = 0; k < m; ++k)
          {
            w[k] = 1e3 * uniform(random); // N
            c[k].reinit(owned, MPI_COMM_WORLD);
            for (std::size_t i = 0; i < n; ++i)
              c[k][i] = 1e-9 * uniform(random); // m/N
            wide[k].assign(c[k].begin(), c[k].end());
            narrow[k].assign(c[k].begin(), c[k].end());
          }
        TrilinosWrappers::MPI::Vector axpys(start), blocked(start),
          single(start);
        std::vector<const StoredResponse *> wide_p, narrow_p;
        for (unsigned int k = 0; k < m; ++k)
          {
            axpys.add(w[k], c[k]);
            wide_p.push_back(&wide[k]);
            narrow_p.push_back(&narrow[k]);
          }
        add_weighted_responses(blocked, w, wide_p);
        add_weighted_responses(single, w, narrow_p);
        bool   bitwise = true;
        double worst   = 0; // error / bound
        for (std::size_t i = 0; i < n; ++i)
          {
            bitwise      = bitwise && blocked[i] == axpys[i];
            double terms = 0;
            for (unsigned int k = 0; k < m; ++k)
              terms += std::abs(w[k]) * std::abs(c[k][i]);
            // The narrowing, and both sums' own round-off in double.
            const double bound =
              std::ldexp(1., -24) * terms +
              2. * (m + 1) * std::ldexp(1., -53) * (std::abs(start[i]) + terms);
            worst = std::max(worst, std::abs(single[i] - axpys[i]) / bound);
          }
        const bool within = worst <= 1.;
        // The ratio itself is round-off: its verdicts only (narrowed at
        // all, and within the bound).
        std::printf("%u terms: (1) double responses bitwise the axpys': %s; "
                    "(2) float responses differ, within 2^-24 sum |w c|: "
                    "%s\n",
                    m,
                    bitwise ? "yes" : "NO",
                    within && worst > 0. ? "yes" : "NO");
        ok = ok && bitwise && within && worst > 0.;
      }
    StoredResponse      a(true), b(false);
    std::vector<double> x(1000, 1.);
    a.assign(x.begin(), x.end());
    b.assign(x.begin(), x.end());
    const bool half = a.size() == b.size() && a.single() && !b.single() &&
                      sizeof(*a.single_data()) * 2 == sizeof(*b.double_data());
    std::printf("(3) a float response holds its %zu entries in half the bytes "
                "of a double one: %s\n",
                a.size(),
                half ? "yes" : "NO");
    ok = ok && half;
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::stored_responses
