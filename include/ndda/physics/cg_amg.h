// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_cg_amg_h
#define ndda_physics_cg_amg_h

#include <deal.II/base/point.h>

#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <Teuchos_ParameterList.hpp>
#include <string>
#include <vector>

namespace ndda
{
  using namespace dealii;

  /**
   * CG with Trilinos ML's smoothed-aggregation AMG for elasticity: what
   * LinearSolver (`Linear solver = CG-AMG`, one process) and
   * DistributedSolver (several) share.
   *
   * @ingroup physics
   */
  namespace cg_amg
  {
    /**
     * The rigid-body modes of dofs at @p location with vector component
     * @p component: the x and y translations and the rotation (-y, x),
     * mode after mode (3 n values).
     */
    std::vector<double>
    rigid_body_modes(const std::vector<Point<2>>     &location,
                     const std::vector<unsigned int> &component);

    /**
     * Build @p amg on @p matrix (elliptic, two smoother sweeps, aggregation
     * threshold 0.02). With @p null_space (the rigid-body modes at this
     * process's rows, mode after mode) those are ML's near null space;
     * without, ML's default (the translations). ML keeps pointers into
     * @p null_space and @p parameters: the caller keeps both alive as long
     * as @p amg.
     */
    void
    initialize(TrilinosWrappers::PreconditionAMG    &amg,
               const TrilinosWrappers::SparseMatrix &matrix,
               const std::vector<double>            &null_space,
               Teuchos::ParameterList               &parameters);

    /**
     * Solve matrix x = b with CG to the residual @p absolute_tolerance,
     * preconditioned by @p amg; returns the iterations. Throws ExcMessage,
     * @p context first and @p advice last, if CG does not converge.
     */
    unsigned int
    solve(const TrilinosWrappers::SparseMatrix    &matrix,
          const TrilinosWrappers::PreconditionAMG &amg,
          TrilinosWrappers::MPI::Vector           &x,
          const TrilinosWrappers::MPI::Vector     &b,
          const double                             absolute_tolerance,
          const std::string                       &context,
          const std::string                       &advice);
  } // namespace cg_amg
} // namespace ndda

#endif
