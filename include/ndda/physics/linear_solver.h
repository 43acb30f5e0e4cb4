// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_linear_solver_h
#define ndda_physics_linear_solver_h

#include <deal.II/base/point.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ndda/parameters/parameters.h>

#include <memory>

namespace ndda
{
  using namespace dealii;

  /**
   * The one place where the linear algebra back end is chosen (DESIGN.md
   * decision 1). The system matrix is assembled as a deal.II SparseMatrix;
   * factorize() prepares a solver for it (an UMFPACK or KLU factorization,
   * or an AMG preconditioner for CG), and solve() may then be called any
   * number of times with new right-hand sides. A scene whose matrix does
   * not change pays for one factorization only.
   *
   * @ingroup physics
   */
  class LinearSolver
  {
  public:
    LinearSolver(const parameters::LinearSolver type, const double tolerance);
    ~LinearSolver();

    /**
     * Give CG-AMG the rigid-body modes (two translations and the rotation)
     * as the near null space of the operator, from the location and vector
     * component of every dof. Without it, ML sees translations only.
     */
    void
    set_rigid_body_modes(const std::vector<Point<2>>     &location,
                         const std::vector<unsigned int> &component);

    /** Prepare for solves with @p matrix (kept by reference for CG). */
    void
    factorize(const SparseMatrix<double> &matrix);

    /**
     * Solve matrix * x = b. Returns the number of iterations (1 for the
     * direct solvers). Throws ExcMessage if the matrix is singular or CG
     * does not converge.
     */
    unsigned int
    solve(Vector<double> &x, const Vector<double> &b);

    /** Number of factorizations so far. */
    unsigned int
    n_factorizations() const
    {
      return factorization_count;
    }

  private:
    struct Implementation;
    const parameters::LinearSolver  type;
    const double                    tolerance;
    std::unique_ptr<Implementation> implementation;
    std::vector<double>             rigid_body_modes;
    unsigned int                    factorization_count = 0;
  };
} // namespace ndda

#endif
