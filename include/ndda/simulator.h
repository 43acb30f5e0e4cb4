// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_simulator_h
#define ndda_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/data_out_base.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <ndda/base/log_file.h>
#include <ndda/base/section_timer.h>
#include <ndda/contact/contact_handler.h>
#include <ndda/contact/detection_distance.h>
#include <ndda/contact/open_close_solver.h>
#include <ndda/fracture/crack_tips.h>
#include <ndda/fracture/edge_failure_check.h>
#include <ndda/kinematics/automatic_kinematics.h>
#include <ndda/mesh/crackable_mesh.h>
#include <ndda/parameters/parameters.h>
#include <ndda/physics/bolts.h>
#include <ndda/physics/constraints.h>
#include <ndda/physics/dof_map.h>
#include <ndda/physics/element_cache.h>
#include <ndda/physics/finite_element.h>
#include <ndda/physics/linear_system.h>
#include <ndda/physics/loads.h>
#include <ndda/physics/stress_field.h>
#include <ndda/postprocess/measure_points.h>
#include <ndda/postprocess/progress_report.h>
#include <ndda/postprocess/visualization.h>
#include <ndda/scene/discretization.h>
#include <ndda/scene/scene.h>
#include <ndda/time/step_controller.h>
#include <ndda/time/time_integrator.h>

