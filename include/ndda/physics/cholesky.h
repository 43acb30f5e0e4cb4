// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_cholesky_h
#define ndda_physics_cholesky_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>

namespace ndda
{
  /**
   * A sparse Cholesky factorization A = L L^T of a symmetric positive
   * definite matrix by CHOLMOD (SuiteSparse; supernodal, its dense kernels
   * on the BLAS and LAPACK that Debian selects, OpenBLAS with ndda.sh).
   * Elasticity with inertia, contact springs and exact or penalty
   * constraints gives such matrices; sliding friction does not (its
   * terms are not symmetric), and a structure free to move in a static
   * analysis is singular: factorize() then says no, and LinearSolver falls
   * back to LU (UMFPACK).
   *
   * A Cholesky factorization has half the fill of an LU and no pivoting:
   * about half the flops and memory. The ordering (CHOLMOD's analysis:
   * AMD, or METIS where AMD fills much) depends on the sparsity pattern
   * alone and is kept while it stays.
   *
   * The forward and backward substitutions are ndda's own
   * (SupernodalSolve, on deal.II's threads, the same to the bit on any
   * number of them), not CHOLMOD's cholmod_solve, which runs on one
   * (doc/performance.md, "The substitutions on threads").
   *
   * @ingroup physics
   */
  class CholeskyFactorization
  {
  public:
    CholeskyFactorization();
    ~CholeskyFactorization();
    CholeskyFactorization(const CholeskyFactorization &) = delete;
    CholeskyFactorization &
    operator=(const CholeskyFactorization &) = delete;

    /**
     * Factorize @p matrix if it is symmetric (is_symmetric()) and positive
     * definite; returns whether it did. If not, no factorization is kept.
     */
    bool
    factorize(const dealii::SparseMatrix<double> &matrix);

    /** x = A^-1 b with the last factorization. */
    void
    solve(dealii::Vector<double> &x, const dealii::Vector<double> &b);

    /** The same, as a preconditioner (GMRES with an earlier
     * factorization). */
    void
    vmult(dealii::Vector<double> &x, const dealii::Vector<double> &b) const;

    /** The size of the factorized matrix, 0 if there is none. */
    std::size_t
    size() const;

    /** The flops of the last factorization over those of a forward and
     * backward substitution with L and a product with A, which
     * LinearSolver::solves_per_factorization() turns into a cost. */
    double
    solves_per_factorization() const;

    /** The subtrees of the factor's tree that the substitutions run on
     * threads (SupernodalSolve), 0 if they run on one. */
    std::size_t
    n_parallel_subtrees() const;

  private:
    struct Implementation;
    std::unique_ptr<Implementation> implementation;
  };

  /**
   * Whether @p matrix is symmetric: every a_ij has an a_ji in the pattern
   * with |a_ij - a_ji| <= @p tolerance sqrt(|a_ii a_jj|) (the entries'
   * natural scale; element matrices summed in another order differ in
   * their last bits). One pass over the entries, a binary search each.
   */
  bool
  is_symmetric(const dealii::SparseMatrix<double> &matrix,
               const double                        tolerance = 1e-12);
} // namespace ndda

#endif
