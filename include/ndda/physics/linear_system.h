// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_linear_system_h
#define ndda_physics_linear_system_h


#include <deal.II/base/array_view.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <ndda/base/section_timer.h>
#include <ndda/physics/bolts.h>
#include <ndda/physics/constraints.h>
#include <ndda/physics/dof_map.h>
#include <ndda/physics/element_cache.h>
#include <ndda/physics/linear_solver.h>

#include <array>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace ndda
{
  class BlockFrames;

  /**
   * The global matrices of a scene and the linear solves of its time steps
   * (thesis 3.11): the stiffness K, mass M and damping C assembled from the
   * element cache and the bolts; the step's system matrix
   * A = K + c_M M + c_C C (+ the penalty springs of the constraints); the
   * sparsity pattern, which also holds the couplings of the contacts; the
   * linear solver and the reuse of its factorization.
   *
   * A factorization of A without contact springs is kept for as long as
   * the geometry and the step size stay (DESIGN.md decision 4). A system
   * whose contact springs changed is first solved by GMRES preconditioned
   * with the last factorization (see LinearSolver); when that converges
   * slowly, the next changed system is factorized.
   *
   * @ingroup physics
   */
  class LinearSystem
  {
  public:
    /** Adds a dense block of springs on the dofs of its second argument
     * to the system (in the blocks' frames, see solve()). The first
     * argument is a number that the caller gives the same block in every
     * solve (a contact's index): under it the system keeps the block and
     * how it is added to the compact system (made anew only when the
     * block's dofs differ from those it was made for). A null block adds
     * the block last added under the number again, if it was on the same
     * dofs; the return value says whether a block was added (false: no
     * block on these dofs was kept, give it). */
    using BlockAdder =
      std::function<bool(const unsigned int,
                         const ArrayView<const types::global_dof_index> &,
                         const FullMatrix<double> *)>;

    /** Adds springs (the contacts') as dense blocks through a BlockAdder
     * and their forces to a right-hand side (global components). */
    using SpringAssembler =
      std::function<void(const BlockAdder &, Vector<double> &)>;

    /**
     * A new linear solver of type @p type; with @p timer, the assembly and
     * the solves are timed in it. The processes of @p communicator solve
     * together (LinearSolver).
     */
    void
    initialize(const parameters::LinearSolverType type,
               const double                       tolerance,
               SectionTimer                      *timer        = nullptr,
               const MPI_Comm                     communicator = MPI_COMM_SELF);

    LinearSolver &
    get_linear_solver()
    {
      return *linear_solver;
    }

    /**
     * Make the sparsity pattern from the couplings of the elements and
     * bolts, @p element_couplings, condensed (in place) with the
     * constraints; every matrix is set to zero on it. With
     * @p with_contacts the element couplings are kept, to add the
     * contacts' to them later.
     * With @p compact (a direct solver only), the solver gets the system
     * of the unconstrained dofs alone, without the rows of the
     * constrained ones: for scenes whose rigid and affine blocks
     * constrain most dofs (ReducedBlocks).
     */
    void
    reinit(DynamicSparsityPattern &element_couplings,
           const Constraints      &constraints,
           const bool              with_contacts,
           const bool              compact = false);

    /**
     * Make sure the pattern holds every (vertex, cell) contact coupling
     * of @p couplings (sorted): it holds them and those of earlier steps,
     * and is rebuilt only when one is missing, so that candidates that
     * come and go near the detection distance keep the symbolic analysis
     * (UMFPACK) or pivot order (KLU) of the solver. When it holds more
     * than twice the couplings in use, it is rebuilt with these only.
     * A compact system rebuilds only the compact pattern, from the
     * element part kept at reinit() and the couplings expanded in compact
     * unknowns, and refills its matrix without springs: its entries are
     * those the whole pattern condensed would give, and the matrices on
     * all dofs, which no contact spring enters, keep theirs. New
     * couplings that expand to entries it has (two reduced blocks already
     * coupled) leave it as it is.
     * Returns whether the matrices are zero, so that assemble() must be
     * called (a rebuilt pattern that is not compact).
     */
    bool
    update_contact_couplings(
      const std::vector<std::pair<unsigned int, unsigned int>> &couplings,
      const DofMap                                             &dof_map,
      const Constraints                                        &constraints);

    /**
     * Assemble K, M and C from the element matrices of every cell and the
     * bolt springs on the present @p displacement.
     *
     * @param changed_cells If given, the matrices hold a full assembly
     * except for these cells, whose element matrices have changed since
     * (ElementCache::get_computed_cells()): only the rows of their dofs
     * are summed again, to the same values, bit for bit, as a full
     * assembly gives. A full assembly is done anyway after reinit(), with
     * bolts, or when half the cells or more changed.
     */
    void
    assemble(const ElementCache<2>           &element_cache,
             const DofMap                    &dof_map,
             const BoltSprings               &bolts,
             const Vector<double>            &displacement,
             const std::vector<unsigned int> *changed_cells = nullptr);

    /**
     * Make the system matrix of a step of size @p dt, A = K + c_M M + c_C C
     * (+ the penalty springs of the constraints of stiffness
     * @p penalty_stiffness), unless it is that of the same size and the
     * matrices did not change since.
     */
    void
    prepare_step(const double       dt,
                 const double       mass_coefficient,
                 const double       damping_coefficient,
                 const Constraints &constraints,
                 const double       penalty_stiffness);

    /**
     * Solve (A + S) d = b + s under @p constraints, where @p add_springs
     * (if not empty) adds the springs S, s; @p prescribed holds the
     * prescribed increments of constrained dofs (exact constraints).
     * A changed system is first solved by GMRES with the last
     * factorization, with up to @p reuse_iterations iterations or as many
     * as a factorization costs where that is more
     * (LinearSolver::reuse_limit(); 0: never). @p b is used as scratch:
     * on return it holds no particular value.
     * Returns the iterations of the solve: GMRES's with the earlier
     * factorization, else the linear solver's (1 for a direct solver).
     *
     * With turned frames (set_frames()), the assembled matrices are those
     * of the blocks' frames (ElementCache), @p add_springs adds the
     * springs in them (Q^T S Q; ContactHandler::set_frames()) and their
     * forces s in global components, and the system is solved there:
     * (A + Q^T S Q) (Q^T d) = Q^T (b + s), d returned in global
     * components.
     */
    unsigned int
    solve(const SpringAssembler &add_springs,
          Vector<double>        &b,
          const Vector<double>  &prescribed,
          const Constraints     &constraints,
          const unsigned int     reuse_iterations,
          Vector<double>        &d);

    /**
     * The blocks' frames in which the assembled matrices are (referenced;
     * nullptr: the global frame).
     */
    void
    set_frames(const BlockFrames *frames)
    {
      this->frames = frames;
    }

    /**
     * Solve M a = @p rhs with a = 0 at the constrained dofs (the initial
     * acceleration of Newmark).
     */
    void
    solve_mass(Vector<double>     rhs,
               const Constraints &constraints,
               Vector<double>    &acceleration) const;

    /** Forget the step size and factorization (the dofs changed). */
    void
    invalidate();

    /**
     * invalidate(), and forget everything the factorization carries from
     * solve to solve (its reuse as a preconditioner, its symbolic
     * analysis): the next solve is the one a process that resumes from a
     * checkpoint makes.
     */
    void
    drop_factorization();

    /**
     * The mass matrix M, stored without the entries that are zero (those
     * that couple a node's x and y dofs, and the contact couplings of the
     * system's pattern): half the entries of the system's pattern for a
     * vector element, so that a product with it reads half the memory.
     * Each row keeps its nonzero entries in their order (the diagonal
     * first), so that a product sums the same terms in the same order as
     * on the full pattern, to the last bit. Kept up to date by assemble().
     */
    const SparseMatrix<double> &
    get_mass_matrix() const
    {
      return mass_operator;
    }

    /** The stiffness matrix K (with the bolt springs). */
    const SparseMatrix<double> &
    get_stiffness_matrix() const
    {
      return stiffness_matrix;
    }

    /** The row sums of the mass matrix: nodal masses (kg). */
    Vector<double>
    lumped_mass() const;

    /**
     * An inertia force M a turned into a nodal acceleration over the
     * lumped mass (zero where a row has no mass), and back: the way an
     * acceleration is carried across a node split, where a force vector
     * must not be copied to both sides of a split node.
     */
    Vector<double>
    lumped_acceleration(const Vector<double> &inertia_force) const;

    /** The inverse of lumped_acceleration(): lumped mass times @p a. */
    Vector<double>
    lumped_inertia_force(const Vector<double> &a) const;

    /** The viscous damping matrix C (kg/s), valid if has_damping(). */
    const SparseMatrix<double> &
    get_damping_matrix() const
    {
      return damping_matrix;
    }

    /** Whether any material has viscous damping. */
    bool
    has_damping() const
    {
      return damped;
    }

    /** Whether the solver gets the compact system (reinit()). */
    bool
    is_compact() const
    {
      return compact;
    }

    /** The compact system's pattern, on the unconstrained dofs
     * (get_free_dofs(), in that order); valid if is_compact(). */
    const SparsityPattern &
    get_compact_pattern() const
    {
      return compact_pattern;
    }

    /** The unconstrained dofs, in the order of the compact system. */
    const std::vector<types::global_dof_index> &
    get_free_dofs() const
    {
      return free_dofs;
    }

    /** The (vertex, cell) contact couplings the pattern holds (sorted). */
    const std::vector<std::pair<unsigned int, unsigned int>> &
    get_contact_couplings() const
    {
      return pattern_couplings;
    }

    /** How many times the compact pattern has been built anew for new
     * contact couplings (update_contact_couplings()), in all. */
    unsigned int
    n_compact_pattern_builds() const
    {
      return compact_pattern_version;
    }

    unsigned int
    n_factorizations() const
    {
      return linear_solver->n_factorizations();
    }

    /**
     * The work (J) that the prescribed increments g of the exact
     * constraints did in the last solve(): g . (A d - b) over the dofs
     * where g is not zero, A d - b being the reactions there (the
     * integrator's balance of the step, contact springs included). Zero
     * when nothing moves a constraint (fixed supports) and with the
     * penalty method.
     */
    double
    last_constraint_work() const
    {
      return constraint_work;
    }

  private:
    /**
     * Add the rows of a cell's element matrices @p data on its @p dofs to
     * K, M and C; only the rows of dofs marked in @p rows, if given.
     */
    void
    add_cell_rows(const ElementCache<2>::CellData            &data,
                  const std::vector<types::global_dof_index> &dofs,
                  const std::vector<bool>                    *rows);

    /**
     * Copy the nonzero entries of mass_matrix into mass_operator
     * (get_mass_matrix()): into its pattern if every nonzero entry has its
     * place there (the others are set to zero), else into a new pattern
     * of the nonzero entries.
     */
    void
    prune_mass_matrix();

    /** Condense @p dsp, make it the sparsity pattern, and reinit every
     * matrix on it (their entries are zero then); a compact system keeps
     * its compact pattern as the element part (compact_element_pattern). */
    void
    reinit_matrices(DynamicSparsityPattern &dsp,
                    const Constraints      &constraints);

    /** Set @p matrix (on the sparsity pattern) to K + c_M M + c_C C, and
     * the penalty springs of inexact @p constraints of stiffness
     * @p penalty_stiffness. */
    void
    build_system_matrix(SparseMatrix<double> &matrix,
                        const double          mass_coefficient,
                        const double          damping_coefficient,
                        const Constraints    &constraints,
                        const double          penalty_stiffness) const;

    SectionTimer *timer = nullptr;

    /// Couplings of elements and bolts, before contacts and condensation
    /// (with contacts, unless compact).
    SparsityPattern element_sparsity;
    /// The compact pattern of the elements and bolts, without contacts
    /// (compact, with contacts).
    SparsityPattern compact_element_pattern;
    /// The (vertex, cell) contact couplings the sparsity pattern holds.
    std::vector<std::pair<unsigned int, unsigned int>> pattern_couplings;
    SparsityPattern                                    sparsity_pattern;
    SparseMatrix<double>                               stiffness_matrix;
    SparseMatrix<double>                               mass_matrix;
    /// The mass matrix without its zero entries (get_mass_matrix()).
    SparsityPattern      mass_pattern;
    SparseMatrix<double> mass_operator;
    SparseMatrix<double> damping_matrix;
    /// The system matrix K + c_M M + c_C C (with the penalty springs of
    /// inexact constraints), only once a solve has prescribed increments
    /// (A g in solve(), prescribed_work()): else it is built in
    /// condensed_base alone, one matrix with the whole pattern less.
    SparseMatrix<double> system_matrix;
    bool                 keep_system_matrix = false;
    /// The system matrix condensed with the constraints' lines, once per
    /// prepare_step() that changes it.
    SparseMatrix<double> condensed_base;
    /// The condensed system matrix with the contact springs of the solve
    /// (added through the lines, block by block), allocated by the first
    /// solve with springs.
    SparseMatrix<double> condensed_matrix;
    /// The last solve() added contact springs: the solver's matrix is the
    /// one with the springs, else the base (solver_matrix()).
    bool with_springs = false;
    /// One row of a cell's mass matrix (add_cell_rows()).
    std::vector<double> mass_row;
    /// The compact system: the unconstrained dofs (in order), the index
    /// of every dof among them (invalid: constrained), the condensed
    /// system matrix on them (once per prepare_step() that changes it),
    /// and that matrix with the contact springs of the solve, which the
    /// solver then gets.
    bool compact = false;
    /// reinit() was told the scene has contacts.
    bool                                 with_contacts = false;
    std::vector<types::global_dof_index> free_dofs;
    std::vector<types::global_dof_index> compact_index;
    SparsityPattern                      compact_pattern;
    SparseMatrix<double>                 compact_base;
    SparseMatrix<double>                 compact_matrix;
    /// Every dof in compact unknowns (CSR): a free dof is its own, a dof
    /// on a homogeneous line the line's masters with their weights, a
    /// dof of an exact constraint none (its value is prescribed).
    std::vector<unsigned int>            expansion_start;
    std::vector<types::global_dof_index> expansion_column;
    std::vector<double>                  expansion_weight;
    /// How a block of springs is added to the compact matrix
    /// (add_to_compact()), kept from solve to solve under the caller's
    /// number for the block: the dofs it was made for; T, their expansion
    /// in the block's m compact unknowns, in sparse rows (the expansion
    /// entries of each dof with their positions among the m); and the
    /// positions of the m x m entries in the compact matrix's values;
    /// and T^T k T of the block last added through it.
    struct CompactPlan
    {
      std::vector<types::global_dof_index> dofs;
      unsigned int                         m = 0;
      /// The m compact unknowns (sorted), and the compact pattern's
      /// version the entries were located in.
      std::vector<types::global_dof_index> columns;
      unsigned int                         pattern_version = 0;
      std::vector<unsigned int>            row_start, position;
      std::vector<double>                  weight;
      std::vector<std::size_t>             entries;
      std::vector<double>                  block;
      bool                                 has_block = false;
    };
    /// The spring block last added under each of the callers' numbers,
    /// with its dofs (see BlockAdder).
    struct KeptBlock
    {
      std::vector<types::global_dof_index> dofs;
      FullMatrix<double>                   k;
    };
    std::vector<KeptBlock> kept_blocks;
    /// The keys of the kept blocks on dofs that g moves, in this solve.
    std::vector<unsigned int> g_blocks;
    /// last_constraint_work(), and what it needs of the right-hand side:
    /// the rows that g moves, with their entries of b before the lifting.
    double                                                  constraint_work = 0;
    std::vector<std::pair<types::global_dof_index, double>> g_rows;
    /// The plans by the callers' numbers; cleared when the expansion
    /// changes (reinit), kept when only the contact couplings do.
    std::vector<CompactPlan> compact_plans;
    /// Buffers of add_to_compact().
    struct
    {
      std::vector<types::global_dof_index> columns;
      /// Per compact unknown, its position in columns while a plan is
      /// made, else invalid.
      std::vector<unsigned int> slot;
      std::vector<double>       kt;
    } scratch;

    /// Counts the compact patterns built (update_compact_couplings()).
    unsigned int compact_pattern_version = 0;

    /** Find the positions of @p plan's entries in the compact pattern. */
    void
    locate_compact_entries(CompactPlan &plan) const;

    /** Make @p plan for a block on @p dofs. */
    void
    make_compact_plan(const ArrayView<const types::global_dof_index> &dofs,
                      CompactPlan                                    &plan);

    /** The expansion of every dof in compact unknowns (reinit). */
    void
    setup_expansion(const AffineConstraints<double> &affine);

    /** Rebuild the compact pattern: the element part and the (vertex,
     * cell) contact @p couplings expanded in compact unknowns; reinit
     * the compact matrices on it, and refill compact_base unless
     * prepare_step() will. */
    void
    update_compact_couplings(
      const std::vector<std::pair<unsigned int, unsigned int>> &couplings,
      const DofMap                                             &dof_map);

    /** The compact unknowns that @p dofs expand to, sorted, in
     * @p columns. */
    void
    expand_in_compact(const ArrayView<const types::global_dof_index> &dofs,
                      std::vector<types::global_dof_index> &columns) const;

    /** Whether the compact pattern has every entry of the (vertex, cell)
     * @p couplings that the pattern's couplings do not have. */
    bool
    compact_pattern_holds(
      const std::vector<std::pair<unsigned int, unsigned int>> &couplings,
      const DofMap                                             &dof_map) const;

    /** Copy the condensed base matrix's entries on the free dofs into
     * compact_base. */
    void
    fill_compact_base();

    /**
     * Add the dense spring block @p k on the dofs @p dofs to the compact
     * matrix through the expansion: T^T k T, T the expansion of the dofs
     * (the lines of the reduced blocks applied to the block before it is
     * added, not entry by entry), by the plan kept under @p key, which
     * keeps T^T k T too. A null @p k adds the kept T^T k T again; false if
     * the plan has none for these dofs (nothing is added then).
     */
    bool
    add_to_compact(const unsigned int                              key,
                   const ArrayView<const types::global_dof_index> &dofs,
                   const FullMatrix<double>                       *k);

    /** The work g . (A d - b) of last_constraint_work(), after a solve
     * with the prescribed increments @p g and the solution @p d (both in
     * the solve's frames), on the rows kept in g_rows: a product with
     * those rows of the matrix only. */
    double
    prescribed_work(const Vector<double> &g, const Vector<double> &d);

    /** Solve the changed condensed system for @p b into @p d: GMRES with
     * the last factorization, or a new factorization (of a system with
     * @p springs or without). Returns the iterations. */
    unsigned int
    solve_changed(const Vector<double> &b,
                  Vector<double>       &d,
                  const bool            springs,
                  const unsigned int    reuse_iterations);

    /** The solver's matrix: the condensed matrix, or the compact one,
     * with the springs of the last solve() if it had any, else the base
     * matrix. */
    const SparseMatrix<double> &
    solver_matrix();

    /** Solve the condensed system for @p b (condensed) into @p d, through
     * the compact system if there is one: returns the solver's
     * iterations (@p factorize: a new factorization first; else GMRES
     * with the last one, at most @p gmres_iterations, 0 if it does not
     * converge; 0 iterations: the plain solve). */
    unsigned int
                                  compact_solve(const Vector<double> &b,
                                                Vector<double>       &d,
                                                const bool            factorize,
                                                const unsigned int    gmres_iterations);
    const BlockFrames            *frames = nullptr;
    std::unique_ptr<LinearSolver> linear_solver;
    bool                          damped = false;
    /// K, M and C hold a full assembly (assemble()) on the present
    /// pattern; reinit_matrices() zeroes them.
    bool   assembled    = false;
    double assembled_dt = -1;
    /// The mass and damping coefficients of the assembled system matrix.
    std::array<double, 2> assembled_coefficients = {{-1., -1.}};
    bool                  matrices_changed       = true;
    /// The factorization is that of the system matrix without contacts.
    bool base_factorized = false;
    /// The last GMRES solve with an earlier factorization converged slowly:
    /// factorize the next changed system.
    bool refactorize_next = false;
    /// GMRES iterations taken with the present factorization since it was
    /// made, beyond the fewest that one solve with it took.
    double reuse_spent = 0;
    /// The fewest GMRES iterations of a solve with the present
    /// factorization.
    unsigned int reuse_fewest = numbers::invalid_unsigned_int;
    /// Counts the system matrices without springs that prepare_step() has
    /// built.
    unsigned int base_version = 0;
    /// base_version at the last solve without springs with an earlier
    /// factorization (invalid if none since the factorization).
    unsigned int reused_base_version = numbers::invalid_unsigned_int;
    /// Scratch of solve() and compact_solve(), kept from step to step so
    /// that a step allocates nothing: the prescribed increments in the
    /// frames, A g, and the compact right-hand side and solution.
    Vector<double> prescribed_in_frame, ag, compact_b, compact_d;
  };
} // namespace ndda

#endif
