// SPDX-License-Identifier: GPL-3.0-or-later
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <ndda/physics/cg_amg.h>

#include <Epetra_MultiVector.h>

namespace ndda
{
  namespace cg_amg
  {
    std::vector<double>
    rigid_body_modes(const std::vector<Point<2>>     &location,
                     const std::vector<unsigned int> &component)
    {
      const std::size_t   n = location.size();
      std::vector<double> modes(3 * n, 0.);
      for (std::size_t i = 0; i < n; ++i)
        {
          modes[0 * n + i] = (component[i] == 0 ? 1. : 0.);
          modes[1 * n + i] = (component[i] == 1 ? 1. : 0.);
          modes[2 * n + i] =
            (component[i] == 0 ? -location[i][1] : location[i][0]);
        }
      return modes;
    }



    void
    initialize(TrilinosWrappers::PreconditionAMG    &amg,
               const TrilinosWrappers::SparseMatrix &matrix,
               const std::vector<double>            &null_space,
               Teuchos::ParameterList               &parameters)
    {
      TrilinosWrappers::PreconditionAMG::AdditionalData data;
      data.elliptic              = true;
      data.higher_order_elements = false;
      data.smoother_sweeps       = 2;
      data.aggregation_threshold = 0.02;
      if (null_space.empty())
        {
          amg.initialize(matrix, data);
          return;
        }
      // Elasticity: the null space of the stiffness holds two translations
      // and the rotation (-y, x); deal.II's constant modes give only the
      // translations.
      const unsigned int n_rows = matrix.local_size();
      AssertThrow(n_rows > 0 && null_space.size() % n_rows == 0,
                  ExcMessage("The near null space does not fit the rows of "
                             "this process."));
      parameters = Teuchos::ParameterList();
      std::unique_ptr<Epetra_MultiVector> unused;
      data.set_parameters(parameters, unused, matrix);
      parameters.set("null space: type", "pre-computed");
      parameters.set("null space: dimension",
                     static_cast<int>(null_space.size() / n_rows));
      parameters.set("null space: vectors",
                     const_cast<double *>(null_space.data()));
      amg.initialize(matrix, parameters);
    }



    unsigned int
    solve(const TrilinosWrappers::SparseMatrix    &matrix,
          const TrilinosWrappers::PreconditionAMG &amg,
          TrilinosWrappers::MPI::Vector           &x,
          const TrilinosWrappers::MPI::Vector     &b,
          const double                             absolute_tolerance,
          const std::string                       &context,
          const std::string                       &advice)
    {
      SolverControl control(10000, absolute_tolerance);
      SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
      try
        {
          cg.solve(matrix, x, b, amg);
        }
      catch (const SolverControl::NoConvergence &exc)
        {
          AssertThrow(false,
                      ExcMessage(context + "CG-AMG did not converge in " +
                                 std::to_string(exc.last_step) +
                                 " iterations (residual " +
                                 std::to_string(exc.last_residual) + ")." +
                                 advice));
        }
      return control.last_step();
    }
  } // namespace cg_amg
} // namespace ndda
