// SPDX-License-Identifier: GPL-3.0-or-later
//
// CholeskyFactorization (CHOLMOD) and Linear solver = direct (issue 19):
//
//  1. a symmetric positive definite matrix (a 2D five-point Laplacian plus
//     a mass term, 400 unknowns) is factorized; the solution agrees with
//     UMFPACK's LU to 1e-12 and its residual is below 1e-12;
//  2. new values on the same pattern are factorized again (the analysis
//     kept), and solved as well;
//  3. a symmetric indefinite matrix (one negative diagonal entry) and a
//     non-symmetric one are refused (factorize() false, size 0); is_symmetric
//     accepts a difference of 1e-14 of the diagonal scale and refuses 1e-6;
//  4. LinearSolver with `direct` solves all three correctly (LU where the
//     Cholesky factorization refuses), with Cholesky's flop ratio on the
//     SPD matrix, UMFPACK's on the others;
//  5. GMRES with an earlier Cholesky factorization on a symmetric change
//     of rank 3 converges to 1e-12;
//  7. the substitutions on threads (SupernodalSolve): a five-point
//     Laplacian of 160 x 160 unknowns, factorized on 1, 2 and 3 threads,
//     is solved in subtrees on threads when there are several, to the bit
//     the solution of one thread, and agrees with UMFPACK to 1e-12;
//  8. SuiteSparse's allocator as set_up_suitesparse() leaves it: a block of
//     the huge-page threshold starts on a 2 MB boundary, calloc'ed ones
//     are zero, and growing, shrinking and moving blocks between malloc()
//     and huge-page mappings keeps their contents; OpenMP runs one thread.

#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <ndda/physics/cholesky.h>
#include <ndda/physics/linear_solver.h>
#include <ndda/physics/suitesparse_setup.h>

#include <cmath>
#include <cstdint>
#include <iostream>
#include <omp.h>
#include <suitesparse/SuiteSparse_config.h>

#include "tests.h"

using namespace dealii;
using namespace ndda;
using ndda_tests::check;

namespace
{
  constexpr unsigned int side = 20, n = side * side;

  SparsityPattern
  five_point_pattern()
  {
    DynamicSparsityPattern dsp(n);
    for (unsigned int i = 0; i < side; ++i)
      for (unsigned int j = 0; j < side; ++j)
        {
          const unsigned int r = i * side + j;
          dsp.add(r, r);
          if (i > 0)
            dsp.add(r, r - side);
          if (i + 1 < side)
            dsp.add(r, r + side);
          if (j > 0)
            dsp.add(r, r - 1);
          if (j + 1 < side)
            dsp.add(r, r + 1);
        }
    SparsityPattern pattern;
    pattern.copy_from(dsp);
    return pattern;
  }

  /** 4 + shift on the diagonal, -1 to the four neighbours; symmetric,
   * positive definite for shift > -8 sin^2(pi / (2 (side + 1))). */
  void
  fill(SparseMatrix<double> &a, const double shift)
  {
    a = 0;
    for (unsigned int r = 0; r < n; ++r)
      for (auto entry = a.begin(r); entry != a.end(r); ++entry)
        entry->value() = entry->column() == r ? 4. + shift : -1.;
  }

  Vector<double>
  right_hand_side()
  {
    Vector<double> b(n);
    for (unsigned int i = 0; i < n; ++i)
      b[i] = std::sin(0.7 * i + 1.);
    return b;
  }

  double
  relative_residual(const SparseMatrix<double> &a,
                    const Vector<double>       &x,
                    const Vector<double>       &b)
  {
    Vector<double> r(n);
    a.vmult(r, x);
    r -= b;
    return r.l2_norm() / b.l2_norm();
  }

  Vector<double>
  lu_solution(const SparseMatrix<double> &a, const Vector<double> &b)
  {
    LinearSolver lu(parameters::LinearSolverType::umfpack, 0.);
    lu.factorize(a);
    Vector<double> x;
    lu.solve(x, b);
    return x;
  }

  double
  relative_difference(Vector<double> x, const Vector<double> &y)
  {
    x -= y;
    return x.l2_norm() / y.l2_norm();
  }

