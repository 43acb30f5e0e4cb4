// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/parallel.h>

#include <ndda/base/threads.h>

#include <limits>
#include <vector>

namespace ndda
{
  void
  set_up_threads()
  {
    // Four times the grain size must not overflow: deal.II compares a
    // vector's length with that.
    dealii::internal::VectorImplementation::minimum_parallel_grain_size =
      std::numeric_limits<unsigned int>::max() / 8;
  }



  double
  matrix_scalar_product(const dealii::SparseMatrix<double> &A,
                        const dealii::Vector<double>       &u,
                        const dealii::Vector<double>       &v)
  {
    AssertDimension(A.m(), u.size());
    AssertDimension(A.n(), v.size());
    // A v row by row (vmult() sums each row's entries in their order, as
    // deal.II's matrix_scalar_product() does, on the threads), then
    // u_i (A v)_i summed in row order on one thread.
    dealii::Vector<double> Av(A.m());
    A.vmult(Av, v);
    double sum = 0;
    for (unsigned int i = 0; i < Av.size(); ++i)
      sum += u[i] * Av[i];
    return sum;
  }



  double
  matrix_norm_square(const dealii::SparseMatrix<double> &A,
                     const dealii::Vector<double>       &v)
  {
    return matrix_scalar_product(A, v, v);
  }
} // namespace ndda
