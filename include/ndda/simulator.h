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
#include <ndda/physics/element_cache.h>
#include <ndda/physics/finite_element.h>
#include <ndda/physics/linear_solver.h>

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
   * space, and runs the time loop of thesis 3.11 (without contact and
   * fracture, which come with later layers):
   *
   *   for every step: loads at the step's end time, prescribed increments,
   *   solve (K + c_M M + c_C C) d = f, step control, update stresses,
   *   velocities and vertex positions, output.
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
      return velocity;
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

    /** Wall time spent in the last call to do_time_step() (s). */
    double
    last_step_wall_time() const
    {
      return last_step_time;
    }
    /** @} */

  private:
    /** A constrained node: its two dofs and what prescribes them. */
    struct NodeConstraint
    {
      std::array<types::global_dof_index, 2> dofs;
      Point<dim>                             position;
      parameters::ConstraintType             type;
      /// Unit normal of a roller (the constrained direction).
      Tensor<1, dim> normal;
      /// Index into constraint_functions (displacement/velocity/roller).
      unsigned int function = numbers::invalid_unsigned_int;
      std::string  name;
    };

    /** Dof indices and shape values at a fixed material point. */
    struct PointEvaluator
    {
      unsigned int                         cell;
      std::vector<types::global_dof_index> dofs;
      /// Value of each local shape function; component in component[i].
      std::vector<double>       shape_values;
      std::vector<unsigned int> component;
    };

    /** Precomputed quadrature data of one loaded boundary face. */
    struct LoadedFace
    {
      unsigned int                         line_load;
      unsigned int                         cell;
      unsigned int                         face;
      std::vector<types::global_dof_index> dofs;
      std::vector<unsigned int>            component;
      /// shape_values[q][i] * JxW[q] * thickness
      std::vector<std::vector<double>> weighted_shape;
      std::vector<Point<dim>>          points;
      std::vector<Tensor<1, dim>>      normals;
    };

    struct Bolt
    {
      std::array<types::global_dof_index, 4> dofs;
      Point<dim>                             first, second;
      double                                 stiffness;
      double                                 pretension;
      /// Spring force k * elongation, accumulated (N, tension positive).
      double axial_force = 0;
    };

    /** Current positions of a bolt's anchors and the unit vector from the
     * second to the first. */
    std::pair<std::array<Point<dim>, 2>, Tensor<1, dim>>
    bolt_geometry(const Bolt &bolt) const;

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
    update_loaded_faces();
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

    /** Area-weighted mean stress of every cell. */
    std::vector<SymmetricTensor<2, dim>>
    cell_mean_stresses() const;

    /**
     * Check the fracturable edges against the fracture criterion, from the
     * step's start (@p start_vertices, @p start_stresses) to its end (the
     * present state); a step of length @p dt that started at @p t0.
     * Counts the failing edges and keeps the earliest failure of the run.
     * Detection only: the edges are not split yet.
     */
    std::vector<std::array<unsigned int, 2>>
    check_fracture(const std::vector<Point<dim>>              &start_vertices,
                   const std::vector<SymmetricTensor<2, dim>> &start_stresses,
                   const double                                t0,
                   const double                                dt);

    /**
     * The state at a step's start that a step changes: kept so that a
     * step in which edges crack can be solved again from its start on
     * the cracked mesh (thesis 5.3, the crack sequence).
     */
    struct StepStart
    {
      Vector<double>                                    displacement;
      Vector<double>                                    velocity;
      Vector<double>                                    inertia_force;
      std::vector<std::vector<SymmetricTensor<2, dim>>> stress;
      std::vector<double>                               bolt_forces;
      std::vector<Point<dim>>                           vertices;
      contact::ContactHandler                           contacts;
      double                                            time      = 0;
      double                                            load_work = 0;
    };

    void
    save_step_start(StepStart &start) const;
    void
    restore_step_start(const StepStart &start);



    /** How one attempt at a time step ended. */
    enum class StepResult
    {
      accepted,
      /// The largest displacement exceeded the allowed ratio.
      too_large,
      /// The open-close iteration did not settle.
      not_settled,
      /// Automatic penalty: raised; solve the step again.
      penalty_raised,
      /// A cell would turn inside out.
      inverted
    };
    void
    compute_internal_force();
    void
    compute_initial_acceleration();
    StepResult
    try_time_step(const double dt);
    void
    prescribed_increment(const double    t0,
                         const double    dt,
                         Vector<double> &increment) const;
    void
    update_state(const Vector<double> &d, const double dt);
    void
    rotate_with_spin(const Vector<double> &d);
    void
    move_mesh(const Vector<double> &d);
    void
    record_measure_points();
    void
    output_results();
    void
    write_statistics() const;

    /** Find the vertex at @p p; throws naming @p entry if there is none. */
    unsigned int
    find_vertex(const Point<dim> &p, const std::string &entry) const;
    /** Locate @p p in the mesh; throws naming @p entry if it is outside. */
    PointEvaluator
    make_point_evaluator(const Point<dim> &p, const std::string &entry) const;

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

    /// Dof indices of every cell, cell after cell.
    std::vector<types::global_dof_index> cell_dof_indices;
    /// Vector component of each local dof.
    std::vector<unsigned int> local_component;
    /// The (x, y) dofs of every vertex of the triangulation.
    std::vector<std::array<types::global_dof_index, 2>> vertex_dofs;
    /// The (x, y) dofs of every node (vertices and, for P2, edge nodes).
    std::vector<std::array<types::global_dof_index, 2>> node_dofs;
    /// Node of every dof.
    std::vector<unsigned int> dof_to_node;

    AffineConstraints<double>                         constraints;
    std::vector<NodeConstraint>                       node_constraints;
    std::vector<std::unique_ptr<FunctionParser<dim>>> constraint_functions;
    double                                            penalty_stiffness = 0;

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
    Vector<double> velocity;
    /// Newmark: M times the acceleration at the present time (the
    /// inertia force), so that contact forces can be taken out of it
    /// without a mass solve.
    Vector<double> inertia_force;
    /// Newmark with contacts: the correction of the inertia force for the
    /// step being solved (ContactHandler::newmark_correction()).
    Vector<double> inertia_correction;
    Vector<double> internal_force;
    Vector<double> gravity_load[dim];
    /// External force at the present time, and at the end of the step
    /// being solved (for the work of the loads).
    Vector<double> external_force, step_external_force;
    double         load_work              = 0;
    double         initial_kinetic_energy = 0;

    std::vector<std::vector<SymmetricTensor<2, dim>>> stress;

    std::unique_ptr<FunctionParser<dim>>              gravity;
    std::vector<std::unique_ptr<FunctionParser<dim>>> point_load_functions;
    std::vector<PointEvaluator>                       point_load_points;
    std::vector<std::unique_ptr<FunctionParser<dim>>> line_load_functions;
    std::vector<LoadedFace>                           loaded_faces;
    std::vector<Bolt>                                 bolts;

    std::vector<PointEvaluator>             measure_points;
    std::vector<std::vector<MeasureSample>> measure_histories;

    double       time                        = 0;
    double       time_step                   = 0;
    unsigned int step_number                 = 0;
    double       stored_strain_energy        = 0;
    double       initial_strain_energy       = 0;
    bool         initial_strain_energy_known = false;
    /// Material id of every active cell.
    std::vector<unsigned int> cell_material;
    double                    scene_half_height      = 0;
    unsigned int              last_solver_iterations = 0;
    unsigned int              step_cuts              = 0;
    unsigned int              n_matrix_rebuilds      = 0;
    double                    last_step_time         = 0;
    double                    max_increment          = 0;
    bool                      is_set_up              = false;
    bool                      parameters_from_file   = false;
    double                    last_dt                = 0;
    /// Steps in a row below 1e-3 of Control/Time step (do_time_step()).
    unsigned int n_crawling_steps = 0;

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

    TableHandler                                statistics;
    double                                      next_output_time = 0;
    unsigned int                                output_number    = 0;
    std::vector<std::pair<double, std::string>> pvd_records;
    std::vector<XDMFEntry>                      xdmf_entries;
  };
} // namespace ndda

#endif
