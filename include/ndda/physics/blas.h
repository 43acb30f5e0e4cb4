// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_blas_h
#define ndda_physics_blas_h

#include <string>

namespace ndda
{
  /**
   * The BLAS that the direct solvers' dense kernels run on, as the log
   * names it: the library that provides `dgemm_` in this process (Debian
   * chooses it with update-alternatives, `LD_LIBRARY_PATH` can override
   * it), with OpenBLAS's version and configuration when it is OpenBLAS,
   * e.g. "OpenBLAS 0.3.21 DYNAMIC_ARCH NO_AFFINITY Zen SINGLE_THREADED
   * (/usr/lib/x86_64-linux-gnu/openblas-serial/libblas.so.3)". UMFPACK's
   * numeric factorization spends most of its time in `dgemm_`: OpenBLAS
   * makes it 3 to 5 times faster than the reference BLAS
   * (doc/performance.md), and `ndda.sh` installs it.
   *
   * @ingroup physics
   */
  std::string
  blas_description();
} // namespace ndda

#endif