#include <fstream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace ndda
{
  using namespace dealii;

  class Archive;

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
    explicit Simulator(const std::string &parameter_file,
                       const MPI_Comm     communicator = MPI_COMM_WORLD);

    /**
     * A scene from parameters that were already read; if @p triangulation
     * is given, it replaces the Geometry section (one block per material
     * id, see CrackableMesh::build()).
     */
    Simulator(const parameters::Parameters &parameters,
              const Triangulation<dim>     *triangulation = nullptr,
              const MPI_Comm                communicator  = MPI_COMM_WORLD);

    ~Simulator();

    /**
     * The run whose checkpoint (Output/Checkpoint interval) is in the
     * output directory @p directory, ready to go on from it: run() (or
     * setup() first) reads the scene's parameters and its whole state from
     * `checkpoint.ndda`, truncates the statistics and measure-point files
     * to the rows they had then, and continues writing into @p directory.
     * A resumed run ends in the same state as one that was never
     * interrupted, bit for bit (doc/design.md, "Decisions": checkpoints).
     */
    static std::unique_ptr<Simulator<dim>>
    resume(const std::string &directory,
           const MPI_Comm     communicator = MPI_COMM_WORLD);

    /**
     * Write the present state to `checkpoint.ndda` in the output directory
     * (replacing the last one, never leaving half a file), after writing
     * the rows of the statistics and measure points. Then set up what
     * a resumed run sets up anew (system, factorization, neighbour list),
     * so that this run and a resumed one go on identically. run() calls it
     * every Output/Checkpoint interval; needs a scene read from a `.prm`
     * file (it holds the file's text).
     */
    void
    write_checkpoint();

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
    /** The processes that run the scene together. */
    MPI_Comm
    get_communicator() const
    {
      return communicator;
    }

    /**
     * Whether this process writes the run's files (statistics, measure
     * points, log, checkpoints, crack files, the frames' collections) and
     * its console output: the first process of the communicator. Every
     * process writes its piece of each frame.
     */
    bool
    writes_files() const
    {
      return this_process == 0;
    }

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
      return fem.dof_handler;
    }

    const Mapping<dim> &
    get_mapping() const
    {
      return fem.mapping;
    }

    /** Subdivisions of a cell in the output (from the element). */
    unsigned int
    get_n_output_subdivisions() const
    {
      return fem.n_output_subdivisions;
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
    ArrayView<const SymmetricTensor<2, dim>>
    get_cell_stress(const unsigned int cell) const
    {
      return stresses[cell];
    }

    /** The stresses at the quadrature points of every active cell. */
    const StressField &
    get_stresses() const
    {
      return stresses;
    }

    /** Area-weighted mean stress of the active cell @p cell. */
    SymmetricTensor<2, dim>
    mean_cell_stress(const unsigned int cell) const
    {
      return stresses.mean(cell);
    }

    /** The global mass matrix (kg, includes the thickness). */
    const SparseMatrix<double> &
    get_mass_matrix() const
    {
      return fem.linear_system.get_mass_matrix();
    }

    /**
     * External force vector (gravity, point and line loads, bolt
     * pretension) at time @p t on the current geometry.
     */
    void
    assemble_external_force(const double t, Vector<double> &force) const;

    /**
     * Histories of the measure points, one vector per point: the last
     * sample is back(). The run streams the samples to measure_points.txt
     * and keeps only those not yet written, unless
     * keep_measure_histories() was called before run().
     */
    const std::vector<std::vector<MeasureSample>> &
    get_measure_histories() const
    {
      return measure_points.get_histories();
    }

    /** Keep every measure-point sample in memory for
     * get_measure_histories(). */
    void
    keep_measure_histories()
    {
      measure_points.keep_all();
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

    /** Wall time per section of the run so far (the table of the log). */
    const SectionTimer &
    get_timer() const
    {
      return timer;
    }

    /** Number of factorizations of the system matrix so far. */
    unsigned int
    n_factorizations() const
    {
      return fem.linear_system.n_factorizations();
    }

    /** Contacts of the scene: states, statistics of the last step. */
    const contact::ContactHandler &
    get_contacts() const
    {
      return contacts;
    }

    /** The detection distance of the steps (Contact/Detection distance). */
    const contact::DetectionDistance &
    get_detection_distance() const
    {
      return detection;
    }

    /** Work done by the external loads since the start (J). */
    double
    work_of_loads() const
    {
      return load_work;
    }

    /**
     * Work done by prescribed motion since the start (J): the reactions of
     * the exact constraints times their prescribed increments, step by
     * step (LinearSystem::last_constraint_work()). Zero with fixed
     * supports only; not counted with `Constraint method = penalty`.
     */
    double
    work_of_prescribed_motion() const
    {
      return prescribed_work;
    }

    /** Whether any material of the scene has viscosity. */
    bool
    has_viscosity() const
    {
      return fem.linear_system.has_damping();
    }

    /** Energy the materials' viscosity took out since the start (J). */
    double
    viscous_dissipation() const
    {
      return viscous_work;
    }

    /**
     * Mechanical energy gained since the start (J): kinetic + strain +
     * contact spring energy - work of the loads - work of prescribed
     * motion - initial kinetic energy. Zero for an exact,
     * energy-conserving run without friction; negative where friction,
     * viscosity, impacts or the integrator take energy out; positive only
     * if something creates energy (a test for spurious gain).
     */
    double
    energy_error() const;

    /**
     * The part of energy_error() that no physical term explains (J): the
     * gain plus what friction (ContactStatistics::friction_dissipation) and
     * viscosity took out. What the integrator (its damping and its
     * treatment of contacts that close or open within a step) took, if
     * negative, or gave, if positive. @p kinetic and @p strain as
     * kinetic_energy() and strain_energy() return them.
     */
    double
    numerical_energy(const double kinetic, const double strain) const;

    /** energy_error() with the kinetic energy and the strain energy given
     * (as kinetic_energy() and strain_energy() return them), for a caller
     * that has them already. */
    double
    energy_error(const double kinetic, const double strain) const;

    /**
     * The earliest edge failure the fracture check has found so far: the
     * time (s), the edge's midpoint at the step's end, and the mode.
     * Without fracturing materials, or before any edge fails, mode is
     * none.
     */
    using EdgeFailureRecord = fracture::FailureRecord;

    const EdgeFailureRecord &
    get_first_edge_failure() const
    {
      return fracture_check.first_failure();
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

    /**
     * Every advance of a crack tip since the start of this run (`Crack
     * path = maximum tangential stress`; not kept in checkpoints).
     */
    const std::vector<fracture::TipAdvance> &
    get_tip_advances() const
    {
      return tip_advances;
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

    /** The automatic block kinematics (Kinematics = auto): its blocks,
     * promotions and demotions. */
    const ndda::kinematics::AutomaticKinematics &
    get_automatic_kinematics() const
    {
      return automatic;
    }

    /** The discretization: element, dofs, block models, constraints. */
    const scene::Discretization &
    get_discretization() const
    {
      return fem;
    }

    /** Wall time spent in the last call to do_time_step() (s). */
    double
    last_step_wall_time() const
    {
      return last_step_time;
    }
    /** @} */

  private:
    /// The checkpoint a resumed run reads (source/simulator_checkpoint.cc).
    struct ResumeState;

    /**
     * Write the run's state after the mesh and the block models to a
     * checkpoint, or read it (Archive); @p vertices are the present vertex
     * positions (read into it, not set).
     */
    void
    serialize_state(Archive &ar, std::vector<Point<dim>> &vertices);
    /** Resuming: the mesh and the block models from the checkpoint. */
    void
    read_checkpoint_mesh();
    void
    read_checkpoint_models();
    /** Resuming, at the end of setup(): the state from the checkpoint. */
    void
    read_checkpoint_state();
    /** After writing or reading a checkpoint: set up anew what depends on
     * how the run came here (write_checkpoint()). */
    void
    rebuild_after_checkpoint();
    /** Resuming, in run(): cut the statistics and measure-point files
     * back to what they held at the checkpoint. */
    void
    continue_files();

    /**
     * Distribute the dofs and build the index caches and state vectors;
     * with @p element_matrices also every cell's element matrices on the
     * present geometry (crack_edges() computes them itself, after it has
     * moved the mesh back and forth).
     */
    void
    setup_dofs(const bool element_matrices = true);
    /** The contacts of the present mesh. */
    void
    setup_contacts();
    /** The element matrices of the cells that moved (all, if not
     * @p only_moved_cells) and what depends on them; the global matrices
     * also if no cell moved, with @p always. */
    void
    build_element_matrices(const bool only_moved_cells,
                           const bool always = false);
    /** Add the viscous dissipation of the step with increment @p d. */
    void
    add_viscous_work(const Vector<double> &d, const double dt);

    /** Internal force and strain energy of the present stresses. */
    void
    compute_internal_force();

    /**
     * The rest of compute_internal_force() once the stresses' internal
     * force is in internal_force and @p energy is the energy they hold:
     * the strain energy, and the bolts' forces.
     */
    void
    finish_internal_force(const double energy);

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
    /** Detect the contacts of the present step within @p distance and
     * set the system's couplings up for them. */
    void
    detect_contacts(const double distance);
    /** One attempt of size @p dt: the open-close iteration, then the
     * checks of the increment @p d (check_increment()). */
    time::AttemptResult
    try_time_step(const double dt, Vector<double> &d);
    /**
     * Whether the settled increment @p d is accepted: not larger than the
     * DDA step control allows, no cell turned inside out, no contact
     * deeper than the penetration tolerance (else the penalty is raised).
     */
    time::AttemptResult
    check_increment(const Vector<double> &d);
    /**
     * Throw an ExcMessage if a value of the dof vector @p v is not finite,
     * naming the step, the time, @p quantity, the first such value's node
     * and block, and @p hint (the likely causes), so that a run stops
     * where it goes wrong rather than writing NaN to the end.
     */
    void
    require_finite(const Vector<double> &v,
                   const double          dt,
                   const std::string    &quantity,
                   const std::string    &hint) const;
    /**
     * Check the fracturable edges against the fracture criterion, from the
     * step's start (the present state) to its trial end (the increment
     * @p d, not committed); a step of length @p dt. Returns the edges that
     * crack now. Detection only: the edges are not split yet.
     */
    std::vector<std::array<unsigned int, 2>>
    check_fracture(const Vector<double> &d, const double dt);
    /**
     * `Crack path = maximum tangential stress`: turn the @p failing edges
     * into tip advances (fracture::plan_crack_advance()), move the vertices
     * the plan moves and carry the state to them
     * (state_transfer::interpolate_moved()), record the advances. Returns
     * the edges crack_edges() must crack. @p d: the step's trial
     * increment, in which the edges failed.
     */
    std::vector<std::array<unsigned int, 2>>
    advance_crack_tips(const std::vector<std::array<unsigned int, 2>> &failing,
                       const Vector<double>                           &d);
    /**
     * Accept the increment @p d of a step of length @p dt: contacts,
     * velocity and acceleration (by the integrator), stresses, bolts, work
     * of the loads, internal force, displacement, vertex positions, time.
     */
    void
    commit_step(const Vector<double> &d, const double dt);
    /**
     * Kinematics = auto: the blocks of the mesh, the fracture strengths of
     * the cells, which blocks hold a crack (setup and after a crack).
     * These members are in source/simulator_kinematics.cc.
     */
    void
    setup_automatic_kinematics();
    /**
     * Kinematics = auto: promote the reduced auto blocks that are near
     * failure at the trial end of the step with increment @p d (or, with
     * nullptr, at the start of the run: those that start meshed, not
     * counted). Returns whether any was promoted: the step is then solved
     * again.
     */
    bool
    promote_blocks(const Vector<double> *d);
    /** Kinematics = auto, after a step: demote the blocks that have been
     * unloaded long enough. */
    void
    demote_blocks();
    /** The system, the fracture check and (not @p at_start) the global
     * matrices for the present block models. */
    void
    set_up_block_models(const bool at_start);
    /** The step report and the statistics row of the step just done. */
    void
    record_statistics(const double dt);
    void
    output_results();
    void
    write_statistics();
    /** The checkpoint file (the first process's part of write_checkpoint()). */
    void
    write_checkpoint_file();

    /// The processes that run the scene (Simulator(): MPI_COMM_SELF in a
    /// program without MPI), their number and this one's rank.
    MPI_Comm     communicator;
    unsigned int n_processes;
    unsigned int this_process;

    parameters::Parameters              parameters;
    ParameterHandler                    prm;
    std::unique_ptr<Triangulation<dim>> user_triangulation;

    /// Console output; also copied into the log file once the run starts.
    std::ostream         console;
    LogFile              log_file;
    ConditionalOStream   pcout;
    mutable SectionTimer timer;

    CrackableMesh mesh;
    /// The finite element discretization of the blocks: element, dofs,
    /// element matrices, constraints, loads, bolts, linear system.
    scene::Discretization fem;

    contact::OpenCloseSolver open_close;
    contact::ContactHandler  contacts;
    scene::ContactDistances  contact_distances;
    /// The detection distance of each step (Contact/Detection distance).
    contact::DetectionDistance detection;

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
    /// Scratch of a step, kept so that a step allocates nothing: the
    /// right-hand side and the prescribed increments of try_time_step(),
    /// the increment with exact rotations of commit_step().
    Vector<double> step_rhs, step_prescribed, step_motion;
    double         load_work       = 0;
    double         prescribed_work = 0;
    double         viscous_work    = 0;
    /// The last step's increment over its size, for add_viscous_work().
    Vector<double> last_mean_velocity;
    double         initial_kinetic_energy = 0;

    StressField stresses;

    postprocess::MeasurePoints measure_points;

    double               time        = 0;
    unsigned int         step_number = 0;
    time::StepController step_controller;
    double               stored_strain_energy        = 0;
    double               initial_strain_energy       = 0;
    bool                 initial_strain_energy_known = false;
    double               scene_half_height           = 0;
    unsigned int         n_matrix_rebuilds           = 0;
    double               last_step_time              = 0;
    double               max_increment               = 0;
    bool                 is_set_up                   = false;
    /// A reduced block's constraint lines depend on its orientation and
    /// it turned: set the system up again before the next step.
    bool block_lines_stale    = false;
    bool parameters_from_file = false;
    /// The `.prm` file's text and its absolute path, for checkpoints.
    std::string parameter_text, parameter_file_name;
    /// Set by resume(): the checkpoint to read.
    std::shared_ptr<ResumeState> resume_state;
    /// The blocks' rotations in the increment of the last attempt
    /// (block_rotations()), if it computed them, for commit_step().
    std::vector<double> solved_rotation;

    /// Kinematics = auto: which blocks are promoted and demoted.
    ndda::kinematics::AutomaticKinematics automatic;

    fracture::EdgeFailureCheck fracture_check;
    /// See get_tip_advances().
    std::vector<fracture::TipAdvance> tip_advances;
    unsigned int                      n_crack_events  = 0;
    unsigned int                      n_cracked_edges = 0;
    bool                              crack_limit_hit = false;

    StepReport step_report;
    /// Rows not yet written (mutable: writing them forgets them).
    postprocess::StatisticsTable     statistics;
    postprocess::VisualizationWriter visualization;
  };
} // namespace ndda

#endif
