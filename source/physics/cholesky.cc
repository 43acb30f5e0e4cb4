// SPDX-License-Identifier: GPL-3.0-or-later
#include <deal.II/base/exceptions.h>
#include <deal.II/base/multithread_info.h>

#include <ndda/physics/cholesky.h>
#include <ndda/physics/suitesparse_setup.h>
#include <ndda/physics/supernodal_solve.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <suitesparse/cholmod.h>
#include <utility>
#include <vector>

namespace ndda
{
  using namespace dealii;

  bool
  is_symmetric(const SparseMatrix<double> &matrix, const double tolerance)
  {
    if (matrix.m() != matrix.n())
      return false;
    for (types::global_dof_index i = 0; i < matrix.m(); ++i)
      for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
        {
          const auto j = entry->column();
          if (j <= i)
            continue;
          // el() is zero for an entry outside the pattern.
          const double difference = std::abs(entry->value() - matrix.el(j, i));
          if (difference > 0. &&
              difference >
                tolerance * std::sqrt(std::abs(matrix.diag_element(i) *
                                               matrix.diag_element(j))))
            return false;
        }
    return true;
  }



  struct CholeskyFactorization::Implementation
  {
    Implementation()
    {
      set_up_suitesparse();
      cholmod_l_start(&common);
      // Not positive definite is an answer here, not an error to print.
      common.print = 0;
      // Always L L^T (supernodal): a simplicial L D L^T would factorize a
      // symmetric indefinite matrix without a word.
      common.supernodal = CHOLMOD_SUPERNODAL;
    }

    ~Implementation()
    {
      free_factor();
      cholmod_l_finish(&common);
    }

    void
    free_factor()
    {
      if (factor != nullptr)
        cholmod_l_free_factor(&factor, &common);
      factor = nullptr;
    }

    /**
     * The upper triangle of @p matrix by rows, sorted: the lower triangle
     * by columns, as CHOLMOD reads it (stype -1). Returns whether the
     * pattern changed.
     */
    bool
    update(const SparseMatrix<double> &matrix)
    {
      return copy_to_compressed_rows(matrix, true, p, i, values);
    }

    /** A CHOLMOD view of the arrays (no copy). */
    cholmod_sparse
    view()
    {
      cholmod_sparse a = {};
      a.nrow           = p.size() - 1;
      a.ncol           = p.size() - 1;
      a.nzmax          = i.size();
      a.p              = p.data();
      a.i              = i.data();
      a.x              = values.data();
      a.stype          = -1;
      a.itype          = CHOLMOD_LONG;
      a.xtype          = CHOLMOD_REAL;
      a.dtype          = CHOLMOD_DOUBLE;
      a.sorted         = 1;
      a.packed         = 1;
      return a;
    }

    void
    solve(Vector<double> &result, const Vector<double> &b)
    {
      AssertThrow(factor != nullptr && b.size() == p.size() - 1,
                  ExcMessage("CHOLMOD: no factorization of this size."));
      result.reinit(b.size(), true);
      substitution.solve(result.begin(), b.begin());
    }

    /// The substitutions with the factor, on threads.
    void
    set_up_substitution()
    {
      SupernodalSolve::Factor f;
      f.n      = factor->n;
      f.nsuper = factor->nsuper;
      f.super  = static_cast<const long *>(factor->super);
      f.pi     = static_cast<const long *>(factor->pi);
      f.px     = static_cast<const long *>(factor->px);
      f.s      = static_cast<const long *>(factor->s);
      f.perm   = static_cast<const long *>(factor->Perm);
      f.x      = static_cast<const double *>(factor->x);
      substitution.initialize(f, MultithreadInfo::n_threads());
    }

    cholmod_common                common;
    cholmod_factor               *factor = nullptr;
    SupernodalSolve               substitution;
    std::vector<SuiteSparse_long> p, i;
    std::vector<double>           values;
    double                        solve_ratio = 0;
    /// Whether the last factorization with this pattern found the matrix
    /// not positive definite.
    bool refused = false;
  };



  CholeskyFactorization::CholeskyFactorization()
    : implementation(std::make_unique<Implementation>())
  {}



  CholeskyFactorization::~CholeskyFactorization() = default;



  bool
  CholeskyFactorization::factorize(const SparseMatrix<double> &matrix)
  {
    auto &impl = *implementation;
    if (!is_symmetric(matrix))
      return false;
    const bool     new_pattern = impl.update(matrix);
    cholmod_sparse a           = impl.view();
    if (new_pattern || impl.factor == nullptr)
      {
        impl.free_factor();
        impl.factor = cholmod_l_analyze(&a, &impl.common);
        AssertThrow(impl.factor != nullptr,
                    ExcMessage("CHOLMOD: the analysis failed with status " +
                               std::to_string(impl.common.status) + "."));
      }
    else if (impl.refused)
      // Not positive definite before, with this pattern: the values of a
      // step rarely change that, so LU is taken at once.
      return false;
    impl.refused = false;
    if (!cholmod_l_factorize(&a, impl.factor, &impl.common) ||
        impl.common.status == CHOLMOD_NOT_POSDEF)
      {
        // The analysis stays for this pattern, marked as refused.
        impl.refused = true;
        return false;
      }
    // Flops of the factorization (CHOLMOD's count from the analysis) over
    // those of a solve: 2 nnz(L) multiply-adds, and a product with A.
    impl.solve_ratio =
      impl.common.fl / (2. * (2. * impl.common.lnz + 2. * impl.i.size()));
    AssertThrow(impl.factor->is_super && impl.factor->is_ll &&
                  impl.factor->xtype == CHOLMOD_REAL,
                ExcMessage("CHOLMOD: the factor is not a real supernodal "
                           "L L^T."));
    impl.set_up_substitution();
    return true;
  }



  void
  CholeskyFactorization::solve(Vector<double> &x, const Vector<double> &b)
  {
    implementation->solve(x, b);
  }



  void
  CholeskyFactorization::vmult(Vector<double> &x, const Vector<double> &b) const
  {
    // The substitutions keep their workspace in the implementation.
    implementation->solve(x, b);
  }



  std::size_t
  CholeskyFactorization::size() const
  {
    const auto &impl = *implementation;
    return impl.factor == nullptr || impl.refused ? 0 : impl.p.size() - 1;
  }



  double
  CholeskyFactorization::solves_per_factorization() const
  {
    return implementation->solve_ratio;
  }



  std::size_t
  CholeskyFactorization::n_parallel_subtrees() const
  {
    return implementation->substitution.n_subtrees();
  }
} // namespace ndda
