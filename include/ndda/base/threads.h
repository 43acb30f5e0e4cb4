// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_base_threads_h
#define ndda_base_threads_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

namespace ndda
{
  /**
   * @name Threads whose number does not change a result
   *
   * ndda runs on deal.II's threads (MultithreadInfo): one unless
   * `ndda --threads N`; the benchmarks take as many as the machine has
   * cores, or `DEAL_II_NUM_THREADS`. A loop on them writes one result per
   * cell or per row into an array of its own; whatever must be summed over
   * cells or rows is summed from that array in order on one thread. So runs
   * on two or more threads agree to the last bit (unit test thread_count:
   * 2 and 3 threads). A run on one thread agrees with them to round-off
   * only: on one thread deal.II's FEValues reuses the mapping data of a
   * cell for the next cell when that is a translation of it, and on more
   * threads it never does (FEValuesBase::check_cell_similarity(), deal.II
   * 9.4), so element matrices differ in their last bits.
   */
  /** @{ */

  /**
   * Keep deal.II's own vector operations on one thread (their parallel
   * grain size set beyond any vector's length): their parallel sums (dot
   * products, norms) split a vector by the number of threads, so that
   * they would change in their last bits with it. SparseMatrix::vmult()
   * stays on the threads (each row is its own sum); ndda does not call
   * deal.II's sums over the rows of a sparse matrix
   * (matrix_norm_square(), matrix_scalar_product(), residual()), whose
   * parallel sums split the rows as TBB chooses, and uses the functions
   * below instead. Simulator's constructor calls this; calling it again
   * does nothing more.
   */
  void
  set_up_threads();

  /**
   * u^T A v: each row's sum (A v)_i u_i on the threads, summed in row
   * order, the same sums as deal.II's SparseMatrix::matrix_scalar_product()
   * on one thread.
   */
  double
  matrix_scalar_product(const dealii::SparseMatrix<double> &A,
                        const dealii::Vector<double>       &u,
                        const dealii::Vector<double>       &v);

  /** v^T A v (matrix_scalar_product() with u = v). */
  double
  matrix_norm_square(const dealii::SparseMatrix<double> &A,
                     const dealii::Vector<double>       &v);

  /** @} */
} // namespace ndda

#endif
