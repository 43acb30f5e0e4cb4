// SPDX-License-Identifier: GPL-3.0-or-later
#include <deal.II/lac/solver_bicgstab.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <ndda/physics/cg_jacobi.h>
#include <ndda/physics/cholesky.h>

#include <string>

namespace ndda
{
  void
  JacobiCG::initialize(const SparseMatrix<double> &matrix)
  {
    this->matrix  = &matrix;
    auto &inverse = inverse_diagonal.get_vector();
    inverse.reinit(matrix.m(), true);
    for (types::global_dof_index i = 0; i < matrix.m(); ++i)
      {
        const double a = matrix.diag_element(i);
        AssertThrow(a > 0.,
                    ExcMessage("Control/Linear solver: CG-Jacobi needs a "
                               "positive diagonal, but the system's row " +
                               std::to_string(i) + " has " + std::to_string(a) +
                               " there. Use direct or UMFPACK."));
        inverse[i] = 1. / a;
      }
    symmetric = is_symmetric(matrix);
  }



  unsigned int
  JacobiCG::solve(Vector<double>       &x,
                  const Vector<double> &b,
                  const double          relative_tolerance) const
  {
    AssertThrow(matrix != nullptr && matrix->m() == b.size(),
                ExcMessage("CG-Jacobi: no matrix of this size to solve with."));
    x.reinit(b.size());
    const double norm = b.l2_norm();
    if (norm == 0.)
      return 0;
    SolverControl control(20000, relative_tolerance * norm);
    try
      {
        if (symmetric)
          SolverCG<Vector<double>>(control).solve(*matrix,
                                                  x,
                                                  b,
                                                  inverse_diagonal);
        else
          SolverBicgstab<Vector<double>>(control).solve(*matrix,
                                                        x,
                                                        b,
                                                        inverse_diagonal);
      }
    catch (const SolverControl::NoConvergence &exc)
      {
        AssertThrow(false,
                    ExcMessage(
                      std::string("Control/Linear solver: CG-Jacobi (") +
                      (symmetric ? "CG" :
                                   "BiCGStab, the matrix being "
                                   "non-symmetric") +
                      ") did not converge in " + std::to_string(exc.last_step) +
                      " iterations (residual " +
                      std::to_string(exc.last_residual) + " against " +
                      std::to_string(control.tolerance()) +
                      "). Its iterations grow with the time step over the "
                      "time a wave takes to cross an element: use a "
                      "shorter time step, CG-AMG or direct."));
      }
    return control.last_step();
  }
} // namespace ndda
