// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_parameters_parameters_h
#define ndda_parameters_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <ndda/fracture/fracture_criterion.h>
#include <ndda/geometry/block_mesh.h>
#include <ndda/postprocess/postprocessor.h>
#include <ndda/time/time_integrator.h>

#include <memory>
#include <string>
#include <vector>

namespace ndda
{
  using namespace dealii;

  class ConstitutiveLaw;

  namespace contact
  {
    class ContactLaw;
  }

  /**
   * The parameters of a scene, one struct per `.prm` subsection, each with
   * static `declare_parameters` and a `parse_parameters` that checks every
   * value and names the entry in its error message.
   *
   * Lists of named objects (blocks, materials, loads, boundary conditions,
   * bolts) are declared by a name list entry, e.g.
   * `set Blocks = bar, plate` in `subsection Geometry`, followed by one
   * subsection per name. The file is therefore read twice: once for the
   * name lists only, and once strictly with everything declared (see
   * Parameters::read()).
   *
   * @ingroup parameters
   */
  namespace parameters
  {
    /** The linear solver of Control/Linear solver (physics::LinearSolver). */
    enum class LinearSolverType
    {
      umfpack,
      klu,
      cg_amg
    };

    enum class ConstraintMethod
    {
      exact,
      penalty
    };

    /** subsection Control */
    struct Control
    {
      /// Static, dynamic or quasi-static (time::create_time_integrator()).
      time::AnalysisType analysis_type;
      /// The scheme's name, `set Time integrator = ...`.
      std::string time_integrator_name;
      /// The integrator of the analysis: the selected scheme with its
      /// parameters read, wrapped for a static analysis and replaced for a
      /// quasi-static one; stateless, so it may be shared.
      std::shared_ptr<const time::TimeIntegrator> time_integrator;
      double                                      time_step;
      double                                      end_time;
      double                                      max_displacement_ratio;
      unsigned int                                max_step_cuts;
      LinearSolverType                            linear_solver;
      double                                      solver_tolerance;
      ConstraintMethod                            constraint_method;
      double                                      penalty_factor;
      double                                      matrix_update_tolerance;
      bool                                        rotate_with_spin;

      /// The scalar element by name, as make_element() takes it
      /// (physics/finite_element.h): Finite element, or else
      /// FE_SimplexP(Element degree).
      std::string finite_element;
      /// Whether finite_element comes from Element degree (for messages).
      bool element_from_degree;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** How the contact penalty is chosen. */
    enum class PenaltyMethod
    {
      /// A fixed multiple of the largest Young's modulus.
      fixed,
      /// Starts as the fixed value and doubles whenever a step ends with a
      /// penetration beyond the tolerance (the step is then solved again).
      automatic
    };

    /** Resolution of vertex-vertex contacts, thesis chapter 6. */
    enum class VertexVertexMethod
    {
      /// The thesis's revised method: entrance edge from the vertex's
      /// trajectory (6.3), temporary vertex-vertex spring for genuine
      /// indeterminacy (6.2).
      revised,
      /// The original rule: the potential reference edge with the smallest
      /// penetration at the end of the step.
      shortest_path
    };

    /** subsection Contact */
    struct Contact
    {
      bool               enabled;
      PenaltyMethod      penalty_method;
      double             penalty_factor;
      double             shear_stiffness_ratio;
      unsigned int       max_open_close_iterations;
      unsigned int       reuse_iterations;
      VertexVertexMethod vertex_vertex_method;
      double             max_penetration_ratio;
      /// The contact law's name, `set Contact law = ...`, and the law with
      /// its parameters read (contact/contact_law.h); stateless, shared.
      std::string                                law_name;
      std::shared_ptr<const contact::ContactLaw> law;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** One material of subsection Materials. */
    struct Material
    {
      std::string name;
      double      density;
      double      youngs_modulus;
      double      poissons_ratio;
      /// Friction angle of contacts on this material's faces (degrees);
      /// negative: Materials/Joint's. A contact uses the smaller of its
      /// two sides.
      double joint_friction_angle;
      double friction_angle;
      double cohesion;
      double tensile_strength;
      double viscosity;
      /// Cells of this material may crack (Fracture subsection).
      bool fracture;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const std::string &name);
    };

    /** Strength of joints and cracks (used by contact and fracture). */
    struct JointMaterial
    {
      double friction_angle;
      double cohesion;
      double tensile_strength;
    };

    /** subsection Materials */
    struct Materials
    {
      /// The constitutive law, `set Constitutive law = ...`, with its
      /// parameters read. Empty in materials not read from a parameter
      /// file: the element cache then uses "linear elasticity".
      std::string                            constitutive_law_name;
      std::shared_ptr<const ConstitutiveLaw> constitutive_law;
      bool                                   plane_strain;
      double                                 thickness;
      std::vector<Material>                  materials;
      JointMaterial                          joint;

      /** Index of the material called @p name; throws naming @p entry. */
      unsigned int
      id(const std::string &name, const std::string &entry) const;

      static void
      declare_parameters(ParameterHandler               &prm,
                         const std::vector<std::string> &names);
      void
      parse_parameters(ParameterHandler               &prm,
                       const std::vector<std::string> &names);
    };

    /** Per-block initial state, given beside the block's geometry. */
    struct InitialState
    {
      /// sigma_xx, sigma_yy, sigma_xy (Pa, tension positive).
      std::array<double, 3> stress = {{0., 0., 0.}};
      /// Velocity components as functions of x, y (muparser).
      std::string velocity = "0; 0";
    };

