// SPDX-License-Identifier: GPL-3.0-or-later
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>

#include <ndda/parallel/distributed_solver.h>
#include <ndda/physics/cg_amg.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <Amesos_Mumps.h>
#include <Epetra_Import.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_LocalMap.h>
#include <Epetra_Vector.h>
#include <Teuchos_ParameterList.hpp>
#include <cstdint>

namespace ndda
{
  namespace
  {
    /**
     * A fingerprint of a sparsity pattern (size, and FNV-1a over the row
     * starts and column numbers), to know whether the split of the rows
     * of the last factorization still fits.
     */
    std::uint64_t
    fingerprint(const SparsityPattern &pattern)
    {
      std::uint64_t hash = 1469598103934665603ull;
      const auto    mix  = [&hash](const std::uint64_t value) {
        hash = (hash ^ value) * 1099511628211ull;
      };
      mix(pattern.n_rows());
      mix(pattern.n_cols());
      for (unsigned int row = 0; row < pattern.n_rows(); ++row)
        {
          mix(pattern.row_length(row));
          for (auto entry = pattern.begin(row); entry != pattern.end(row);
               ++entry)
            mix(entry->column());
        }
      return hash;
    }



    /**
     * The flops of MUMPS's factorization (RINFOG(3), from its analysis)
     * over those of a solve with its factors (INFOG(20) entries, twice
     * for the symmetric factorization, which stores one triangle) and a
     * product with the matrix (@p n_nonzeros entries): the cost of a
     * factorization in GMRES iterations, as LinearSolver's serial
     * factorizations count it. MUMPS defines its global counts on the
     * first process; the ratio is sent to all.
     */
    double
    mumps_solve_ratio(Amesos_BaseSolver &solver,
                      const std::size_t  n_nonzeros,
                      const bool         symmetric,
                      const MPI_Comm     communicator)
    {
      double ratio = 0;
      if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
        if (auto *mumps = dynamic_cast<Amesos_Mumps *>(&solver))
          {
            const double flops = mumps->GetRINFOG()[2];
            const int    count = mumps->GetINFOG()[19];
            // A negative count is in millions.
            const double entries =
              count >= 0 ? count : -1e6 * static_cast<double>(count);
            const double multiply_adds =
              (symmetric ? 2. : 1.) * entries + n_nonzeros;
            ratio = multiply_adds > 0. ? flops / (2. * multiply_adds) : 0.;
          }
      return dealii::Utilities::MPI::broadcast(communicator, ratio, 0);
    }
  } // namespace



  struct DistributedSolver::Implementation
  {
    /// The split of the rows, and the pattern it and the distributed
    /// matrix's pattern were made for.
    IndexSet      owned;
    std::uint64_t pattern_fingerprint = 0;
    bool          split_made          = false;

    TrilinosWrappers::SparseMatrix matrix;
    /// The solution and right-hand side in this process's rows, and the
    /// import that gathers the whole solution on every process, made with
    /// the split (Epetra builds an import with a collective directory
    /// lookup: once per split, not once per solve).
    TrilinosWrappers::MPI::Vector  x, b;
    std::unique_ptr<Epetra_Map>    all;
    std::unique_ptr<Epetra_Import> gather;
    std::unique_ptr<Epetra_Vector> gathered;

    /// MUMPS through Amesos.
    std::unique_ptr<Epetra_LinearProblem> problem;
    std::unique_ptr<Amesos_BaseSolver>    mumps;
    /// Whether MUMPS was told the matrix is symmetric positive definite.
    bool mumps_symmetric = false;
    /// MUMPS's factorization flops over those of a solve and a product.
    double solve_ratio = 0;

    /// CG-AMG: the preconditioner, and the rigid-body modes of this
    /// process's rows, column after column (ML keeps a pointer to them).
    TrilinosWrappers::PreconditionAMG amg;
    std::vector<double>               null_space;
    Teuchos::ParameterList            ml_parameters;
  };



  std::string
  DistributedSolver::name(const Method method)
  {
    return method == Method::mumps ? "MUMPS" : "CG-AMG";
  }



  DistributedSolver::DistributedSolver(const MPI_Comm communicator,
                                       const Method   method,
                                       const double   tolerance)
    : communicator(communicator)
    , method(method)
    , tolerance(tolerance)
    , implementation(std::make_unique<Implementation>())
  {}



  DistributedSolver::~DistributedSolver() = default;



