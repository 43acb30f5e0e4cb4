// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_scene_scene_h
#define ndda_scene_scene_h

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/mapping.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/vector.h>

#include <ndda/contact/contact_handler.h>
#include <ndda/contact/open_close_solver.h>
#include <ndda/fracture/fracture_criterion.h>
#include <ndda/mesh/crackable_mesh.h>
#include <ndda/parameters/parameters.h>
#include <ndda/physics/dof_map.h>
#include <ndda/physics/stress_field.h>
#include <ndda/time/step_controller.h>

#include <optional>
#include <vector>

/**
 * From a scene's parameters to the parts that run it: the mesh, the
 * initial state, the contacts' settings, the materials' strengths, the
 * step controller's limits. The Simulator calls these in setup() (and
 * after a crack); nothing here keeps state.
 *
 * @ingroup simulator
 */
namespace ndda
{
  namespace scene
  {
    /**
     * Build @p mesh: from @p triangulation if given (one block per
     * connected group of cells with one material id), else from the mesh
     * file or the blocks and regions of the Geometry section, where every
     * point at which something acts (loads, constraints, bolts, measure
     * points) becomes a mesh vertex. Checks that every cell's material id
     * names a declared material.
     */
    void
    build_mesh(const parameters::Parameters   &parameters,
               const dealii::Triangulation<2> *triangulation,
               CrackableMesh                  &mesh);

    /**
     * Half the height of the scene, or a thousandth of its width for a
     * flat one: the length the DDA step control and the contact distances
     * are fractions of.
     */
    double
    half_height(const CrackableMesh &mesh);

    /**
     * The initial state of every block of @p mesh: its own
     * (Geometry/<block>), or its region's, with the kinematics model of
     * Control/Kinematics where the block names none.
     */
    std::vector<parameters::InitialState>
    initial_states(const parameters::Parameters &parameters,
                   const CrackableMesh          &mesh);

    /**
     * The initial stress and velocity of every block (Geometry/<block>/
     * Initial stress and Initial velocity, or its region's): @p stresses
     * (reinit before) and the nodal @p velocity.
     */
    void
    set_initial_state(const parameters::Parameters &parameters,
                      const CrackableMesh          &mesh,
                      const dealii::DoFHandler<2>  &dof_handler,
                      const dealii::Mapping<2>     &mapping,
                      StressField                  &stresses,
                      dealii::Vector<double>       &velocity);

    /** The distances of contact detection (m). */
    struct ContactDistances
    {
      /// Shi's detection distance: twice the largest displacement a step
      /// may have, so every contact a step can close is a candidate of
      /// that step.
      double detection = 0;
      /// The largest penetration an accepted step may leave.
      double penetration_tolerance = 0;

      template <class Archive>
      void
      serialize(Archive &ar)
      {
        ar &detection &penetration_tolerance;
      }
    };

    /**
     * Initialize @p contacts for the boundary edges of @p mesh: the
     * friction of each edge's material (cells' material ids
     * @p cell_material), stiffnesses, strengths and the law from
     * @p parameters, the dofs through @p dofs. The distances are
     * fractions of @p length, the scene's half height at the start
     * (half_height()). Returns them.
     */
    ContactDistances
    setup_contacts(const parameters::Parameters    &parameters,
                   const CrackableMesh             &mesh,
                   const std::vector<unsigned int> &cell_material,
                   const DofMap                    &dofs,
                   const double                     length,
                   contact::ContactHandler         &contacts);

    /** The step controller's limits (Control and Contact sections). */
    time::StepController::Limits
    step_limits(const parameters::Parameters &parameters);

    /** The open-close iteration's settings (Contact section, and whether
     * the time integrator averages contact forces). */
    contact::OpenCloseSolver::Settings
    open_close_settings(const parameters::Parameters &parameters);
  } // namespace scene
} // namespace ndda

#endif
