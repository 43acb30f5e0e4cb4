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
     * @p max_steps iterations, and after @p sure_steps iterations also as
     * soon as the reduction of the residual so far, extrapolated at its
     * mean rate, would not reach the tolerance within @p max_steps: such
     * a solve costs more than the factorization it was to save.
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
            const unsigned int sure_steps,
            const double       tolerance,
            const double       initial)
      {
        set_max_steps(max_steps);
        set_tolerance(tolerance * initial);
        this->sure_steps = sure_steps;
        this->initial    = initial;
        log_target       = std::log(tolerance);
      }

      State
      check(const unsigned int step, const double value) override
      {
        const State state = SolverControl::check(step, value);
        if (state != iterate || step < sure_steps)
          return state;
        const double log_reduction = std::log(value / initial);
        if (!(log_reduction < 0.) ||
            step * log_target / log_reduction > max_steps())
          {
            lcheck = failure;
            return failure;
          }
        return state;
      }

    private:
      unsigned int sure_steps = 0;
      double       initial = 1, log_target = 0;
    };



    /**
     * GMRES with right preconditioning and the true residual's estimate
     * as criterion, one cycle of at most @p basis_size - 2 iterations:
     * the operations of deal.II's SolverGMRES (9.4) in that case, in the
     * same order and with the same vector operations, so that it gives
     * the same iterate to the last bit (the tests' figures did not move).
     * Unlike SolverGMRES it keeps its basis, Hessenberg matrix and Givens
     * rotations from solve to solve: SolverGMRES allocates them at every
     * call, which cost a single block's step more than its iterations
     * (about 20,000 instructions a solve of three unknowns).
     */
    class ReuseGMRES
    {
    public:
      /**
       * Solve A x = b from the x given, preconditioned by @p preconditioner;
       * @p control decides. Returns whether it converged (if not, x is
       * left as it was).
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
        // The basis vectors are sized when an iteration first needs them
        // (empty vectors hold no memory): a large system that converges in
        // a few iterations does not hold a hundred of its vectors.
        const unsigned int n_tmp = std::max(basis_size, 3u);
        if (basis.size() < n_tmp - 1)
          basis.resize(n_tmp - 1);
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
        sized(p);
        A.vmult(v, x);
        v.sadd(-1., 1., b);
        double       rho   = v.l2_norm();
        auto         state = control.check(0, rho);
        unsigned int dim   = 0;
        if (state == SolverControl::iterate)
          {
            gamma[0] = rho;
            v *= 1. / rho;
            bool re_orthogonalize = false;
            for (unsigned int inner = 0;
                 inner < n_tmp - 2 && state == SolverControl::iterate;
                 ++inner)
              {
                Vector<double> &vv = sized(basis[inner + 1]);
                preconditioner.vmult(p, basis[inner]);
                A.vmult(vv, p);
                dim            = inner + 1;
                const double s = orthogonalize(dim, vv, re_orthogonalize);
                h[inner + 1]   = s;
                if (s != 0)
                  vv *= 1. / s;
                givens_rotation(inner);
                for (unsigned int i = 0; i < dim; ++i)
                  H_at(i, inner) = h[i];
                rho   = std::fabs(gamma[dim]);
                state = control.check(dim, rho);
              }
          }
        if (state != SolverControl::success)
          return false;
        if (dim == 0)
          return true;
        // Back substitution with the rotated Hessenberg matrix, and the
        // update x += P^-1 V y.
        y.resize(dim);
        for (int i = dim - 1; i >= 0; --i)
          {
            double sum = gamma[i];
            for (unsigned int j = i + 1; j < dim; ++j)
              sum -= y[j] * H_at(i, j);
            y[i] = sum / H_at(i, i);
          }
        p = 0.;
        for (unsigned int i = 0; i < dim; ++i)
          p.add(y[i], basis[i]);
        preconditioner.vmult(v, p);
        x.add(1., v);
        return true;
      }

    private:
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

      /// The Krylov basis, and the work vector p = P^-1 v.
      std::vector<Vector<double>> basis;
      Vector<double>              p;
      /// The rotated Hessenberg matrix by rows, its present column, the
      /// rotated right-hand side, the rotations and the coefficients.
      std::vector<double> H, h, gamma, ci, si, y;
    };
  } // namespace internal
} // namespace ndda

#endif