  void
  DistributedSolver::set_rigid_body_modes(
    const std::vector<Point<2>>     &location,
    const std::vector<unsigned int> &component)
  {
    rigid_body_modes = cg_amg::rigid_body_modes(location, component);
  }



  void
  DistributedSolver::set_row_owners(const std::vector<unsigned int> &owners)
  {
    const unsigned int n_parts =
      dealii::Utilities::MPI::n_mpi_processes(communicator);
    for (const auto p : owners)
      AssertThrow(p < n_parts,
                  ExcMessage("DistributedSolver: a row owned by process " +
                             std::to_string(p) + " of " +
                             std::to_string(n_parts) + "."));
    if (owners != row_owners)
      {
        row_owners                 = owners;
        implementation->split_made = false;
      }
  }



  const IndexSet &
  DistributedSolver::locally_owned_rows() const
  {
    return implementation->owned;
  }



  std::size_t
  DistributedSolver::size() const
  {
    return implementation->split_made ? implementation->owned.size() : 0;
  }



  double
  DistributedSolver::solves_per_factorization() const
  {
    return method == Method::mumps ? implementation->solve_ratio : 0.;
  }



  void
  DistributedSolver::forget_factorization()
  {
    implementation = std::make_unique<Implementation>();
  }



  void
  DistributedSolver::factorize(const SparseMatrix<double> &matrix,
                               const bool symmetric_positive_definite)
  {
    auto              &impl = *implementation;
    const unsigned int n_parts =
      dealii::Utilities::MPI::n_mpi_processes(communicator);
    const unsigned int this_part =
      dealii::Utilities::MPI::this_mpi_process(communicator);
    const SparsityPattern &pattern = matrix.get_sparsity_pattern();

    // A new pattern (or new owners): a new split of the rows (the owners
    // given, else METIS on the first process, the same for all), and the
    // distributed matrix's pattern from the rows of this process.
    // (deal.II 9.4's TrilinosWrappers::SparseMatrix::reinit() from a
    // SparseMatrix and two index sets loses entries on more than one process:
    // ../shared/DESIGN.md.)
    const std::uint64_t print = fingerprint(pattern);
    const bool          same_pattern =
      impl.split_made && print == impl.pattern_fingerprint;
    if (!same_pattern)
      {
        // MUMPS's instance refers to the distributed matrix (its
        // destructor reads it): it goes first.
        impl.mumps.reset();
        impl.problem.reset();
        std::vector<unsigned int> part(matrix.m(), 0);
        if (row_owners.size() == matrix.m())
          part = row_owners;
        else if (n_parts > 1)
          {
            if (this_part == 0)
              SparsityTools::partition(pattern,
                                       n_parts,
                                       part,
                                       SparsityTools::Partitioner::metis);
            dealii::Utilities::MPI::broadcast(part.data(),
                                              part.size(),
                                              0,
                                              communicator);
          }
        impl.owned = IndexSet(matrix.m());
        for (unsigned int i = 0; i < matrix.m(); ++i)
          if (part[i] == this_part)
            impl.owned.add_index(i);
        impl.owned.compress();

        TrilinosWrappers::SparsityPattern    distributed_pattern(impl.owned,
                                                              impl.owned,
                                                              communicator);
        std::vector<types::global_dof_index> columns;
        for (const auto row : impl.owned)
          {
            columns.clear();
            for (auto entry = pattern.begin(row); entry != pattern.end(row);
                 ++entry)
              columns.push_back(entry->column());
            distributed_pattern.add_entries(row,
                                            columns.begin(),
                                            columns.end());
          }
        distributed_pattern.compress();
        impl.matrix.reinit(distributed_pattern);
        impl.x.reinit(impl.owned, communicator);
        impl.b.reinit(impl.owned, communicator);
        const Epetra_BlockMap &owned_map = impl.x.trilinos_vector().Map();
        impl.all =
          std::make_unique<Epetra_LocalMap>(static_cast<int>(matrix.m()),
                                            0,
                                            owned_map.Comm());
        impl.gather   = std::make_unique<Epetra_Import>(*impl.all, owned_map);
        impl.gathered = std::make_unique<Epetra_Vector>(*impl.all);
        impl.pattern_fingerprint = print;
        impl.split_made          = true;
      }

    // This process's rows, every entry of the pattern kept.
    {
      std::vector<types::global_dof_index> columns;
      std::vector<double>                  values;
      for (const auto row : impl.owned)
        {
          columns.clear();
          values.clear();
          for (auto entry = matrix.begin(row); entry != matrix.end(row);
               ++entry)
            {
              columns.push_back(entry->column());
              values.push_back(entry->value());
            }
          impl.matrix.set(row, columns, values, false);
        }
      impl.matrix.compress(VectorOperation::insert);
    }

    if (method == Method::mumps)
      {
        // The same pattern and properties: MUMPS's analysis is kept.
        if (impl.mumps != nullptr && same_pattern &&
            impl.mumps_symmetric == symmetric_positive_definite)
          {
            impl.problem->SetOperator(
              const_cast<Epetra_CrsMatrix *>(&impl.matrix.trilinos_matrix()));
            AssertThrow(impl.mumps->NumericFactorization() == 0,
                        ExcMessage("MUMPS could not factorize the system "
                                   "matrix; it is probably singular."));
            return;
          }
        impl.mumps_symmetric = symmetric_positive_definite;
        impl.mumps.reset();
        impl.problem = std::make_unique<Epetra_LinearProblem>();
        impl.problem->SetOperator(
          const_cast<Epetra_CrsMatrix *>(&impl.matrix.trilinos_matrix()));
        Amesos factory;
        impl.mumps.reset(factory.Create("Amesos_Mumps", *impl.problem));
        AssertThrow(impl.mumps != nullptr,
                    ExcMessage("This build of Trilinos has no MUMPS "
                               "(Amesos_Mumps)."));
        Teuchos::ParameterList parameters;
        parameters.set("MatrixProperty",
                       symmetric_positive_definite ? "SPD" : "general");
        impl.mumps->SetParameters(parameters);
        AssertThrow(impl.mumps->SymbolicFactorization() == 0 &&
                      impl.mumps->NumericFactorization() == 0,
                    ExcMessage("MUMPS could not factorize the system matrix; "
                               "it is probably singular."));
        impl.solve_ratio = mumps_solve_ratio(*impl.mumps,
                                             matrix.n_nonzero_elements(),
                                             symmetric_positive_definite,
                                             communicator);
        return;
      }

    // The modes at this process's rows, in the order of its rows.
    impl.null_space.clear();
    if (!rigid_body_modes.empty())
      {
        const std::size_t n       = matrix.m();
        const std::size_t n_local = impl.owned.n_elements();
        AssertThrow(rigid_body_modes.size() == 3 * n,
                    ExcMessage("The rigid-body modes are not those of this "
                               "matrix's dofs."));
        impl.null_space.assign(3 * n_local, 0.);
        std::size_t k = 0;
        for (const auto row : impl.owned)
          {
            for (unsigned int mode = 0; mode < 3; ++mode)
              impl.null_space[mode * n_local + k] =
                rigid_body_modes[mode * n + row];
            ++k;
          }
      }
    cg_amg::initialize(impl.amg,
                       impl.matrix,
                       impl.null_space,
                       impl.ml_parameters);
  }



