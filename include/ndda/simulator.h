// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_simulator_h
#define ndda_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/table_handler.h>
#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <ndda/contact/contact_handler.h>
#include <ndda/mesh/crackable_mesh.h>
#include <ndda/parameters/parameters.h>
#include <ndda/physics/bolts.h>
#include <ndda/physics/constraints.h>
#include <ndda/physics/dof_map.h>
#include <ndda/physics/element_cache.h>
#include <ndda/physics/finite_element.h>
#include <ndda/physics/linear_solver.h>
#include <ndda/physics/loads.h>
#include <ndda/postprocess/visualization.h>
#include <ndda/time/step_controller.h>
#include <ndda/time/time_integrator.h>

#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace ndda
{
  using namespace dealii;

  /**
   * One value of a measure point at one time.
   */
  struct MeasureSample
  {
    double                time;
    Tensor<1, 2>          displacement;
    Tensor<1, 2>          velocity;
    SymmetricTensor<2, 2> stress;
  };

  /**
   * The ndda engine: reads a scene, builds the mesh and the finite element
   * space, and runs the time loop of thesis 3.11 and 5.4. Every step:
   *
   *   for each attempt of the step controller: detect contacts, solve
   *   (K + c_M M + c_C C + contact springs) d = f with the open-close
   *   iteration, accept or cut;
   *   crack check on the step's trial end state: if edges fail, split them
   *   and solve the step again on the cracked mesh;
   *   commit (velocities, stresses, vertex positions), postprocess.
   *
   * The formulas, and where they differ from the thesis, are in
   * doc/theory.md. Only dim = 2 is instantiated.
   *
   * @ingroup simulator
   */
  template <int dim>
  class Simulator
  {
    static_assert(dim == 2, "ndda is a two-dimensional code.");

  public:
    /**
     * Read the scene from a `.prm` file. Nothing is built yet.
     */
    explicit Simulator(const std::string &parameter_file);

    /**
     * A scene from parameters that were already read; if @p triangulation
     * is given, it replaces the Geometry section (one block per material
     * id, see CrackableMesh::build()).
     */
    Simulator(const parameters::Parameters &parameters,
              const Triangulation<dim>     *triangulation = nullptr);

    ~Simulator();

    /**
     * Build the mesh, the finite element space, constraints and loads, and
     * check everything that can be checked before the run (points inside
     * the scene, constraints on mesh vertices). Writes nothing.
     */
    void
    setup();

    /**
     * Run the time loop to the end time; calls setup() if that has not been
     * done. Creates the output directory only now.
     */
    void
    run();

    /**
     * Do one time step of nominal size (with cuts if needed). Used by
     * run() and by benchmarks.
     */
    void
    do_time_step();

    /** @name Access for tests, benchmarks and postprocessing */
    /** @{ */
    const parameters::Parameters &
    get_parameters() const
    {
      return parameters;
    }

    const CrackableMesh &
    get_mesh() const
    {
      return mesh;
    }

    const DoFHandler<dim> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    const Mapping<dim> &
    get_mapping() const
    {
      return mapping;
    }

    /** Subdivisions of a cell in the output (from the element). */
    unsigned int
    get_n_output_subdivisions() const
    {
      return n_output_subdivisions;
    }

    double
    get_time() const
    {
      return time;
    }

    unsigned int
    get_step_number() const
    {
      return step_number;
    }

    /** Total displacement since the start. */
    const Vector<double> &
    get_displacement() const
    {
      return displacement;
    }

    const Vector<double> &
    get_velocity() const
    {
      return kinematics.velocity;
    }

    /** Stress at every quadrature point of the active cell @p cell. */
    const std::vector<SymmetricTensor<2, dim>> &
    get_cell_stress(const unsigned int cell) const
    {
      return stress[cell];
    }

    /** Area-weighted mean stress of the active cell @p cell. */
    SymmetricTensor<2, dim>
    mean_cell_stress(const unsigned int cell) const;

    /** The global mass matrix (kg, includes the thickness). */
    const SparseMatrix<double> &
    get_mass_matrix() const
    {
      return mass_matrix;
    }

    /**
     * External force vector (gravity, point and line loads, bolt
     * pretension) at time @p t on the current geometry.
     */
    void
    assemble_external_force(const double t, Vector<double> &force) const;

    /** Histories of the measure points, one vector per point. */
    const std::vector<std::vector<MeasureSample>> &
    get_measure_histories() const
    {
      return measure_histories;
    }

    /** Kinetic energy 1/2 v^T M v (J). */
    double
    kinetic_energy() const;

    /** Elastic strain energy, accumulated per step (J). */
    double
    strain_energy() const
    {
      return stored_strain_energy;
    }

    /** Number of factorizations of the system matrix so far. */
    unsigned int
    n_factorizations() const
    {
      return linear_solver->n_factorizations();
    }

    /** Contacts of the scene: states, statistics of the last step. */
    const contact::ContactHandler &
    get_contacts() const
    {
      return contacts;
    }

    /** Work done by the external loads since the start (J). */
    double
    work_of_loads() const
    {
      return load_work;
    }

    /**
     * Mechanical energy gained since the start (J): kinetic + strain +
     * contact spring energy - work of the loads - initial kinetic energy.
     * Zero for an exact, energy-conserving run without friction; negative
     * where friction, impacts or the integrator take energy out; positive
     * only if something creates energy (a test for spurious gain).
     */
    double
    energy_error() const;

    /**
     * The earliest edge failure the fracture check has found so far: the
     * time (s), the edge's midpoint at the step's end, and the mode.
     * Without fracturing materials, or before any edge fails, mode is
     * none.
     */
    struct EdgeFailureRecord
    {
      fracture::FailureMode mode = fracture::FailureMode::none;
      double                time = 0;
      Point<dim>            location;
    };

    const EdgeFailureRecord &
    get_first_edge_failure() const
    {
      return first_edge_failure;
    }

    /**
     * Crack the given interior edges (pairs of vertex indices of
     * get_mesh().get_block_mesh()) now, between steps: node splitting
     * (CrackableMesh::crack), and the whole state carried over to the new
     * mesh: dof vectors through the cells (which keep their index),
     * stresses by cell, contact memory (old vertices keep their index),
     * bolt forces; everything that depends on the mesh is set up again.
     * The crack sequence of a step calls it; library users may call it to
     * add discontinuities to a running scene.
     */
    void
    crack_edges(const std::vector<std::array<unsigned int, 2>> &edges);

    /** Edges cracked (split) since the start of the run. */
    unsigned int
    get_n_cracked_edges() const
    {
      return n_cracked_edges;
    }

    /** What the last time step did, for the statistics. */
    struct StepReport
    {
      /// Its size (s), after cuts.
      double dt = 0;
      /// Its cuts, and of those the cuts of an unsettled open-close
      /// iteration.
      unsigned int cuts            = 0;
      unsigned int open_close_cuts = 0;
      /// GMRES iterations of its last solve (0: a fresh factorization).
      unsigned int solver_iterations = 0;
      /// Element matrix builds since the start.
      unsigned int matrix_builds = 0;
      /// Largest nodal displacement increment (m).
      double max_increment = 0;
      /// Whether the scene has fracturing materials.
      bool fracture = false;
      /// Crack events since the start; whether the step ended at the
      /// limit of crack events; edges failing in its last check.
      unsigned int crack_events    = 0;
      bool         crack_limit_hit = false;
      unsigned int failing_edges   = 0;
    };

    const StepReport &
    get_step_report() const
    {
      return step_report;
    }

    /** Wall time spent in the last call to do_time_step() (s). */
    double
    last_step_wall_time() const
    {
      return last_step_time;
    }
    /** @} */

  private:
    void
    make_mesh(const Triangulation<dim> *triangulation);
    /**
     * Distribute the dofs and build the index caches and state vectors;
     * with @p element_matrices also every cell's element matrices on the
     * present geometry (crack_edges() computes them itself, after it has
     * moved the mesh back and forth).
     */
    void
    setup_dofs(const bool element_matrices = true);
    void
    setup_constraints();
    void
    setup_loads();
    void
    setup_measure_points();
    void
    build_element_matrices(const bool only_moved_cells);
    void
    assemble_global_matrices();
    void
    assemble_system_matrix(const double dt);
    void
    factorize(const bool with_contacts);
    void
    setup_contacts();
    void
    update_sparsity_for_contacts();
    /** Condense @p dsp, make it the sparsity pattern, and reinit every
     * matrix on it (their entries are zero then). */
    void
    reinit_matrices(DynamicSparsityPattern &dsp);

    /** Find the interior edges that may fracture (setup). */
    void
    setup_fracture();

    /** Area-weighted mean of the stresses @p sigma at the quadrature
     * points of @p cell. */
    SymmetricTensor<2, dim>
    mean_stress(const unsigned int                          cell,
                const std::vector<SymmetricTensor<2, dim>> &sigma) const;

    /** Area-weighted mean stress of every cell. */
    std::vector<SymmetricTensor<2, dim>>
    cell_mean_stresses() const;

    /**
     * Check the fracturable edges against the fracture criterion, from the
     * step's start (the present state) to its trial end (the increment
     * @p d, not committed); a step of length @p dt.
     * Counts the failing edges and keeps the earliest failure of the run.
     * Detection only: the edges are not split yet.
     */
    std::vector<std::array<unsigned int, 2>>
    check_fracture(const Vector<double> &d, const double dt);

    void
    compute_internal_force();
    void
    compute_initial_acceleration();
    /**
     * Everything a step needs before its first attempt: on the first step
     * the initial acceleration, measure points and external force; on
     * every step the element matrices of the cells that moved.
     */
    void
    prepare_step();
    /**
     * Solve the present step from its start state, with step cuts until
     * an attempt is accepted: contact detection, then attempts of the
     * step controller's sizes. Returns the accepted size; @p d holds the
     * increment. Nothing is committed.
     */
    double
    solve_step(Vector<double> &d);
    /** One attempt of size @p dt: the open-close iteration. */
    time::AttemptResult
    try_time_step(const double dt, Vector<double> &d);
    /**
     * Accept the increment @p d of a step of length @p dt: contacts,
     * velocity and acceleration (by the integrator), stresses, bolts, work
     * of the loads, internal force, displacement, vertex positions, time.
     */
    void
    commit_step(const Vector<double> &d, const double dt);
    /** The step report and the statistics row of the step just done. */
    void
    record_statistics(const double dt);
    /**
     * The stresses of cell @p c at the end of a step with increment @p d:
     * the start stresses turned by the cell's rotation in the increment
     * (with Control/Rotate with spin), plus C eps(d). @p sigma holds the
     * start stresses on entry.
     */
    void
    advance_cell_stress(const unsigned int                    c,
                        const Vector<double>                 &d,
                        std::vector<SymmetricTensor<2, dim>> &sigma) const;
    /** Rotation (rad) of cell @p c in the increment @p d, times its area,
     * and its area. */
    std::pair<double, double>
    cell_rotation(const unsigned int c, const Vector<double> &d) const;
    /**
     * Turn the velocity and inertia force of each block relative to its
     * centre of mass by the block's rotation in the increment @p d.
     */
    void
    rotate_velocities(const Vector<double> &d);
    void
    move_mesh(const Vector<double> &d);
    void
    record_measure_points();
    void
    output_results();
    void
    write_statistics() const;

    parameters::Parameters              parameters;
    ParameterHandler                    prm;
    std::unique_ptr<Triangulation<dim>> user_triangulation;

    /// Console output; also copied into the log file once the run starts.
    std::ofstream                   log_file;
    std::unique_ptr<std::streambuf> tee_buffer;
    std::ostream                    console;
    ConditionalOStream              pcout;
    mutable TimerOutput             timer;

    CrackableMesh                        mesh;
    std::unique_ptr<FESystem<dim>>       fe;
    MappingFE<dim>                       mapping;
    std::unique_ptr<Quadrature<dim - 1>> face_quadrature;
    unsigned int                         n_output_subdivisions = 1;
    DoFHandler<dim>                      dof_handler;

    ElementCache<dim> element_cache;

    /// The dofs as index arrays, for the loops of the time step.
    DofMap dof_map;

    Constraints boundary_constraints;
    /// Stiffness of the penalty springs of Constraint method = penalty.
    double penalty_stiffness = 0;

    /// Couplings of elements and bolts, before contacts and condensation.
    SparsityPattern base_sparsity;
    /// The (vertex, cell) contact couplings the sparsity pattern holds.
    std::vector<std::pair<unsigned int, unsigned int>> pattern_couplings;
    SparsityPattern                                    sparsity_pattern;
    SparseMatrix<double>                               stiffness_matrix;
    SparseMatrix<double>                               mass_matrix;
    SparseMatrix<double>                               damping_matrix;
    bool                                               has_damping = false;
    SparseMatrix<double>                               system_matrix;
    SparseMatrix<double>                               condensed_matrix;
    std::unique_ptr<LinearSolver>                      linear_solver;
    double                                             assembled_dt     = -1;
    bool                                               matrices_changed = true;
    /// The factorization is that of the system matrix without contacts.
    bool base_factorized = false;
    /// The last GMRES solve with an earlier factorization converged slowly:
    /// factorize the next changed system.
    bool refactorize_next = false;

    contact::ContactHandler contacts;
    double                  contact_threshold     = 0;
    double                  penetration_tolerance = 0;

    Vector<double> displacement;
    /// Velocity and inertia force M a, carried by the time integrator.
    time::KinematicState kinematics;
    /// With an integrator that averages contact forces: the correction of
    /// the inertia force for the step being solved
    /// (ContactHandler::newmark_correction()).
    Vector<double> inertia_correction;
    Vector<double> internal_force;
    /// External force at the present time, and at the end of the step
    /// being solved (for the work of the loads).
    Vector<double> external_force, step_external_force;
    double         load_work              = 0;
    double         initial_kinetic_energy = 0;

    std::vector<std::vector<SymmetricTensor<2, dim>>> stress;

    ExternalLoads loads;
    BoltSprings   bolts;

    std::vector<PointEvaluator>             measure_points;
    std::vector<std::vector<MeasureSample>> measure_histories;

    double               time        = 0;
    unsigned int         step_number = 0;
    time::StepController step_controller;
    double       stored_strain_energy        = 0;
    double       initial_strain_energy       = 0;
    bool         initial_strain_energy_known = false;
    /// Material id of every active cell.
    std::vector<unsigned int> cell_material;
    double                    scene_half_height      = 0;
    unsigned int              last_solver_iterations = 0;
    unsigned int              n_matrix_rebuilds      = 0;
    double                    last_step_time         = 0;
    double                    max_increment          = 0;
    bool                      is_set_up              = false;
    bool                      parameters_from_file   = false;

    /// Interior edges of the blocks whose material may fracture, and the
    /// strength of each (the weaker of its two cells' materials).
    std::vector<fracture::InteriorEdge> fracture_edges;
    std::vector<fracture::Strength>     fracture_strength;
    EdgeFailureRecord                   first_edge_failure;
    bool                                fracture_enabled = false;
    unsigned int                        n_failing_edges  = 0;
    unsigned int                        n_crack_events   = 0;
    unsigned int                        n_cracked_edges  = 0;
    bool                                crack_limit_hit  = false;

    StepReport                       step_report;
    TableHandler                     statistics;
    double                           next_output_time = 0;
    postprocess::VisualizationWriter visualization;
  };
} // namespace ndda

#endif
