// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_suitesparse_setup_h
#define ndda_physics_suitesparse_setup_h

#include <deal.II/lac/sparse_matrix.h>

#include <cstddef>
#include <suitesparse/SuiteSparse_config.h>
#include <vector>

namespace ndda
{
  /**
   * A fresh anonymous mapping of at least @p size bytes that starts on a
   * 2 MB boundary, with the kernel asked to back it with transparent huge
   * pages (`madvise(MADV_HUGEPAGE)`), or nullptr if there is no memory.
   * Release it with unmap_huge_pages() and the same size. Debian's kernels
   * give huge pages only where a program asks
   * (`/sys/kernel/mm/transparent_hugepage/enabled` is `madvise`);
   * otherwise memory is touched in 4 kB pages, one page fault each, and on
   * the reference machine a fault costs about 12 microseconds (0.35 GB/s
   * of fresh memory, against 17 GB/s in huge pages once the host has
   * backed them; doc/performance.md). The advice is a hint: without
   * transparent huge pages the block works the same.
   *
   * @ingroup physics
   */
  void *
  map_huge_pages(std::size_t size);

  /** Release a block of map_huge_pages(@p size). */
  void
  unmap_huge_pages(void *block, std::size_t size);

  /**
   * The smallest block that SuiteSparse's allocator maps in huge pages
   * (set_up_suitesparse()): 4 MiB. Smaller ones come from malloc().
   */
  constexpr std::size_t
  huge_page_threshold()
  {
    return std::size_t(4) << 20;
  }

  /**
   * Set SuiteSparse (UMFPACK, CHOLMOD, KLU) up for ndda, once per process,
   * before its first factorization (LinearSolver's constructor calls it;
   * later calls do nothing):
   * - blocks of at least huge_page_threshold() bytes are mappings of
   *   their own in huge pages (map_huge_pages()), the others come from
   *   malloc() as before, unless the environment variable
   *   `NDDA_HUGE_PAGES` is `0` (for measurements). Own mappings, not
   *   advice on malloc()'s blocks: glibc serves blocks up to 32 MiB from
   *   its heap, whose pages have been touched already, and advice there
   *   has the kernel's khugepaged merge them later in the background
   *   (single steps 40 ms slower at 1e5 DoFs);
   * - OpenMP runs on one thread (`omp_set_max_active_levels(0)`).
   *   Debian's CHOLMOD 3.0.14 asks for four threads, fixed when it was
   *   compiled, in the scatter loops of its supernodal factorization: on
   *   two cores that oversubscribed them, and a third of its time went to
   *   waking and waiting threads. ndda's threads are TBB's, and its results
   *   do not depend on their number.
   */
  void
  set_up_suitesparse();

  /**
   * Copy @p matrix into compressed rows with sorted column indices, as
   * SuiteSparse reads them (UMFPACK and KLU: the compressed columns of the
   * transpose; CHOLMOD with stype -1: the lower triangle by columns): the
   * row starts @p p, the column indices @p i and the values @p x. With
   * @p upper_only, only the entries on and above the diagonal. Returns
   * whether the sparsity pattern differs from the one in @p p and @p i
   * before the call (then the symbolic analysis must be done again).
   */
  bool
  copy_to_compressed_rows(const dealii::SparseMatrix<double> &matrix,
                          bool                                upper_only,
                          std::vector<SuiteSparse_long>      &p,
                          std::vector<SuiteSparse_long>      &i,
                          std::vector<double>                &x);
} // namespace ndda

#endif