  unsigned int
  DistributedSolver::solve(Vector<double> &x, const Vector<double> &b)
  {
    auto &impl = *implementation;
    AssertThrow(impl.split_made && b.size() == impl.owned.size(),
                ExcMessage("DistributedSolver::solve() before factorize(), "
                           "or with a vector of another size."));
    TrilinosWrappers::MPI::Vector &tx = impl.x, &tb = impl.b;
    tx = 0.;
    {
      double *local = tb.begin();
      for (const auto row : impl.owned)
        *local++ = b[row];
    }

    unsigned int iterations = 1;
    if (method == Method::mumps)
      {
        impl.problem->SetLHS(&tx.trilinos_vector());
        impl.problem->SetRHS(&tb.trilinos_vector());
        AssertThrow(impl.mumps->Solve() == 0,
                    ExcMessage("MUMPS could not solve with its factors."));
      }
    else
      {
        iterations = cg_amg::solve(impl.matrix,
                                   impl.amg,
                                   tx,
                                   tb,
                                   tolerance * b.l2_norm(),
                                   "Control/Linear solver: ",
                                   " Use direct or MUMPS for this scene.");
      }
    // Every process gets the whole solution.
    AssertThrow(impl.gathered->Import(tx.trilinos_vector(),
                                      *impl.gather,
                                      Insert) == 0,
                ExcMessage("DistributedSolver: the solution could not be "
                           "gathered."));
    x.reinit(b.size(), true);
    std::copy(impl.gathered->Values(),
              impl.gathered->Values() + b.size(),
              x.begin());
    return iterations;
  }
} // namespace ndda
