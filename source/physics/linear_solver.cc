// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/index_set.h>

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ndda/parallel/distributed_solver.h>
#include <ndda/parallel/serial_work.h>
#include <ndda/physics/cg_amg.h>
#include <ndda/physics/cg_jacobi.h>
#include <ndda/physics/cholesky.h>
#include <ndda/physics/linear_solver.h>
#include <ndda/physics/suitesparse_setup.h>

#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <suitesparse/klu.h>
#include <suitesparse/umfpack.h>

#include "reuse_gmres.h"

namespace ndda
{
  namespace
  {
    /**
     * The cost of a factorization in GMRES iterations with it, from
     * @p flop_ratio, the factorization's flops over those of one iteration
     * (a solve with the factors and a product with the matrix; 0: no
     * factorization). The flops alone misjudge it both ways
     * (doc/performance.md, "The cost of a factorization in iterations"):
     * a triangular solve runs at the speed of memory, while a
     * factorization runs its flops @p flops_faster times as fast (UMFPACK's
     * and CHOLMOD's dense fronts with BLAS-3; KLU, without BLAS, twice),
     * and it has work beside its flops (copying the matrix, assembling the
     * fronts, allocating the factors), about fifteen iterations' worth.
     * The constants are fixed, not measured in the run, so that a scene
     * takes the same decisions, and gives the same results, on every
     * machine.
     */
    double
    iterations_per_factorization(const double flop_ratio,
                                 const double flops_faster)
    {
      constexpr double work_besides_flops = 15.;
      return flop_ratio > 0. ? work_besides_flops + flop_ratio / flops_faster :
                               0.;
    }



    /**
     * UMFPACK called directly rather than through SparseDirectUMFPACK, for
     * two reasons measured on ndda's systems: the symbolic analysis
     * (ordering) depends only on the sparsity pattern and is kept across
     * factorizations, and the symmetric strategy (AMD on A + A^T, diagonal
     * pivots preferred) fits the symmetric positive definite matrices of
     * elasticity with inertia.
     */
    /**
     * A matrix in compressed rows with sorted column indices, which
     * UMFPACK and KLU read as the compressed columns of its transpose.
     */
    struct CompressedRows
    {
      /** Copy @p matrix; returns whether its sparsity pattern changed. */
      bool
      update(const SparseMatrix<double> &matrix)
      {
        return copy_to_compressed_rows(matrix, false, ap, ai, ax);
      }

      SuiteSparse_long
      size() const
      {
        return ap.empty() ? 0 : ap.size() - 1;
      }

      std::vector<SuiteSparse_long> ap, ai;
      std::vector<double>           ax;
    };



    /**
     * A factorization as preconditioner: dst = (factorized matrix)^-1 src.
     * (The direct solvers' solve functions do not change the
     * factorization; their C interfaces just do not say const.)
     */
    template <class Solver>
    struct AsPreconditioner
    {
      void
      vmult(Vector<double> &dst, const Vector<double> &src) const
      {
        const_cast<Solver *>(static_cast<const Solver *>(this))
          ->solve(dst, src);
      }
    };



    class Umfpack : public AsPreconditioner<Umfpack>
    {
    public:
      ~Umfpack()
      {
        if (numeric != nullptr)
          umfpack_dl_free_numeric(&numeric);
        if (symbolic != nullptr)
          umfpack_dl_free_symbolic(&symbolic);
      }

      void
      factorize(const SparseMatrix<double> &matrix)
      {
        const SuiteSparse_long n           = matrix.m();
        const bool             new_pattern = rows.update(matrix);
        auto                  &ap          = rows.ap;
        auto                  &ai          = rows.ai;
        auto                  &ax          = rows.ax;
        if (numeric != nullptr)
          umfpack_dl_free_numeric(&numeric);
        numeric = nullptr;
        if (symbolic == nullptr || new_pattern)
          {
            if (symbolic != nullptr)
              umfpack_dl_free_symbolic(&symbolic);
            symbolic = nullptr;
            umfpack_dl_defaults(control);
            control[UMFPACK_STRATEGY] = UMFPACK_STRATEGY_SYMMETRIC;
            control[UMFPACK_IRSTEP]   = 0;
            check(umfpack_dl_symbolic(n,
                                      n,
                                      ap.data(),
                                      ai.data(),
                                      ax.data(),
                                      &symbolic,
                                      control,
                                      info),
                  "symbolic factorization");
          }
        check(
          umfpack_dl_numeric(
            ap.data(), ai.data(), ax.data(), symbolic, &numeric, control, info),
          "numeric factorization");
        solve_ratio =
          info[UMFPACK_FLOPS] /
          (2. * (info[UMFPACK_LNZ] + info[UMFPACK_UNZ] + ai.size()));
      }

