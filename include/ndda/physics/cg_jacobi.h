// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_cg_jacobi_h
#define ndda_physics_cg_jacobi_h

#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

namespace ndda
{
  using namespace dealii;

  /**
   * `Linear solver = CG-Jacobi`: conjugate gradients on ndda's own matrix,
   * preconditioned by its inverse diagonal; BiCGStab where sliding friction
   * makes the matrix non-symmetric (or a diagonal entry is not positive).
   * Nothing is copied or factorized: the solver keeps a pointer to the matrix
   * and one vector, so its memory is the matrix's and five vectors' (the least
   * of ndda's solvers; the one that lets a 1e7-DoF continuum fit a 24 GB
   * machine, doc/performance.md). The matrix-vector products and vector
   * operations run on deal.II's threads, with the same result for any number of
   * threads.
   *
   * Its iterations grow with the square root of the condition number of
   * the diagonally scaled matrix. In a dynamic analysis (`K + c M`) that
   * is about the number of elements a wave crosses in one time step, so
   * it suits time steps near the wave-resolving one, and continua whose
   * matrix does not change; a static analysis, or a time step far longer
   * than the waves' crossing of an element, wants CG-AMG or a direct
   * solver.
   *
   * @ingroup physics
   */
  class JacobiCG
  {
  public:
    /**
     * Solve with @p matrix from now on (kept by pointer: it must not move
     * or change until the next initialize()): with CG if it is symmetric
     * and its diagonal positive, else with BiCGStab.
     */
    void
    initialize(const SparseMatrix<double> &matrix);

    /**
     * Solve matrix x = b from x = 0 to the residual @p relative_tolerance
     * |b|; returns the iterations. Throws ExcMessage if it does not
     * converge.
     */
    unsigned int
    solve(Vector<double>       &x,
          const Vector<double> &b,
          const double          relative_tolerance) const;

    /** The size of the matrix of the last initialize(), or 0. */
    types::global_dof_index
    size() const
    {
      return matrix == nullptr ? 0 : matrix->m();
    }

  private:
    /// A plain pointer: the matrix's owner (LinearSystem) may destroy it
    /// before this solver.
    const SparseMatrix<double>    *matrix = nullptr;
    DiagonalMatrix<Vector<double>> inverse_diagonal;
    bool                           symmetric = true;
  };
} // namespace ndda

#endif
