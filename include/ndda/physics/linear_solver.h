// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_linear_solver_h
#define ndda_physics_linear_solver_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ndda/physics/physics_parameters.h>

#include <memory>

namespace ndda
{
  using namespace dealii;

  class DistributedSolver;
  class SerialWork;

  /**
   * The one place where the linear algebra back end is chosen (DESIGN.md
   * decision 1). The system matrix is assembled as a deal.II SparseMatrix;
   * factorize() prepares a solver for it (an UMFPACK or KLU factorization,
   * or an AMG preconditioner for CG), and solve() may then be called any
   * number of times with new right-hand sides. A scene whose matrix does
   * not change pays for one factorization only.
   *
   * MUMPS and, on a @p communicator of more than one process
   * (`mpirun -np N`), CG-AMG are solved by the processes of @p communicator
   * together (DistributedSolver), each holding the same matrix and
   * right-hand side. The serial solvers (direct, UMFPACK, KLU) stay
   * serial: the first process factorizes and solves, and sends the
   * solution (and any error) to the others, so that a run on several
   * processes repeats the run on one to the bit and only one process
   * holds the factors. Every process gets the same solution, to the
   * bit.
   *
   * @ingroup physics
   */
  class LinearSolver
  {
  public:
    LinearSolver(const parameters::LinearSolverType type,
                 const double                       tolerance,
                 const MPI_Comm communicator = MPI_COMM_SELF);
    ~LinearSolver();

    /**
     * Give CG-AMG the rigid-body modes (two translations and the rotation)
     * as the near null space of the operator, from the location and vector
     * component of every dof. Without it, ML sees translations only.
     */
    void
    set_rigid_body_modes(const std::vector<Point<2>>     &location,
                         const std::vector<unsigned int> &component);

    /**
     * The process that owns each row of the matrices to come, for CG-AMG
     * on several processes (DistributedSolver::set_row_owners()). MUMPS
     * keeps METIS's split of the rows, which measured faster for it; the
     * serial solvers have no split.
     */
    void
    set_row_owners(const std::vector<unsigned int> &owners);

    /** Prepare for solves with @p matrix (kept by reference for CG-Jacobi,
     * copied for CG-AMG). */
    void
    factorize(const SparseMatrix<double> &matrix);

    /**
     * Solve matrix * x = b. Returns the number of iterations (1 for the
     * direct solvers). Throws ExcMessage if the matrix is singular or CG
     * does not converge.
     */
    unsigned int
    solve(Vector<double> &x, const Vector<double> &b);

    /**
     * Solve matrix * x = b with GMRES, preconditioned by the factorization
     * of an earlier matrix of the same size (UMFPACK or KLU). Meant for the
     * open-close iteration, where the matrix of one iteration differs from
     * the factorized one by a few contact springs, or by small changes of
     * the contact geometry from step to step: a preconditioner that is
     * exact up to a low-rank or small perturbation converges in a few
     * iterations, each one triangular solve and one product with the
     * matrix, instead of a new factorization.
     *
     * GMRES may take @p min_iterations solves with the factorization, or
     * more where a factorization costs more (solves_per_factorization(),
     * at most 100); from its fourth on it gives up as soon as neither its
     * residual's mean rate since the first nor its rate over the last two
     * would reach the tolerance within them.
     *
     * Returns the solves with the factorization it took, or 0 if there is no
     * such factorization or GMRES did not reduce the residual to @p tolerance
     * times |b| within its iterations; x is then undefined, and the
     * caller factorizes the matrix instead.
     */
    unsigned int
    solve_with_earlier_factorization(const SparseMatrix<double> &matrix,
                                     Vector<double>             &x,
                                     const Vector<double>       &b,
                                     const unsigned int          min_iterations,
                                     const double                tolerance);

    /**
     * The cost of the last factorization (CHOLMOD, UMFPACK, KLU, MUMPS)
     * in iterations with it, each one solve with the factors and one
     * product with the matrix. For the serial solvers, fifteen iterations
     * plus the ratio of the floating point operations divided by how much
     * faster the factorization runs its flops (CHOLMOD 3.5, UMFPACK 10,
     * KLU 2; doc/performance.md, "The cost of a factorization in
     * iterations"); for MUMPS the ratio of the flops. 0 for the
     * iterative solvers or before the first factorization. It depends on
     * the sparsity pattern and pivot order alone.
     */
    double
    solves_per_factorization() const;

    /**
     * The most GMRES iterations solve_with_earlier_factorization() takes
     * with at least @p min_iterations: solves_per_factorization(), at
     * most 100.
     */
    unsigned int
    reuse_limit(const unsigned int min_iterations) const;

    /**
     * Forget the factorization, its symbolic analysis and the GMRES
     * storage: the next solve factorizes anew, as a process that never had
     * one does (a run resumed from a checkpoint).
     */
    void
    forget_factorization();

    /** Number of factorizations so far. */
    unsigned int
    n_factorizations() const
    {
      return factorization_count;
    }

  private:
    /** What factorize(), solve(), solve_with_earlier_factorization() and
     * solves_per_factorization() do on the process that does the work. */
    void
    factorize_here(const SparseMatrix<double> &matrix);
    unsigned int
    solve_here(Vector<double> &x, const Vector<double> &b);
    unsigned int
    reuse_here(const SparseMatrix<double> &matrix,
               Vector<double>             &x,
               const Vector<double>       &b,
               const unsigned int          min_iterations,
               const double                tolerance);
    double
    solves_per_factorization_here() const;

    /** Send the first process's solution @p x (of size @p n) to all. */
    void
    send_solution(Vector<double> &x, const std::size_t n) const;

    /** solve_with_earlier_factorization() with the DistributedSolver. */
    unsigned int
    distributed_reuse(const SparseMatrix<double> &matrix,
                      Vector<double>             &x,
                      const Vector<double>       &b,
                      const unsigned int          min_iterations,
                      const double                tolerance);

    struct Implementation;
    const parameters::LinearSolverType type;
    const double                       tolerance;
    std::unique_ptr<Implementation>    implementation;
    /// The solver of several processes, or of MUMPS (else null).
    std::unique_ptr<DistributedSolver> distributed;
    /// The processes of the run; whether a serial solver on several of
    /// them works on the first one only, and the cost of its last
    /// factorization there, sent to all.
    MPI_Comm communicator         = MPI_COMM_SELF;
    bool     first_process_solves = false;
    /// The first process's work and the others' wait, when it solves.
    std::unique_ptr<SerialWork> serial_work;
    double                      sent_solve_ratio = 0;
    std::vector<double>         rigid_body_modes;
    unsigned int                factorization_count = 0;
  };
} // namespace ndda

#endif
