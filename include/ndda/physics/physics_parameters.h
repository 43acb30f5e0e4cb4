// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_physics_parameters_h
#define ndda_physics_physics_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <ndda/geometry/block_mesh.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace ndda
{
  class ConstitutiveLaw;

  /**
   * The parameters that physics/ reads: subsections Materials, Loads,
   * Boundary conditions and Bolts, and the choices of Control that name a
   * physics part (linear solver, constraint method). Each struct declares
   * and parses its own entries.
   *
   * @ingroup parameters
   */
  namespace parameters
  {
    using dealii::ParameterHandler;
    using dealii::Point;

    /** The linear solver of Control/Linear solver (physics::LinearSolver). */
    enum class LinearSolverType
    {
      /// Cholesky (CHOLMOD) where the matrix is symmetric positive
      /// definite, LU (UMFPACK) where it is not.
      direct,
      umfpack,
      klu,
      cg_amg,
      /// CG (BiCGStab where non-symmetric) with the inverse diagonal as
      /// preconditioner, on ndda's matrix itself (JacobiCG).
      cg_jacobi,
      /// MUMPS (through Trilinos' Amesos) on the processes of the run.
      mumps
    };

    enum class ConstraintMethod
    {
      exact,
      penalty
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

  } // namespace parameters
} // namespace ndda

#endif
