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
    // CG where the matrix is symmetric with a positive diagonal (a
    // diagonal entry that is not positive means it is not positive
    // definite); BiCGStab where not, scaled by the diagonal's inverse
    // wherever the diagonal is not zero.
    bool positive = true;
    for (types::global_dof_index i = 0; i < matrix.m(); ++i)
      {
        const double a = matrix.diag_element(i);
        positive       = positive && a > 0.;
        inverse[i]     = (a != 0. ? 1. / a : 1.);
      }
    symmetric = positive && is_symmetric(matrix);
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
                                   "non-symmetric or indefinite") +
                      ") did not converge in " + std::to_string(exc.last_step) +
                      " iterations (residual " +
                      std::to_string(exc.last_residual) + " against " +
                      std::to_string(control.tolerance()) +
                      "). Its iterations grow with the time step over the "
                      "time a wave takes to cross an element, and with "
                      "stiff contact springs: use a shorter time step, "
                      "CG-AMG (without friction) or direct."));
      }
    return control.last_step();
  }
} // namespace ndda
