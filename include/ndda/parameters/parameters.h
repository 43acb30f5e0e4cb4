// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_parameters_parameters_h
#define ndda_parameters_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <ndda/contact/contact_parameters.h>
#include <ndda/fracture/fracture_criterion.h>
#include <ndda/geometry/block_mesh.h>
#include <ndda/kinematics/automatic_kinematics.h>
#include <ndda/parameters/entries.h>
#include <ndda/physics/physics_parameters.h>
#include <ndda/postprocess/output_parameters.h>
#include <ndda/postprocess/postprocessor.h>
#include <ndda/scene/scene_parameters.h>
#include <ndda/time/time_integrator.h>

#include <memory>
#include <optional>
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
      /// The scene's default block kinematics model (by name).
      std::string kinematics;
      /// The settings of Kinematics = auto.
      kinematics::AutomaticSettings automatic_kinematics;

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

    /**
     * All parameters of a scene.
     */
    struct Parameters
    {
      std::string        scene_name;
      Control            control;
      Contact            contact;
      Materials          materials;
      Geometry           geometry;
      Loads              loads;
      BoundaryConditions boundary_conditions;
      Bolts              bolts;
      Output             output;
      Fracture           fracture;
      Postprocess        postprocess;

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

      /**
       * Check what no single section can: HDF5 output with the element's
       * subdivisions, the time step against the end time, a fracturing
       * material whose strength the criterion finds zero
       * (FractureCriterion::fails_under_any_load()).
       */
      void
      check_consistency() const;
    };

    /**
     * The strength of each material for the fracture check (friction
     * angle in radians), unset for materials that do not fracture.
     */
    std::vector<std::optional<fracture::Strength>>
    material_strengths(const Materials &materials);

  } // namespace parameters
} // namespace ndda

#endif