  /**
   * 7.: the Laplacian of @p m x @p m unknowns plus a mass term, solved on
   * 1, 2 and 3 threads.
   */
  void
  check_threaded_substitution(const unsigned int m)
  {
    DynamicSparsityPattern dsp(m * m);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < m; ++j)
        for (const auto &[di, dj] : {std::pair(0, 0),
                                     std::pair(-1, 0),
                                     std::pair(1, 0),
                                     std::pair(0, -1),
                                     std::pair(0, 1)})
          if (int(i) + di >= 0 && int(i) + di < int(m) && int(j) + dj >= 0 &&
              int(j) + dj < int(m))
            dsp.add(i * m + j, (i + di) * m + j + dj);
    SparsityPattern pattern;
    pattern.copy_from(dsp);
    SparseMatrix<double> a(pattern);
    for (unsigned int r = 0; r < m * m; ++r)
      for (auto entry = a.begin(r); entry != a.end(r); ++entry)
        entry->value() = entry->column() == r ? 4.01 : -1.;
    Vector<double> b(m * m);
    for (unsigned int i = 0; i < b.size(); ++i)
      b[i] = std::sin(0.7 * i + 1.);
    LinearSolver lu(parameters::LinearSolverType::umfpack, 0.);
    lu.factorize(a);
    Vector<double> reference;
    lu.solve(reference, b);

