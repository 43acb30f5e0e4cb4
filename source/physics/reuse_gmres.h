// SPDX-License-Identifier: GPL-3.0-or-later
//
// Private header of source/physics/: GMRES with an earlier factorization
// as preconditioner (ReuseGMRES) and its control (ReuseControl), for
// LinearSolver::solve_with_earlier_factorization() with the serial
// factorizations and with DistributedSolver.
#ifndef ndda_source_physics_reuse_gmres_h
#define ndda_source_physics_reuse_gmres_h


#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ndda
{
  namespace internal
  {
    using namespace dealii;

    /**
     * GMRES's control with an earlier factorization: it fails at
     * @p max_steps iterations, and from the fourth on also as soon as
     * neither the mean rate of the residual since the first iteration nor
     * its rate over the last two would reach the tolerance within
     * @p max_steps: such a solve costs more than the factorization it was
     * to save. The first iteration takes out at once what the earlier
     * factorization still gets right, often all but 1e-3 of the residual;
     * the rate after it is what the changed springs leave. On the
     * 10,050-brick wall the solves that gave up at the tenth iteration,
     * as the rule before this one let them, had mostly stagnated since
     * their second (doc/performance.md). The rate over the last two
     * iterations sees GMRES's rate grow once the outlying eigenvalues are
     * found (a change of low rank). The steps counted are the solves with
     * the factorization.
     */
    class ReuseControl : public SolverControl
    {
    public:
      ReuseControl()
        : SolverControl(1, 0., false, false)
      {}

      /** Set up for the next solve (the control is kept from solve to
       * solve, with the GMRES solvers that refer to it). */
      void
      reset(const unsigned int max_steps,
            const double       tolerance,
            const double       initial)
      {
        set_max_steps(max_steps);
        set_tolerance(tolerance * initial);
        residuals.assign(1, initial);
      }

      State
      check(const unsigned int step, const double value) override
      {
        const State state = SolverControl::check(step, value);
        if (state != iterate)
          return state;
        // The last residual at each step.
        if (residuals.size() <= step)
          residuals.resize(step + 1);
        residuals[step] = value;
        if (step < first_judged)
          return state;
        // The steps a rate needs from here; whether the faster of the
        // mean rate since the first step and that of the last two
        // (GMRES's rate grows once the outlying eigenvalues are found)
        // gets there.
        const auto steps_at = [&](const unsigned int from) {
          const double log_rate =
            std::log(value / residuals[from]) / (step - from);
          return log_rate < 0. ? std::log(tolerance() / value) / log_rate :
                                 std::numeric_limits<double>::infinity();
        };
        if (step + std::min(steps_at(1), steps_at(step - 2)) > max_steps())
          {
            lcheck = failure;
            return failure;
          }
        return state;
      }

    private:
      /// The first solve with the factorization at which the rate is
      /// judged.
      static constexpr unsigned int first_judged = 4;
      /// The last residual at each step of this solve.
      std::vector<double> residuals;
    };



    /**
     * Flexible GMRES (Saad 1993) with right preconditioning and the true
     * residual's estimate as criterion: its search directions P^-1 v are
     * kept, and the solution is x0 + Z y, so it costs no last solve with
     * the factors (right-preconditioned GMRES forms x0 + P^-1 V y). It
     * keeps its vectors, Hessenberg matrix and rotations from solve to
     * solve: deal.II's SolverGMRES allocates them at every call, which
     * cost a single block's step more than its iterations (about 20,000
     * instructions a solve of three unknowns).
     */
    class ReuseGMRES
    {
    public:
      /**
       * Solve A x = b from the x given, preconditioned by @p preconditioner;
       * @p control decides, and counts the solves with the
       * preconditioner: at most @p basis_size - 2 of them in a cycle.
       * Returns whether it converged (if not, x is undefined); the solves
       * with the preconditioner are n_preconditioner_solves().
       *
       * The residual is computed once more at the end (a product with the
       * matrix), and a second cycle from that x goes on where it is above
       * 100 times the tolerance. (Not the tolerance itself: the computed
       * residual of these matrices, made ill-conditioned by the penalty
       * springs, has a floor of its own, 5e-12 of |b| in
       * `statistics_sliding_block`.)
       */
      template <class Preconditioner>
      bool
      solve(const SparseMatrix<double> &A,
            Vector<double>             &x,
            const Vector<double>       &b,
            const Preconditioner       &preconditioner,
            SolverControl              &control,
            const unsigned int          basis_size)
      {
        solves = 0;
        for (unsigned int cycle = 0; cycle < 2; ++cycle)
          {
            if (!run_cycle(A, x, b, preconditioner, control, basis_size))
              return false;
            Vector<double> &r = basis[0];
            A.vmult(r, x);
            r.sadd(-1., 1., b);
            if (r.l2_norm() <= 100. * control.tolerance())
              return true;
          }
        return false;
      }

      /** The solves with the preconditioner of the last solve(). */
      unsigned int
      n_preconditioner_solves() const
      {
        return solves;
      }

    private:
      /**
       * One cycle of flexible GMRES from x. Returns whether the control
       * was satisfied.
       */
      template <class Preconditioner>
      bool
      run_cycle(const SparseMatrix<double> &A,
                Vector<double>             &x,
                const Vector<double>       &b,
                const Preconditioner       &preconditioner,
                SolverControl              &control,
                const unsigned int          basis_size)
      {
        // Vectors are sized when an iteration first needs them (empty
        // vectors hold no memory): a large system that converges in a few
        // iterations does not hold a hundred of its vectors.
        const unsigned int n_tmp = std::max(basis_size, 3u);
        if (basis.size() < n_tmp - 1)
          basis.resize(n_tmp - 1);
        if (directions.size() < n_tmp - 2)
          directions.resize(n_tmp - 2);
        const auto sized = [&](Vector<double> &vector) -> Vector<double> & {
          if (vector.size() != x.size())
            vector.reinit(x.size());
          return vector;
        };
        H.resize(n_tmp * (n_tmp - 1));
        gamma.assign(n_tmp, 0.);
        ci.resize(n_tmp - 1);
        si.resize(n_tmp - 1);
        h.assign(n_tmp - 1, 0.);
        const auto H_at = [&](const unsigned int i,
                              const unsigned int j) -> double & {
          return H[i * (n_tmp - 1) + j];
        };

        Vector<double> &v = sized(basis[0]);
        A.vmult(v, x);
        v.sadd(-1., 1., b);
        double       rho   = v.l2_norm();
        auto         state = control.check(solves, rho);
        unsigned int dim   = 0;
        if (state == SolverControl::iterate)
          {
            gamma[0] = rho;
            v *= 1. / rho;
            bool re_orthogonalize = false;
            for (; dim < n_tmp - 2 && state == SolverControl::iterate;)
              {
                Vector<double> &z = sized(directions[dim]);
                preconditioner.vmult(z, basis[dim]);
                ++solves;
                Vector<double> &vv = sized(basis[dim + 1]);
                A.vmult(vv, z);
                dim            = dim + 1;
                const double s = orthogonalize(dim, vv, re_orthogonalize);
                h[dim]         = s;
                if (s != 0)
                  vv *= 1. / s;
                givens_rotation(dim - 1);
                for (unsigned int i = 0; i < dim; ++i)
                  H_at(i, dim - 1) = h[i];
                rho   = std::fabs(gamma[dim]);
                state = control.check(solves, rho);
              }
          }
        if (state != SolverControl::success)
          return false;
        // Back substitution with the rotated Hessenberg matrix, and the
        // update x += Z y.
        y.resize(dim);
        for (int i = dim - 1; i >= 0; --i)
          {
            double sum = gamma[i];
            for (unsigned int j = i + 1; j < dim; ++j)
              sum -= y[j] * H_at(i, j);
            y[i] = sum / H_at(i, i);
          }
        for (unsigned int i = 0; i < dim; ++i)
          x.add(y[i], directions[i]);
        return true;
      }

      /** Modified Gram-Schmidt of @p vv against the first @p dim basis
       * vectors into h, with a second pass once orthogonality is lost
       * (checked every fifth iteration); returns the norm left. */
      double
      orthogonalize(const unsigned int dim,
                    Vector<double>    &vv,
                    bool              &re_orthogonalize)
      {
        const unsigned int inner         = dim - 1;
        double             norm_vv_start = 0;
        const bool         consider      = !re_orthogonalize && inner % 5 == 4;
        if (consider)
          norm_vv_start = vv.l2_norm();
        h[0] = vv * basis[0];
        for (unsigned int i = 1; i < dim; ++i)
          h[i] = vv.add_and_dot(-h[i - 1], basis[i - 1], basis[i]);
        double norm_vv =
          std::sqrt(vv.add_and_dot(-h[dim - 1], basis[dim - 1], vv));
        if (consider)
          {
            if (norm_vv > 10. * norm_vv_start *
                            std::sqrt(std::numeric_limits<double>::epsilon()))
              return norm_vv;
            re_orthogonalize = true;
          }
        if (re_orthogonalize)
          {
            double step = vv * basis[0];
            h[0] += step;
            for (unsigned int i = 1; i < dim; ++i)
              {
                step = vv.add_and_dot(-step, basis[i - 1], basis[i]);
                h[i] += step;
              }
            norm_vv = std::sqrt(vv.add_and_dot(-step, basis[dim - 1], vv));
          }
        return norm_vv;
      }

      /** Apply the earlier rotations to column @p col of the Hessenberg
       * matrix (in h), and a new one that zeroes its subdiagonal entry. */
      void
      givens_rotation(const unsigned int col)
      {
        for (unsigned int i = 0; i < col; ++i)
          {
            const double s = si[i], c = ci[i], old = h[i];
            h[i]     = c * old + s * h[i + 1];
            h[i + 1] = -s * old + c * h[i + 1];
          }
        const double r =
          1. / std::sqrt(h[col] * h[col] + h[col + 1] * h[col + 1]);
        si[col]        = h[col + 1] * r;
        ci[col]        = h[col] * r;
        h[col]         = ci[col] * h[col] + si[col] * h[col + 1];
        gamma[col + 1] = -si[col] * gamma[col];
        gamma[col] *= ci[col];
      }

      /// The Arnoldi basis, and the search directions Z (A Z = V H).
      std::vector<Vector<double>> basis, directions;
      unsigned int                solves = 0;
      /// The rotated Hessenberg matrix by rows, its present column, the
      /// rotated right-hand side, the rotations and the coefficients.
      std::vector<double> H, h, gamma, ci, si, y;
    };
  } // namespace internal
} // namespace ndda

#endif