      /** The flops of the last factorization over those of a solve and
       * a product with the matrix, which
       * LinearSolver::solves_per_factorization() turns into a cost. */
      double solve_ratio = 0;

      void
      solve(Vector<double> &x, const Vector<double> &b)
      {
        x.reinit(b.size());
        check(umfpack_dl_solve(UMFPACK_At,
                               rows.ap.data(),
                               rows.ai.data(),
                               rows.ax.data(),
                               x.begin(),
                               b.begin(),
                               numeric,
                               control,
                               info),
              "solve");
      }

      /** The size of the factorized matrix, 0 if there is none. */
      SuiteSparse_long
      size() const
      {
        return numeric == nullptr ? 0 : rows.size();
      }

    private:
      static void
      check(const SuiteSparse_long status, const std::string &what)
      {
        AssertThrow(status == UMFPACK_OK,
                    ExcMessage("UMFPACK " + what + " failed with status " +
                               std::to_string(status) +
                               (status == UMFPACK_WARNING_singular_matrix ?
                                  " (the matrix is singular)" :
                                  "") +
                               "."));
      }

      CompressedRows rows;
      void          *symbolic = nullptr;
      void          *numeric  = nullptr;
      double         control[UMFPACK_CONTROL];
      double         info[UMFPACK_INFO];
    };



    /**
     * SuiteSparse's KLU, called directly (Trilinos' Amesos wrapper copies
     * the matrix into Epetra structures at every factorization: 0.2 s of
     * the jointed grid scene had not finished after 12 minutes, against
     * 18 s with UMFPACK). KLU has little
     * overhead per factorization, which suits the small systems of block
     * assemblies, and a refactorization that keeps the pivot order when
     * only the values change (every open-close iteration with the same
     * candidate couplings). Its partial pivoting handles the
     * non-symmetric friction terms.
     */
    class Klu : public AsPreconditioner<Klu>
    {
    public:
      Klu()
      {
        klu_l_defaults(&common);
      }

      ~Klu()
      {
        free();
      }

      void
      factorize(const SparseMatrix<double> &matrix)
      {
        const bool new_pattern = rows.update(matrix);
        if (new_pattern || symbolic == nullptr)
          {
            free();
            symbolic = klu_l_analyze(rows.size(),
                                     rows.ap.data(),
                                     rows.ai.data(),
                                     &common);
            check(symbolic != nullptr, "analysis");
          }
        else if (numeric != nullptr)
          {
            // Same pattern: keep the pivot order unless it has become
            // poor (reciprocal pivot growth estimate).
            if (klu_l_refactor(rows.ap.data(),
                               rows.ai.data(),
                               rows.ax.data(),
                               symbolic,
                               numeric,
                               &common) &&
                klu_l_rcond(symbolic, numeric, &common) && common.rcond > 1e-12)
              return;
            klu_l_free_numeric(&numeric, &common);
          }
        numeric = klu_l_factor(
          rows.ap.data(), rows.ai.data(), rows.ax.data(), symbolic, &common);
        check(numeric != nullptr, "factorization");
        // The flops of the factorization depend on the pivot order alone,
        // which a refactorization keeps.
        check(klu_l_flops(symbolic, numeric, &common), "flop count");
        solve_ratio = common.flops / (2. * (numeric->lnz + numeric->unz +
                                            numeric->nzoff + rows.ai.size()));
      }

      /** The flops of the last factorization over those of a solve and
       * a product with the matrix, which
       * LinearSolver::solves_per_factorization() turns into a cost. */
      double solve_ratio = 0;

      void
      solve(Vector<double> &x, const Vector<double> &b)
      {
        x = b;
        // The rows of the matrix are the columns of the factorized one.
        check(
          klu_l_tsolve(symbolic, numeric, rows.size(), 1, x.begin(), &common),
          "solve");
      }

      SuiteSparse_long
      size() const
      {
        return numeric == nullptr ? 0 : rows.size();
      }

    private:
      void
      free()
      {
        if (numeric != nullptr)
          klu_l_free_numeric(&numeric, &common);
        if (symbolic != nullptr)
          klu_l_free_symbolic(&symbolic, &common);
      }

      void
      check(const bool ok, const std::string &what) const
      {
        AssertThrow(ok,
                    ExcMessage("KLU " + what + " failed with status " +
                               std::to_string(common.status) +
                               (common.status == KLU_SINGULAR ?
                                  " (the matrix is singular)" :
                                  "") +
                               "."));
      }