    const unsigned int threads = MultithreadInfo::n_threads();
    Vector<double>     one_thread;
    for (const unsigned int n_threads : {1u, 2u, 3u})
      {
        MultithreadInfo::set_thread_limit(n_threads);
        CholeskyFactorization cholesky;
        check(cholesky.factorize(a), "the large Laplacian is factorized");
        Vector<double> x;
        cholesky.solve(x, b);
        const double difference = relative_difference(x, reference);
        std::cout << "Laplacian " << m << " x " << m << ", " << n_threads
                  << " thread(s): " << cholesky.n_parallel_subtrees()
                  << " subtrees on threads, against LU " << difference
                  << std::endl;
        check(difference < 1e-12, "the threaded solution is UMFPACK's");
        check((n_threads == 1) == (cholesky.n_parallel_subtrees() == 0),
              "subtrees on threads exactly when there are several");
        if (n_threads == 1)
          one_thread = x;
        bool same = true;
        for (unsigned int i = 0; i < x.size(); ++i)
          same = same && x[i] == one_thread[i];
        check(same,
              "the solution is the same to the bit on every number "
              "of threads");
      }
    MultithreadInfo::set_thread_limit(threads);
  }

  /** Fill @p n bytes at @p block with a pattern that depends on @p seed. */
  void
  write_pattern(void *block, const std::size_t n, const unsigned int seed)
  {
    auto *const bytes = static_cast<unsigned char *>(block);
    for (std::size_t i = 0; i < n; ++i)
      bytes[i] = static_cast<unsigned char>((i * 131 + seed) % 251);
  }

  bool
  has_pattern(const void *block, const std::size_t n, const unsigned int seed)
  {
    const auto *const bytes = static_cast<const unsigned char *>(block);
    for (std::size_t i = 0; i < n; ++i)
      if (bytes[i] != static_cast<unsigned char>((i * 131 + seed) % 251))
        return false;
    return true;
  }

  void
  check_allocator()
  {
    set_up_suitesparse();
    check(omp_get_max_active_levels() == 0, "OpenMP regions run on one thread");
    const std::size_t huge  = huge_page_threshold();
    const std::size_t small = 1000;
    int               ok    = 0;

    void *block = SuiteSparse_malloc(huge, 1);
    check(block != nullptr &&
            reinterpret_cast<std::uintptr_t>(block) % (2u << 20) == 0,
          "a huge block starts on a 2 MB boundary");
    write_pattern(block, huge, 1);
    // Grow (the pages moved to a new mapping), twice, then shrink in
    // place, then move below the threshold to malloc().
    block = SuiteSparse_realloc(3 * huge, huge, 1, block, &ok);
    check(ok && has_pattern(block, huge, 1) &&
            reinterpret_cast<std::uintptr_t>(block) % (2u << 20) == 0,
          "growing keeps the contents and the 2 MB boundary");
    write_pattern(block, 3 * huge, 2);
    block = SuiteSparse_realloc(5 * huge + 7, 3 * huge, 1, block, &ok);
    check(ok && has_pattern(block, 3 * huge, 2),
          "growing again keeps the contents");
    write_pattern(block, 5 * huge + 7, 2);
    block = SuiteSparse_realloc(3 * huge, 5 * huge + 7, 1, block, &ok);
    check(ok && has_pattern(block, 3 * huge, 2), "shrinking keeps them");
    block = SuiteSparse_realloc(huge + 5, 3 * huge, 1, block, &ok);
    check(ok && has_pattern(block, huge + 5, 2), "shrinking keeps them");
    block = SuiteSparse_realloc(small, huge + 5, 1, block, &ok);
    check(ok && has_pattern(block, small, 2), "moving to malloc() keeps them");
    // And from malloc() to a mapping.
    block = SuiteSparse_realloc(2 * huge, small, 1, block, &ok);
    check(ok && has_pattern(block, small, 2),
          "moving from malloc() keeps them");
    SuiteSparse_free(block);

    auto *const zeros =
      static_cast<double *>(SuiteSparse_calloc(huge / sizeof(double), 8));
    bool all_zero = zeros != nullptr;
    for (std::size_t i = 0; all_zero && i < huge / sizeof(double); ++i)
      all_zero = zeros[i] == 0.;
    check(all_zero, "a huge calloc'ed block is zero");
    SuiteSparse_free(zeros);
    std::cout << "allocator: huge blocks of " << huge / (1 << 20)
              << " MiB and more aligned, contents kept, zeros zero"
              << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const SparsityPattern            pattern = five_point_pattern();
  SparseMatrix<double> spd(pattern), indefinite(pattern), nonsymmetric(pattern);
  fill(spd, 0.01);
  fill(indefinite, 0.01);
  indefinite.set(n / 2, n / 2, -3.);
  fill(nonsymmetric, 0.01);
  nonsymmetric.set(5, 6, -1.5);
  const Vector<double> b = right_hand_side();

  // 1. and 2.
  CholeskyFactorization cholesky;
  for (const double shift : {0.01, 1.})
    {
      fill(spd, shift);
      check(cholesky.factorize(spd) && cholesky.size() == n,
            "an SPD matrix is factorized");
      Vector<double> x;
      cholesky.solve(x, b);
      const double difference = relative_difference(x, lu_solution(spd, b));
      const double residual   = relative_residual(spd, x, b);
      std::cout << "SPD, shift " << shift << ": against LU " << difference
                << ", residual " << residual << std::endl;
      check(difference < 1e-12 && residual < 1e-12,
            "the Cholesky solution is UMFPACK's");
    }

  // 3.
  check(!cholesky.factorize(indefinite) && cholesky.size() == 0,
        "a symmetric indefinite matrix is refused");
  check(!cholesky.factorize(nonsymmetric) && cholesky.size() == 0,
        "a non-symmetric matrix is refused");
  SparseMatrix<double> almost(pattern);
  fill(almost, 0.01);
  almost.set(5, 6, -1. + 4e-14);
  check(is_symmetric(almost), "a round-off difference is symmetric");
  almost.set(5, 6, -1. + 4e-6);
  check(!is_symmetric(almost), "a difference of 1e-6 is not");

  // 4.
  fill(spd, 0.01);
  for (const auto &[matrix, name] :
       {std::make_pair(&spd, "SPD"),
        std::make_pair(&indefinite, "symmetric indefinite"),
        std::make_pair(&nonsymmetric, "non-symmetric")})
    {
      LinearSolver direct(parameters::LinearSolverType::direct, 0.);
      direct.factorize(*matrix);
      Vector<double> x;
      direct.solve(x, b);
      const double residual = relative_residual(*matrix, x, b);
      std::cout << "direct, " << name << ": residual " << residual
                << ", factorization = " << direct.solves_per_factorization()
                << " solves" << std::endl;
      check(residual < 1e-12, std::string("direct solves the ") + name);
      check(direct.solves_per_factorization() > 0,
            "the factorization's cost is known");
    }

  // 5.
  LinearSolver direct(parameters::LinearSolverType::direct, 0.);
  direct.factorize(spd);
  SparseMatrix<double> changed(pattern);
  changed.copy_from(spd);
  for (const unsigned int row : {3u, 150u, 377u})
    changed.add(row, row, 1.5);
  Vector<double>     x;
  const unsigned int iterations =
    direct.solve_with_earlier_factorization(changed, x, b, 10, 1e-12);
  const double residual = relative_residual(changed, x, b);
  std::cout << "GMRES with the earlier Cholesky factorization: " << iterations
            << " iterations, residual " << residual << std::endl;
  check(iterations > 0 && residual < 1e-11,
        "GMRES converges with the earlier Cholesky factorization");
  // 7.
  check_threaded_substitution(160);
  // 8.
  check_allocator();
  std::cout << "OK" << std::endl;
  return 0;
}
