#include <deal.II/base/timer.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <fgimpact/analysis/modal_analysis.h>
#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>
#include <fgimpact/base/stop_signals.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/postprocessing.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

namespace fgimpact
{
  ModalAnalysis::ModalAnalysis(const Parameters &parameters,
                               const EffectiveMatrixSolver::Parameters &solver,
                               const PlateModel                        &plate)
    : parameters(parameters)
    , solver_parameters(solver)
    , plate(plate)
  {}



  namespace
  {
    /// mask = 1 at the unconstrained DoFs, w_mask = 1 at the unconstrained
    /// z components (for the share of kinetic energy in w).
    void
    make_masks(const PlateModel              &plate,
               TrilinosWrappers::MPI::Vector &mask,
               TrilinosWrappers::MPI::Vector &w_mask)
    {
      const auto                          &fe = plate.get_fe();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (plate.locally_owned_dofs().is_element(dofs[i]) &&
                  !plate.get_constraints().is_constrained(dofs[i]))
                {
                  mask(dofs[i]) = 1.;
                  w_mask(dofs[i]) =
                    (fe.system_to_component_index(i).first == 2 ? 1. : 0.);
                }
          }
      mask.compress(VectorOperation::insert);
      w_mask.compress(VectorOperation::insert);
    }



    /// Rayleigh-Ritz on the block Y: (Y^T K Y) q = lambda (Y^T M Y) q,
    /// X = Y Q (M-orthonormal Ritz vectors, ascending lambda); tmp and Mx
    /// are scratch vectors.
    void
    rayleigh_ritz(const TrilinosWrappers::SparseMatrix             &K,
                  const TrilinosWrappers::SparseMatrix             &M,
                  const std::vector<TrilinosWrappers::MPI::Vector> &Y,
                  TrilinosWrappers::MPI::Vector                    &tmp,
                  TrilinosWrappers::MPI::Vector                    &Mx,
                  std::vector<double>                              &lambda,
                  std::vector<TrilinosWrappers::MPI::Vector>       &X)
    {
      const unsigned int       p = Y.size();
      LAPACKFullMatrix<double> Kr(p, p), Mr(p, p);
      const MPI_Comm           comm = K.get_mpi_communicator();
      for (unsigned int j = 0; j < p; ++j)
        {
          throw_if_stop_signal(comm, "during the modal iteration");
          K.vmult(tmp, Y[j]);
          M.vmult(Mx, Y[j]);
          for (unsigned int i = 0; i <= j; ++i)
            {
              Kr(i, j) = Kr(j, i) = Y[i] * tmp;
              Mr(i, j) = Mr(j, i) = Y[i] * Mx;
            }
        }
      std::vector<Vector<double>> q(p, Vector<double>(p));
      Kr.compute_generalized_eigenvalues_symmetric(Mr, q);
      for (unsigned int j = 0; j < p; ++j)
        lambda[j] = Kr.eigenvalue(j).real();
      for (unsigned int j = 0; j < p; ++j)
        {
          throw_if_stop_signal(comm, "during the modal iteration");
          X[j] = 0.;
          for (unsigned int i = 0; i < p; ++i)
            X[j].add(q[j](i), Y[i]);
        }
    }

    /// The subspace's size for n modes: 2 n + 8, at most the free DoFs
    /// (mask's ones).  A mesh has as many modes as free DoFs: asking for
    /// more cannot be answered (the block would be singular and LAPACK
    /// return nothing).
    unsigned int
    block_size(const unsigned int n, const TrilinosWrappers::MPI::Vector &mask)
    {
      const auto n_free = static_cast<unsigned int>(mask.l1_norm() + 0.5);
      AssertThrow(n <= n_free,
                  ExcNumericalFailure(
                    "Modal/Number of modes = " + std::to_string(n) +
                    " exceeds the " + std::to_string(n_free) +
                    " free DoFs of this mesh (its number of modes); ask for "
                    "at most that many or refine Geometry/Subdivisions."));
      return std::min<unsigned int>(2 * n + 8, n_free);
    }