      CompressedRows  rows;
      klu_l_common    common;
      klu_l_symbolic *symbolic = nullptr;
      klu_l_numeric  *numeric  = nullptr;
    };



    /**
     * GMRES on @p matrix x = b from x = 0, preconditioned on the right by
     * @p preconditioner (a solve with an earlier factorization), to the
     * residual
     * @p tolerance |b| within @p max_iterations solves with the
     * preconditioner, while its rate promises to get there
     * (internal::ReuseControl). Returns those solves (at least 1), or 0
     * if it did not get there.
     */
    template <class Preconditioner>
    unsigned int
    gmres_with(internal::ReuseGMRES       &gmres,
               internal::ReuseControl     &control,
               const SparseMatrix<double> &matrix,
               Vector<double>             &x,
               const Vector<double>       &b,
               const Preconditioner       &preconditioner,
               const unsigned int          max_iterations,
               const double                tolerance)
    {
      x.reinit(b.size());
      const double norm = b.l2_norm();
      if (norm == 0.)
        return 1;
      // Right preconditioning: GMRES then watches the true residual.
      control.reset(max_iterations, tolerance, norm);
      if (!gmres.solve(
            matrix, x, b, preconditioner, control, max_iterations + 2))
        return 0;
      return std::max(1u, gmres.n_preconditioner_solves());
    }
  } // namespace



  struct LinearSolver::Implementation
  {
    CholeskyFactorization cholesky;
    /// Linear solver = direct: whether the last factorization is the
    /// Cholesky one (else UMFPACK's LU).
    bool                              cholesky_active = false;
    Umfpack                           umfpack;
    Klu                               klu;
    JacobiCG                          jacobi;
    TrilinosWrappers::SparseMatrix    trilinos_matrix;
    TrilinosWrappers::PreconditionAMG amg;
    IndexSet                          all;
    /// Rigid-body modes for ML, column after column (kept alive: ML keeps
    /// a pointer to them).
    std::vector<double>    null_space;
    Teuchos::ParameterList ml_parameters;
    /// GMRES with an earlier factorization: its control and its storage,
    /// kept from solve to solve.
    internal::ReuseControl reuse_control;
    internal::ReuseGMRES   gmres;
  };



  LinearSolver::LinearSolver(const parameters::LinearSolverType type,
                             const double                       tolerance,
                             const MPI_Comm                     communicator)
    : type(type)
    , tolerance(tolerance)
    , implementation(std::make_unique<Implementation>())
  {
    set_up_suitesparse();
    // The serial solvers stay serial on several processes: the first
    // process factorizes and solves, and sends the solution to the
    // others, so that a run repeats the run on one process to the bit.
    const unsigned int n_processes =
      Utilities::MPI::job_supports_mpi() ?
        Utilities::MPI::n_mpi_processes(communicator) :
        1;
    this->communicator = communicator;
    first_process_solves =
      n_processes > 1 && (type == parameters::LinearSolverType::direct ||
                          type == parameters::LinearSolverType::umfpack ||
                          type == parameters::LinearSolverType::klu ||
                          type == parameters::LinearSolverType::cg_jacobi);
    if (first_process_solves)
      serial_work = std::make_unique<SerialWork>(communicator);
    if (type == parameters::LinearSolverType::mumps)
      distributed =
        std::make_unique<DistributedSolver>(communicator,
                                            DistributedSolver::Method::mumps);
    else if (n_processes > 1 && type == parameters::LinearSolverType::cg_amg)
      distributed =
        std::make_unique<DistributedSolver>(communicator,
                                            DistributedSolver::Method::cg_amg,
                                            tolerance);
  }



  LinearSolver::~LinearSolver() = default;



  void
  LinearSolver::set_rigid_body_modes(const std::vector<Point<2>>     &location,
                                     const std::vector<unsigned int> &component)
  {
    rigid_body_modes = cg_amg::rigid_body_modes(location, component);
    if (distributed != nullptr)
      distributed->set_rigid_body_modes(location, component);
  }



  void
  LinearSolver::set_row_owners(const std::vector<unsigned int> &owners)
  {
    // CG-AMG works on the split itself (its products, ML's aggregates);
    // MUMPS moves the rows to its own mapping, and METIS's split of the
    // matrix's graph gave it the faster transfer (doc/performance.md,
    // "MPI, third stage: deal.II's shared triangulation").
    if (distributed != nullptr && type == parameters::LinearSolverType::cg_amg)
      distributed->set_row_owners(owners);
  }



