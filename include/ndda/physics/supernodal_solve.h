// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_supernodal_solve_h
#define ndda_physics_supernodal_solve_h

#include <cstddef>
#include <utility>
#include <vector>

namespace ndda
{
  /**
   * The forward and backward substitution x = A^-1 b with a supernodal
   * Cholesky factor L L^T = P A P^T in CHOLMOD's layout, on deal.II's
   * threads.
   *
   * A supernode is a range of columns of L that share their rows below
   * the diagonal block; its values are a dense column-major block. The
   * supernodes form a tree (the parent is the supernode of the first row
   * below the diagonal block), numbered in postorder, so that every
   * subtree is a range of supernodes. initialize() picks disjoint
   * subtrees of about equal work, one set per thread; the supernodes of
   * no chosen subtree (the separators near the root) are the serial top.
   *
   * Forward (L y = P b): the threads run their subtrees, each writing the
   * rows of its own subtree and keeping its contributions to the rows
   * outside (all in the top) in a list; then, in the order of the
   * supernodes, the top's supernodes run and each subtree's list is
   * applied where the subtree stands in that order. Backward
   * (L^T z = y): the top first, then the subtrees on the threads, which
   * only read the top. Each row therefore sees the same operations in
   * the same order as in one pass over the supernodes, and the solution
   * is the same to the bit whatever the number of threads (and whatever
   * subtrees were chosen).
   *
   * The arithmetic is ndda's own loops, not the BLAS's: with dgemv for
   * the larger blocks, one of two runs of a scene had other results (163
   * matrix builds where every other run had 161; the serial OpenBLAS
   * that Debian ships is not known to be safe from two threads at once).
   * They take four columns of a supernode at a time (each row still
   * receives the columns' terms in column order: the same bits as one
   * column at a time), so that the rows' running sums are read and
   * written once per four columns (doc/performance.md, "Four columns at
   * a time in the substitutions").
   * The solution agrees with cholmod_solve()'s (a BLAS triangular solve
   * and product per supernode) to round-off, not to the bit. On one
   * thread it was about as fast at 1e4 DoFs and 15-30 % slower at 1e5
   * before the four-column kernels, which took about 7 % off; the gain
   * is the threads (doc/performance.md, "The substitutions on threads").
   *
   * @ingroup physics
   */
  class SupernodalSolve
  {
  public:
    /** A supernodal factor as CHOLMOD holds it (not owned, not copied). */
    struct Factor
    {
      long          n      = 0;
      long          nsuper = 0;
      const long   *super  = nullptr; ///< first column of each supernode
      const long   *pi     = nullptr; ///< start of each supernode's rows in s
      const long   *px     = nullptr; ///< start of its values in x
      const long   *s      = nullptr; ///< the row indices
      const long   *perm   = nullptr; ///< row k of P A P^T is row perm[k] of A
      const double *x      = nullptr; ///< the values
    };

    /** Take @p factor and split its tree among @p n_threads threads. */
    void
    initialize(const Factor &factor, const unsigned int n_threads);

    /** @p x = A^-1 @p b (both of size n; they may be the same array). */
    void
    solve(double *x, const double *b) const;

    /** The number of subtrees run on threads, 0 on one thread. */
    std::size_t
    n_subtrees() const;

  private:
    void
    forward(const long                            s,
            const long                            rows_end,
            std::vector<double>                  &e,
            std::vector<std::pair<long, double>> *outside) const;
    void
    backward(const long s, std::vector<double> &gathered) const;

    Factor L;
    /// The chosen subtrees: first and last supernode, and the thread.
    std::vector<long>         subtree_first, subtree_last;
    std::vector<unsigned int> subtree_thread;
    unsigned int              n_threads = 1;
    /// Workspace: the permuted vector, each subtree's contributions to
    /// rows outside it, a buffer per thread.
    mutable std::vector<double>                               y;
    mutable std::vector<std::vector<std::pair<long, double>>> outside;
    mutable std::vector<std::vector<double>>                  buffer;
  };
} // namespace ndda

#endif