    /** subsection Geometry */
    struct Geometry
    {
      std::vector<geometry::BlockDescription>  blocks;
      std::vector<geometry::RegionDescription> regions;
      /// Initial state, one per block, then one per region.
      std::vector<InitialState> block_states;
      std::vector<InitialState> region_states;
      std::string               mesh_file;
      /// For a mesh file: the material name of each physical surface tag
      /// ("tag: material, ..."), empty means material id = tag.
      std::vector<std::pair<unsigned int, std::string>> mesh_file_materials;
      double                                            min_angle;

      static void
      declare_parameters(ParameterHandler               &prm,
                         const std::vector<std::string> &block_names,
                         const std::vector<std::string> &region_names);
      void
      parse_parameters(ParameterHandler               &prm,
                       const std::vector<std::string> &block_names,
                       const std::vector<std::string> &region_names,
                       const Materials                &materials,
                       const std::string              &base_directory);
    };

    /** A point load, thesis 3.5.1. */
    struct PointLoad
    {
      std::string name;
      Point<2>    point;
      /// "fx(t); fy(t)" in N (per unit thickness times thickness: force).
      std::string force;
    };

    /** A load on a boundary segment, thesis 3.5.2. */
    struct LineLoad
    {
      std::string       name;
      geometry::Segment segment;
      /// Pressure (scalar, Pa, pushing into the block) or traction (Pa).
      bool        is_pressure;
      std::string value;
    };

    /** subsection Loads */
    struct Loads
    {
      /// Gravity as "gx(t); gy(t)" (m/s^2).
      std::string            gravity;
      std::vector<PointLoad> point_loads;
      std::vector<LineLoad>  line_loads;

      static void
      declare_parameters(ParameterHandler               &prm,
                         const std::vector<std::string> &point_names,
                         const std::vector<std::string> &line_names);
      void
      parse_parameters(ParameterHandler               &prm,
                       const std::vector<std::string> &point_names,
                       const std::vector<std::string> &line_names);
    };

    /** Kinds of displacement constraints, thesis 3.9. */
    enum class ConstraintType
    {
      fixed,
      roller,
      displacement,
      velocity
    };

    /** One entry of subsection Boundary conditions. */
    struct BoundaryCondition
    {
      std::string                    name;
      ConstraintType                 type;
      std::vector<Point<2>>          points;
      std::vector<geometry::Segment> segments;
      /// Direction along which a roller may move (degrees from the x axis).
      double roller_angle;
      /// Histories: "ux(t); uy(t)" (displacement), "vx(t); vy(t)" (velocity),
      /// "d(t)" (roller: displacement along the constrained normal).
      std::string value;
    };

    /** subsection Boundary conditions */
    struct BoundaryConditions
    {
      std::vector<BoundaryCondition> conditions;

      static void
      declare_parameters(ParameterHandler               &prm,
                         const std::vector<std::string> &names);
      void
      parse_parameters(ParameterHandler               &prm,
                       const std::vector<std::string> &names);
    };

    /** A bolt between two points, thesis 3.6. */
    struct Bolt
    {
      std::string name;
      Point<2>    first;
      Point<2>    second;
      double      stiffness;
      double      pretension;
    };

    /** subsection Bolts */
    struct Bolts
    {
      std::vector<Bolt> bolts;

      static void
      declare_parameters(ParameterHandler               &prm,
                         const std::vector<std::string> &names);
      void
      parse_parameters(ParameterHandler               &prm,
                       const std::vector<std::string> &names);
    };

    /** subsection Output */
    struct Output
    {
      std::string           directory;
      double                interval;
      bool                  write_vtu;
      bool                  write_hdf5;
      std::vector<Point<2>> measure_points;
      double                progress_interval;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const std::string &scene_name);
    };

    /**
     * All parameters of a scene.
     */
    struct Parameters
    {
      std::string             scene_name;
      Control                 control;
      Contact                 contact;
      Materials               materials;
      Geometry                geometry;
      Loads                   loads;
      BoundaryConditions      boundary_conditions;
      Bolts                   bolts;
      Output                  output;
      fracture::Parameters    fracture;
      postprocess::Parameters postprocess;

      /** The name lists that decide which subsections exist. */
      struct NameLists
      {
        std::vector<std::string> blocks, regions, materials, point_loads,
          line_loads, boundary_conditions, bolts;
      };

      /** Declare everything for the given name lists. */
      static void
      declare_parameters(ParameterHandler &prm, const NameLists &names);

      /**
       * Read a scene from @p input (the text of a `.prm` file) named
       * @p filename (for messages and relative paths): first the name lists,
       * then everything, strictly. @p prm ends up holding all entries, as
       * used, for printing. Throws ExcMessage on every error.
       */
      void
      read(const std::string &input,
           const std::string &filename,
           ParameterHandler  &prm);

      /** Read a scene from a file. */
      void
      read_file(const std::string &filename, ParameterHandler &prm);
    };

    /**
     * Parse "x, y; x, y; ..." into points. @p entry names the entry in the
     * error message.
     */
    std::vector<Point<2>>
    parse_points(const std::string &text, const std::string &entry);

    /** Parse "x1, y1, x2, y2; ..." into segments. */
    std::vector<geometry::Segment>
    parse_segments(const std::string &text, const std::string &entry);

    /**
     * Check that @p expression is a valid muparser expression with
     * @p n_components components separated by ';' in the given variables;
     * throws naming @p entry otherwise.
     */
    void
    check_function(const std::string &expression,
                   const unsigned int n_components,
                   const std::string &variables,
                   const std::string &entry);
  } // namespace parameters
} // namespace ndda

#endif