  void
  LinearSolver::forget_factorization()
  {
    implementation = std::make_unique<Implementation>();
    if (distributed != nullptr)
      distributed->forget_factorization();
  }



  void
  LinearSolver::factorize_here(const SparseMatrix<double> &matrix)
  {
    auto &impl = *implementation;
    try
      {
        if (distributed != nullptr)
          {
            // MUMPS's symmetric factorization where the matrix is
            // symmetric; its LU where it is not, or where the symmetric one
            // fails.
            const bool symmetric = is_symmetric(matrix);
            try
              {
                distributed->factorize(matrix, symmetric);
              }
            catch (const ExceptionBase &)
              {
                if (!symmetric)
                  throw;
                distributed->factorize(matrix, false);
              }
            return;
          }
        if (type == parameters::LinearSolverType::direct)
          {
            impl.cholesky_active = impl.cholesky.factorize(matrix);
            if (!impl.cholesky_active)
              impl.umfpack.factorize(matrix);
            return;
          }
        if (type == parameters::LinearSolverType::umfpack)
          {
            impl.umfpack.factorize(matrix);
            return;
          }
        if (type == parameters::LinearSolverType::klu)
          {
            impl.klu.factorize(matrix);
            return;
          }
        if (type == parameters::LinearSolverType::cg_jacobi)
          {
            impl.jacobi.initialize(matrix);
            return;
          }
        impl.all = complete_index_set(matrix.m());
        impl.trilinos_matrix.reinit(matrix, 0., true, nullptr);
        impl.null_space = rigid_body_modes;
        cg_amg::initialize(impl.amg,
                           impl.trilinos_matrix,
                           impl.null_space,
                           impl.ml_parameters);
      }
    catch (const ExceptionBase &exc)
      {
        std::ostringstream message;
        exc.print_info(message);
        AssertThrow(false,
                    ExcMessage(
                      "The system matrix cannot be factorized; it is "
                      "probably singular because a block can move freely "
                      "in a quasi-static analysis. Constrain every block "
                      "or use Control/Analysis type = static or dynamic. "
                      "Solver message: " +
                      message.str()));
      }
  }



  double
  LinearSolver::solves_per_factorization_here() const
  {
    if (distributed != nullptr)
      return distributed->solves_per_factorization();
    // Fitted to ndda's systems of 3,000-60,000 unknowns
    // (doc/performance.md, "The cost of a factorization in iterations").
    const auto &impl = *implementation;
    if (type == parameters::LinearSolverType::direct && impl.cholesky_active)
      return iterations_per_factorization(
        impl.cholesky.solves_per_factorization(), 3.5);
    if (type == parameters::LinearSolverType::direct ||
        type == parameters::LinearSolverType::umfpack)
      return iterations_per_factorization(impl.umfpack.solve_ratio, 10.);
    if (type == parameters::LinearSolverType::klu)
      return iterations_per_factorization(impl.klu.solve_ratio, 2.);
    return 0;
  }



  unsigned int
  LinearSolver::reuse_limit(const unsigned int min_iterations) const
  {
    // As many iterations as the factorization costs, at most 100.
    return std::max(min_iterations,
                    static_cast<unsigned int>(
                      std::min(100., solves_per_factorization())));
  }



  unsigned int
  LinearSolver::reuse_here(const SparseMatrix<double> &matrix,
                           Vector<double>             &x,
                           const Vector<double>       &b,
                           const unsigned int          min_iterations,
                           const double                tolerance)
  {
    if (distributed != nullptr)
      return distributed_reuse(matrix, x, b, min_iterations, tolerance);
    auto      &impl = *implementation;
    const bool cholesky =
      type == parameters::LinearSolverType::direct && impl.cholesky_active;
    const bool umfpack =
      type == parameters::LinearSolverType::umfpack ||
      (type == parameters::LinearSolverType::direct && !impl.cholesky_active);
    const auto             n = static_cast<SuiteSparse_long>(matrix.m());
    const SuiteSparse_long factorized =
      cholesky ? static_cast<SuiteSparse_long>(impl.cholesky.size()) :
      umfpack  ? impl.umfpack.size() :
      type == parameters::LinearSolverType::klu ? impl.klu.size() :
                                                  -1;
    if (min_iterations == 0 || factorized != n)
      return 0;
    const auto run = [&](const auto &preconditioner) {
      return gmres_with(impl.gmres,
                        impl.reuse_control,
                        matrix,
                        x,
                        b,
                        preconditioner,
                        reuse_limit(min_iterations),
                        tolerance);
    };
    return cholesky ? run(impl.cholesky) :
           umfpack  ? run(impl.umfpack) :
                      run(impl.klu);
  }