    /// Whether each of the lowest n Ritz values changed by at most
    /// `tolerance` (relative) from the iteration before.
    bool
    settled(const std::vector<double> &lambda,
            const std::vector<double> &lambda_old,
            const unsigned int         n,
            const double               tolerance)
    {
      bool converged = true;
      for (unsigned int j = 0; j < n; ++j)
        converged = converged && std::abs(lambda[j] - lambda_old[j]) <=
                                   tolerance * std::abs(lambda[j]);
      return converged;
    }

    /// LAPACK's sygv reports a failure on the screen only and leaves
    /// zeros (a free plate's rigid modes are near zero too, but never the
    /// whole block): never write 0 Hz for modes not found.
    void
    check_ritz_values(const std::vector<double> &lambda,
                      const unsigned int         iteration)
    {
      bool found = *std::max_element(lambda.begin(), lambda.end()) > 0.;
      for (const double value : lambda)
        found = found && std::isfinite(value);
      AssertThrow(found,
                  ExcNumericalFailure(
                    "the subspace iteration's Rayleigh-Ritz problem failed "
                    "at iteration " +
                    std::to_string(iteration) +
                    " (no eigenvalues: a singular block); ask for fewer "
                    "Modal/Number of modes or refine Geometry/"
                    "Subdivisions."));
    }

