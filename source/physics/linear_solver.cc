// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/index_set.h>

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ndda/physics/linear_solver.h>

namespace ndda
{
  struct LinearSolver::Implementation
  {
    SparseDirectUMFPACK                             umfpack;
    TrilinosWrappers::SparseMatrix                  trilinos_matrix;
    SolverControl                                   direct_control{1, 0};
    std::unique_ptr<TrilinosWrappers::SolverDirect> klu;
    TrilinosWrappers::PreconditionAMG               amg;
    IndexSet                                        all;
  };



  LinearSolver::LinearSolver(const parameters::LinearSolver type,
                             const double                   tolerance)
    : type(type)
    , tolerance(tolerance)
    , implementation(std::make_unique<Implementation>())
  {}



  LinearSolver::~LinearSolver() = default;



  void
  LinearSolver::factorize(const SparseMatrix<double> &matrix)
  {
    ++factorization_count;
    auto &impl = *implementation;
    try
      {
        if (type == parameters::LinearSolver::umfpack)
          {
            impl.umfpack.initialize(matrix);
            return;
          }
        impl.all = complete_index_set(matrix.m());
        impl.trilinos_matrix.reinit(matrix, 0., true, nullptr);
        if (type == parameters::LinearSolver::klu)
          {
            impl.klu = std::make_unique<TrilinosWrappers::SolverDirect>(
              impl.direct_control,
              TrilinosWrappers::SolverDirect::AdditionalData(false,
                                                             "Amesos_Klu"));
            impl.klu->initialize(impl.trilinos_matrix);
          }
        else
          {
            TrilinosWrappers::PreconditionAMG::AdditionalData data;
            data.elliptic              = true;
            data.higher_order_elements = false;
            data.smoother_sweeps       = 2;
            data.aggregation_threshold = 0.02;
            impl.amg.initialize(impl.trilinos_matrix, data);
          }
      }
    catch (const ExceptionBase &exc)
      {
        std::ostringstream message;
        exc.print_info(message);
        AssertThrow(false,
                    ExcMessage(
                      "The system matrix cannot be factorized; it is "
                      "probably singular because a block can move freely "
                      "in a quasi-static analysis. Constrain every block "
                      "or use Control/Analysis type = static or dynamic. "
                      "Solver message: " +
                      message.str()));
      }
  }



  unsigned int
  LinearSolver::solve(Vector<double> &x, const Vector<double> &b)
  {
    auto &impl = *implementation;
    if (type == parameters::LinearSolver::umfpack)
      {
        impl.umfpack.vmult(x, b);
        return 1;
      }
    TrilinosWrappers::MPI::Vector tx(impl.all, MPI_COMM_SELF),
      tb(impl.all, MPI_COMM_SELF);
    for (unsigned int i = 0; i < b.size(); ++i)
      tb[i] = b[i];
    tb.compress(VectorOperation::insert);
    unsigned int iterations = 1;
    if (type == parameters::LinearSolver::klu)
      impl.klu->solve(tx, tb);
    else
      {
        SolverControl control(10000, tolerance * b.l2_norm());
        SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
        try
          {
            cg.solve(impl.trilinos_matrix, tx, tb, impl.amg);
          }
        catch (const SolverControl::NoConvergence &exc)
          {
            AssertThrow(false,
                        ExcMessage("Control/Linear solver: CG-AMG did not "
                                   "converge in " +
                                   std::to_string(exc.last_step) +
                                   " iterations (residual " +
                                   std::to_string(exc.last_residual) +
                                   "). Use UMFPACK or KLU for this scene."));
          }
        iterations = control.last_step();
      }
    for (unsigned int i = 0; i < x.size(); ++i)
      x[i] = tx[i];
    return iterations;
  }
} // namespace ndda