  unsigned int
  LinearSolver::distributed_reuse(const SparseMatrix<double> &matrix,
                                  Vector<double>             &x,
                                  const Vector<double>       &b,
                                  const unsigned int          min_iterations,
                                  const double                tolerance)
  {
    // As with the serial factorizations: GMRES on the whole vectors,
    // which every process holds alike, preconditioned by the processes'
    // solve with the earlier factorization (collective: every process
    // takes the same iterations, since it computes the same numbers).
    struct Preconditioner
    {
      void
      vmult(Vector<double> &dst, const Vector<double> &src) const
      {
        solver->solve(dst, src);
      }
      DistributedSolver *solver;
    };
    if (min_iterations == 0 || distributed->size() != matrix.m() ||
        solves_per_factorization() == 0.)
      return 0;
    auto &impl = *implementation;
    return gmres_with(impl.gmres,
                      impl.reuse_control,
                      matrix,
                      x,
                      b,
                      Preconditioner{distributed.get()},
                      reuse_limit(min_iterations),
                      tolerance);
  }



  unsigned int
  LinearSolver::solve_here(Vector<double> &x, const Vector<double> &b)
  {
    if (distributed != nullptr)
      return distributed->solve(x, b);
    auto &impl = *implementation;
    if (type == parameters::LinearSolverType::direct)
      {
        if (impl.cholesky_active)
          impl.cholesky.solve(x, b);
        else
          impl.umfpack.solve(x, b);
        return 1;
      }
    if (type == parameters::LinearSolverType::umfpack)
      {
        impl.umfpack.solve(x, b);
        return 1;
      }
    if (type == parameters::LinearSolverType::klu)
      {
        impl.klu.solve(x, b);
        return 1;
      }
    if (type == parameters::LinearSolverType::cg_jacobi)
      return impl.jacobi.solve(x, b, tolerance);
    TrilinosWrappers::MPI::Vector tx(impl.all, MPI_COMM_SELF),
      tb(impl.all, MPI_COMM_SELF);
    for (unsigned int i = 0; i < b.size(); ++i)
      tb[i] = b[i];
    tb.compress(VectorOperation::insert);
    const unsigned int iterations =
      cg_amg::solve(impl.trilinos_matrix,
                    impl.amg,
                    tx,
                    tb,
                    tolerance * b.l2_norm(),
                    "Control/Linear solver: ",
                    " Use UMFPACK or KLU for this scene.");
    for (unsigned int i = 0; i < x.size(); ++i)
      x[i] = tx[i];
    return iterations;
  }
  void
  LinearSolver::factorize(const SparseMatrix<double> &matrix)
  {
    ++factorization_count;
    if (!first_process_solves)
      {
        factorize_here(matrix);
        return;
      }
    serial_work->run([&]() { factorize_here(matrix); });
    // The reuse decisions of every process follow the first one's
    // factorization.
    sent_solve_ratio =
      Utilities::MPI::broadcast(communicator,
                                Utilities::MPI::this_mpi_process(
                                  communicator) == 0 ?
                                  solves_per_factorization_here() :
                                  0.,
                                0);
  }



  double
  LinearSolver::solves_per_factorization() const
  {
    return first_process_solves ? sent_solve_ratio :
                                  solves_per_factorization_here();
  }



  unsigned int
  LinearSolver::solve_with_earlier_factorization(
    const SparseMatrix<double> &matrix,
    Vector<double>             &x,
    const Vector<double>       &b,
    const unsigned int          min_iterations,
    const double                tolerance)
  {
    if (!first_process_solves)
      return reuse_here(matrix, x, b, min_iterations, tolerance);
    unsigned int iterations = 0;
    serial_work->run([&]() {
      iterations = reuse_here(matrix, x, b, min_iterations, tolerance);
    });
    iterations = Utilities::MPI::broadcast(communicator, iterations, 0);
    if (iterations > 0)
      send_solution(x, b.size());
    return iterations;
  }



  unsigned int
  LinearSolver::solve(Vector<double> &x, const Vector<double> &b)
  {
    if (!first_process_solves)
      return solve_here(x, b);
    unsigned int iterations = 0;
    serial_work->run([&]() { iterations = solve_here(x, b); });
    send_solution(x, b.size());
    return Utilities::MPI::broadcast(communicator, iterations, 0);
  }



  void
  LinearSolver::send_solution(Vector<double> &x, const std::size_t n) const
  {
    if (x.size() != n)
      x.reinit(n, true);
    Utilities::MPI::broadcast(x.begin(), n, 0, communicator);
  }
} // namespace ndda