    /// The start block X (p vectors, zero on constrained DoFs):
    /// deterministic, all length scales present; Y sized alike.
    void
    start_block(const PlateModel                           &plate,
                const TrilinosWrappers::MPI::Vector        &mask,
                const unsigned int                          p,
                std::vector<TrilinosWrappers::MPI::Vector> &X,
                std::vector<TrilinosWrappers::MPI::Vector> &Y)
    {
      subspace_start_block(plate, p, X, Y);
      for (auto &x : X)
        x.scale(mask);
    }
  } // namespace



  void
  subspace_start_block(const PlateModel                           &plate,
                       const unsigned int                          p,
                       std::vector<TrilinosWrappers::MPI::Vector> &X,
                       std::vector<TrilinosWrappers::MPI::Vector> &Y)
  {
    X.resize(p);
    Y.resize(p);
    for (unsigned int j = 0; j < p; ++j)
      {
        plate.initialize_vector(X[j]);
        plate.initialize_vector(Y[j]);
        for (const auto i : X[j].locally_owned_elements())
          X[j](i) = std::sin(0.37 + 1.7 * j + 12.9898 * i * (j + 1));
        X[j].compress(VectorOperation::insert);
      }
  }



  void
  ModalAnalysis::report_costs(const bool report)
  {
    print_costs = report;
  }



  void
  ModalAnalysis::report_iteration_cost(const double       seconds,
                                       const unsigned int block) const
  {
    // A long request says so after its first iteration (Modal/Max
    // iterations of them at most), instead of minutes of silence.
    if (!print_costs || seconds < 2. ||
        Utilities::MPI::this_mpi_process(plate.get_mpi_communicator()) != 0)
      return;
    char text[400];
    std::snprintf(text,
                  sizeof(text),
                  "  modal: the first subspace iteration (a block of %u "
                  "vectors for %u modes) took %.1f s; up to Modal/Max "
                  "iterations = %u of them may follow (at most %.0f s); "
                  "fewer Modal/Number of modes is faster.\n",
                  block,
                  parameters.n_modes,
                  seconds,
                  parameters.max_iterations,
                  seconds * parameters.max_iterations);
    std::cout << text << std::flush;
  }



  void
  ModalAnalysis::report_estimated_cost(const double solve_seconds,
                                       const TrilinosWrappers::MPI::Vector &x,
                                       const TrilinosWrappers::MPI::Vector &y,
                                       const unsigned int block) const
  {
    if (!print_costs)
      return;
    // The Rayleigh-Ritz step's 2 p products with K and M and 2 p^2 vector
    // operations (the projections and the new block) outweigh the p
    // solves for large blocks: time 5 products and 20 dot products
    // (collective, as the iteration's).
    TrilinosWrappers::MPI::Vector Kx(x);
    Timer                         timer;
    for (unsigned int k = 0; k < 5; ++k)
      plate.stiffness_matrix().vmult(Kx, x);
    const double    product_seconds = timer.wall_time() / 5;
    volatile double sink            = 0; // the products are not dropped
    timer.restart();
    for (unsigned int k = 0; k < 20; ++k)
      sink = sink + x * y;
    const double op_seconds = timer.wall_time() / 20;
    // A request that takes minutes says so before its first iteration,
    // not after it: a lower bound (vectors timed while in cache, the dense
    // p x p eigenproblem left out).
    const double iteration = (solve_seconds + 2. * product_seconds) * block +
                             2. * op_seconds * block * block;
    if (iteration < 2. ||
        Utilities::MPI::this_mpi_process(plate.get_mpi_communicator()) != 0)
      return;
    char text[400];
    std::snprintf(text,
                  sizeof(text),
                  "  modal: estimated at least %.1f s per subspace "
                  "iteration (%u solves of %.3f s and the projection on a "
                  "block of %u vectors, for %u modes), and up to "
                  "Modal/Max iterations = %u iterations; fewer "
                  "Modal/Number of modes is faster.\n",
                  iteration,
                  block,
                  solve_seconds,
                  block,
                  parameters.n_modes,
                  parameters.max_iterations);
    std::cout << text << std::flush;
  }



  void
  ModalAnalysis::solve()
  {
    const auto        &K     = plate.stiffness_matrix();
    const auto        &M     = plate.mass_matrix();
    const unsigned int n     = parameters.n_modes;
    const double       sigma = std::pow(2. * M_PI * parameters.shift, 2);

    // Unconstrained DoFs mask: constrained rows of K and M carry
    // artificial diagonal entries whose ratios are not plate modes.
    TrilinosWrappers::MPI::Vector mask, w_mask, tmp, Mx;
    for (auto *v : {&mask, &w_mask, &tmp, &Mx})
      plate.initialize_vector(*v);
    make_masks(plate, mask, w_mask);
    const unsigned int p = block_size(n, mask);

    // The shifted operator K - sigma M, factorized once.
    TrilinosWrappers::SparseMatrix shifted;
    shifted.copy_from(K);
    if (sigma != 0.)
      shifted.add(-sigma, M);
    EffectiveMatrixSolver solver(solver_parameters);
    solver.initialize(shifted);

    std::vector<TrilinosWrappers::MPI::Vector> X, Y;
    start_block(plate, mask, p, X, Y);

    std::vector<double> lambda(p, 0.), lambda_old(p, 0.);
    Timer               first_iteration;
    for (iterations = 1; iterations <= parameters.max_iterations; ++iterations)
      {
        apply_inverse(solver, mask, X, Y, Mx, iterations == 1, first_iteration);
        rayleigh_ritz(K, M, Y, tmp, Mx, lambda, X);
        check_ritz_values(lambda, iterations);
        if (iterations == 1)
          report_iteration_cost(first_iteration.wall_time(), p);

        const bool converged =
          iterations > 1 &&
          settled(lambda, lambda_old, n, parameters.tolerance);
        lambda_old = lambda;
        if (converged)
          break;
      }
    AssertThrow(iterations <= parameters.max_iterations,
                ExcNumericalFailure(
                  "no convergence within Modal/Max iterations = " +
                  std::to_string(parameters.max_iterations) +
                  "; raise it or loosen Modal/Tolerance."));

    collect_modes(X, lambda, w_mask);
  }



  void
  ModalAnalysis::apply_inverse(
    EffectiveMatrixSolver                            &solver,
    const TrilinosWrappers::MPI::Vector              &mask,
    const std::vector<TrilinosWrappers::MPI::Vector> &X,
    std::vector<TrilinosWrappers::MPI::Vector>       &Y,
    TrilinosWrappers::MPI::Vector                    &Mx,
    const bool                                        first,
    const Timer                                      &first_iteration) const
  {
    // Y = (K - sigma M)^{-1} M X.  A stop signal is acted on between two
    // solves (a block of 1000 vectors takes minutes per iteration).
    const auto &M = plate.mass_matrix();
    for (unsigned int j = 0; j < Y.size(); ++j)
      {
        throw_if_stop_signal(plate.get_mpi_communicator(),
                             "during the modal iteration");
        M.vmult(Mx, X[j]);
        Mx.scale(mask);
        Y[j] = 0.;
        solver.solve(Y[j], Mx);
        Y[j].scale(mask);
        if (first && j == 0)
          report_estimated_cost(first_iteration.wall_time(),
                                Y[0],
                                Mx,
                                Y.size());
      }
  }



  void
  ModalAnalysis::collect_modes(
    const std::vector<TrilinosWrappers::MPI::Vector> &X,
    const std::vector<double>                        &lambda,
    const TrilinosWrappers::MPI::Vector              &w_mask)
  {
    // Each mode's frequency and the share of its kinetic energy in the
    // transverse (w) motion.
    const auto                   &M = plate.mass_matrix();
    TrilinosWrappers::MPI::Vector tmp, Mx;
    plate.initialize_vector(tmp);
    plate.initialize_vector(Mx);
    modes.clear();
    shapes.clear();
    for (unsigned int j = 0; j < parameters.n_modes; ++j)
      {
        M.vmult(Mx, X[j]);
        const double total = X[j] * Mx;
        tmp                = X[j];
        tmp.scale(w_mask);
        M.vmult(Mx, tmp);
        modes.push_back({std::sqrt(std::max(lambda[j], 0.)) / (2. * M_PI),
                         (tmp * Mx) / total});
        shapes.push_back(X[j]);
      }
  }



  SummaryWriter
  ModalAnalysis::summary() const
  {
    SummaryWriter out;
    out.add_text("status", "completed");
    for (unsigned int j = 0; j < modes.size(); ++j)
      out.add("frequency_" + std::to_string(j + 1) + "_Hz",
              modes[j].frequency,
              4);
    out.add("n_dofs", plate.n_dofs(), 0);
    out.add("subspace_iterations", iterations, 0);
    return out;
  }



  void
  ModalAnalysis::write_output(
    const std::string                                &directory,
    const DataOutBase::VtkFlags::ZlibCompressionLevel vtu_compression,
    const VtuFields                                  &fields) const
  {
    // Rank 0 writes, every rank learns the outcome before the collective
    // VTU output (a failure on rank 0 alone must not leave rank 1 waiting).
    run_on_root(plate.get_mpi_communicator(), [&]() {
      std::string csv = "mode,frequency_Hz,w_energy_fraction\n";
      char        line[200];
      for (unsigned int j = 0; j < modes.size(); ++j)
        {
          std::snprintf(line,
                        sizeof(line),
                        "%u,%.4f,%.6f\n",
                        j + 1,
                        modes[j].frequency,
                        modes[j].w_fraction);
          csv += line;
        }
      write_file_atomically(directory + "/frequencies.csv", csv);
    });
    // Mode shapes scaled to a unit maximum displacement, as VTU "time"
    // steps 1..N, the mode numbers (ParaView's time bar then steps through
    // the modes), with the frequency as the field frequency_Hz.
    TrilinosWrappers::MPI::Vector zero;
    plate.initialize_vector(zero);
    VtuWriter vtu(plate, directory, vtu_compression, fields);
    for (unsigned int j = 0; j < shapes.size(); ++j)
      {
        // The Ritz vectors are condensed (hanging nodes 0): the shape a
        // user sees has the constraints distributed.
        TrilinosWrappers::MPI::Vector shape = shapes[j];
        plate.get_constraints().distribute(shape);
        shape /= shape.linfty_norm();
        vtu.write(
          j + 1, j + 1, shape, zero, {"frequency_Hz", modes[j].frequency});
      }
    vtu.finish();
  }
} // namespace fgimpact
