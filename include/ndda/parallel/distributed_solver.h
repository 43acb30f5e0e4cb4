// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_parallel_distributed_solver_h
#define ndda_parallel_distributed_solver_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace ndda
{
  using namespace dealii;

  /**
   * @defgroup parallel Parallel
   * Running on several MPI processes (issue 19).
   */

  /**
   * Solve a linear system with the processes of an MPI communicator, each
   * process holding the rows of its part of the matrix in Trilinos'
   * distributed matrices and vectors, with a parallel direct solver (MUMPS
   * through Trilinos' Amesos) or CG preconditioned by smoothed-aggregation
   * AMG (Trilinos' ML, with the rigid-body modes as its near null space).
   *
   * The matrix comes in whole, the same on every process (ndda's serial
   * assembly, replicated), and the solution goes out whole on every
   * process. Each row belongs to the process that the caller says owns it
   * (set_row_owners(): in a scene, the owner of its dof in the shared
   * triangulation); without owners the rows are split by METIS on the
   * graph of the matrix (deal.II's SparsityTools::partition(), computed
   * on the first process and sent to the others, so that every process
   * has the same split). With one process it is the same code on one part.
   *
   * MUMPS's solution agrees with a serial direct solver to round-off
   * (tests/distributed_solver.cc), and CG-AMG's to its tolerance. With one
   * process both repeat their results to the bit from run to run; MUMPS
   * on several processes does not (its parallel factorization varies in
   * the last bits, doc/performance.md, "MPI, first stage").
   *
   * @ingroup parallel
   */
  class DistributedSolver
  {
  public:
    enum class Method
    {
      /// MUMPS (Amesos_Mumps): its symmetric positive definite
      /// factorization, or its general LU, see factorize().
      mumps,
      /// CG with an ML AMG preconditioner, to a relative residual.
      cg_amg
    };

    /** The method's name, as the benchmarks print it. */
    static std::string
    name(const Method method);

    /**
     * @p tolerance is CG's relative residual |b - Ax| / |b| (unused by
     * MUMPS).
     */
    DistributedSolver(const MPI_Comm communicator,
                      const Method   method,
                      const double   tolerance = 1e-12);
    ~DistributedSolver();

    /**
     * Give CG-AMG the rigid-body modes (two translations and the rotation)
     * from the location and vector component of every dof, as
     * LinearSolver::set_rigid_body_modes().
     */
    void
    set_rigid_body_modes(const std::vector<Point<2>>     &location,
                         const std::vector<unsigned int> &component);

    /**
     * The process that owns each row of the matrices to come, the same on
     * every process; an empty list, or one whose size is not the
     * matrix's, leaves the split to METIS. A new list makes the next
     * factorize() split the rows anew.
     */
    void
    set_row_owners(const std::vector<unsigned int> &owners);

    /**
     * Split the rows of @p matrix (the same on every process) among the
     * processes, copy each process's rows into the distributed matrix, and
     * factorize it (MUMPS) or build the AMG hierarchy. While the pattern
     * is the one of the last call, the split, the distributed matrix's
     * pattern and MUMPS's analysis are kept, and only the values are
     * copied and factorized. @p symmetric_positive_definite tells MUMPS it
     * may use its symmetric factorization. Collective.
     */
    void
    factorize(const SparseMatrix<double> &matrix,
              const bool                  symmetric_positive_definite);

    /**
     * Solve matrix * x = b; @p b is the same on every process, @p x comes
     * back whole and the same on every process. Returns the number of CG
     * iterations, 1 for MUMPS. Collective.
     */
    unsigned int
    solve(Vector<double> &x, const Vector<double> &b);

    /** The rows of this process. */
    const IndexSet &
    locally_owned_rows() const;

    /** The size of the factorized matrix, 0 before factorize(). */
    std::size_t
    size() const;

    /**
     * The cost of MUMPS's last factorization in solves (its flops over
     * those of one solve with its factors and one product with the
     * matrix), the same on every process; 0 for CG-AMG.
     */
    double
    solves_per_factorization() const;

    /** Forget the split and the factorization: the next factorize() starts
     * anew. */
    void
    forget_factorization();

  private:
    struct Implementation;

    const MPI_Comm      communicator;
    const Method        method;
    const double        tolerance;
    std::vector<double> rigid_body_modes;
    /// See set_row_owners().
    std::vector<unsigned int>       row_owners;
    std::unique_ptr<Implementation> implementation;
  };
} // namespace ndda

#endif
