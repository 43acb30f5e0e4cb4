// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_scene_discretization_h
#define ndda_scene_discretization_h

#include <deal.II/base/quadrature.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>

#include <deal.II/lac/vector.h>

#include <ndda/base/section_timer.h>
#include <ndda/kinematics/block_kinematics.h>
#include <ndda/kinematics/reduced_blocks.h>
#include <ndda/mesh/crackable_mesh.h>
#include <ndda/parallel/owned_cells.h>
#include <ndda/parameters/parameters.h>
#include <ndda/physics/block_rotation.h>
#include <ndda/physics/bolts.h>
#include <ndda/physics/constraints.h>
#include <ndda/physics/dof_map.h>
#include <ndda/physics/element_cache.h>
#include <ndda/physics/finite_element.h>
#include <ndda/physics/linear_system.h>
#include <ndda/physics/loads.h>
#include <ndda/physics/stress_field.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace ndda
{
  namespace scene
  {
    /**
     * The finite element discretization of a scene's blocks, set up from
     * its parameters on its mesh: the element (by name, with its
     * quadratures, mapping and output subdivisions), the dofs and their
     * index arrays, the material of every cell, the element matrices, the
     * constraints, bolts and loads, and the linear system. It holds no
     * state of the motion: the Simulator owns displacement, velocities and
     * stresses, and hands the displacement in where bolts need it.
     *
     * Its parts are public: the time step reads them all.
     *
     * @ingroup simulator
     */
    class Discretization
    {
    public:
      /** On @p mesh (referenced); the linear system is timed in @p timer. */
      Discretization(CrackableMesh &mesh, SectionTimer &timer);

      ~Discretization();

      /**
       * The element of Control/Finite element, its dofs and index arrays,
       * the material id of every cell, a new linear solver; with
       * @p element_matrices also every cell's element matrices on the
       * present geometry.
       */
      void
      setup_dofs(const parameters::Parameters &parameters,
                 const bool                    element_matrices);

      /**
       * Constraints and bolts, found by position on the present geometry
       * (the scene's initial geometry: CrackableMesh::on_initial_geometry()).
       */
      void
      setup_constraints(const parameters::Parameters &parameters);

      /**
       * The kinematics model of every cell, from its block's (or region's)
       * Kinematics entry or Control/Kinematics. Once, after the mesh is
       * built: a crack keeps the cells and their models.
       */
      void
      setup_kinematics(const parameters::Parameters &parameters);

      /**
       * The model called @p name, created on first use (it stays in
       * models).
       */
      const kinematics::BlockKinematics *
      model(const std::string &name);

      /**
       * Give every cell of the mesh blocks @p blocks the model
       * @p block_model; setup_system() then sets the system up for it.
       */
      void
      set_block_models(const std::vector<unsigned int>   &blocks,
                       const kinematics::BlockKinematics *block_model);

      /** The number of blocks of each model of models, in its order. */
      std::vector<unsigned int>
      blocks_per_model() const;

      /** Whether every model in use is a meshed one (no block is reduced
       * now or later). */
      bool
      all_meshed() const
      {
        for (const auto &m : models)
          if (m.second->n_unknowns() > 0)
            return false;
        return true;
      }

      /** Whether each block is meshed now. */
      std::vector<bool>
      meshed_blocks() const;

      /** Whether each block's model holds strains now (all but rigid
       * blocks: BlockKinematics::strains()), as of setup_system(). */
      const std::vector<bool> &
      straining_blocks() const
      {
        return straining;
      }

      /** Whether each block is reduced now (rigid, affine): not
       * meshed_blocks(). */
      std::vector<bool>
      reduced_mesh_blocks() const;

      /**
       * After setup_constraints(), on the present geometry: the blocks'
       * frames, the reduced blocks (rigid, affine) tied to their unknowns,
       * and the sparsity pattern of the linear system.
       */
      void
      setup_system(const parameters::Parameters &parameters);

      /** Loads: points and loaded faces on the present geometry. */
      void
      setup_loads(const parameters::Parameters &parameters);

      /**
       * After setup_loads(): evaluate every expression of the loads and
       * prescribed values where the run uses it, at 65 times from 0 to
       * Control/End time, and throw naming the entry on the first value
       * that is not finite (so that --validate finds a history that
       * turns NaN late in the run).
       */
      void
      check_expressions(const parameters::Parameters &parameters);

      /**
       * With @p only_moved_cells, recompute the element matrices of the
       * cells that moved beyond Control/Matrix update tolerance (of every
       * cell if the constitutive law's tangent depends on the stress: then
       * from @p stresses, and on the first step too); without, keep those
       * setup_dofs() computed. Then
       * the global matrices (with the bolt springs on @p displacement),
       * gravity and, with @p only_moved_cells, the loaded faces. Returns
       * false if no cell needed it (nothing was done), unless
       * @p always_assemble (after a crack: the dofs are new, though no cell
       * changed its shape).
       */
      bool
      update_matrices(const parameters::Parameters &parameters,
                      const bool                    only_moved_cells,
                      const Vector<double>         &displacement,
                      const StressField            &stresses,
                      const bool                    always_assemble = false);

      /**
       * Assemble K, M and C (bolt springs on @p displacement); with
       * @p changed_cells, only the rows that these cells' new element
       * matrices change (LinearSystem::assemble()).
       */
      void
      assemble(const Vector<double>            &displacement,
               const std::vector<unsigned int> *changed_cells = nullptr);

      /**
       * The external force at time @p t on the present geometry: loads and
       * the bolts' pretension (on @p displacement).
       */
      void
      external_force(const double          t,
                     const Vector<double> &displacement,
                     Vector<double>       &force) const;

      /** Whether each cell belongs to a meshed block (the cells that may
       * crack). */
      std::vector<bool>
      meshed_cells() const
      {
        std::vector<bool> meshed(cell_model.size());
        for (unsigned int c = 0; c < meshed.size(); ++c)
          meshed[c] = cell_model[c]->n_unknowns() == 0;
        return meshed;
      }

      /**
       * One line for the log: blocks, cells, vertices, degrees of freedom
       * (and the element), constrained nodes.
       */
      std::string
      summary() const;

      /**
       * The inertia force M a0 at the start of a run, for an integrator
       * that needs the initial acceleration: M a0 = f_ext(t) - f_int, with
       * zero acceleration at constrained dofs.
       */
      Vector<double>
      initial_inertia_force(const double          t,
                            const Vector<double> &displacement,
                            const Vector<double> &internal_force) const;

      CrackableMesh                 &mesh;
      std::unique_ptr<FESystem<2>>   fe;
      LinearMapping                  mapping;
      std::unique_ptr<Quadrature<1>> face_quadrature;
      unsigned int                   n_output_subdivisions = 1;
      DoFHandler<2>                  dof_handler;
      ElementCache<2>                element_cache;
      /// The dofs as index arrays, for the loops of the time step.
      DofMap dof_map;
      /// Material id of every active cell.
      std::vector<unsigned int> cell_material;
      Constraints               constraints;
      /// Stiffness of the penalty springs of Constraint method = penalty.
      double        penalty_stiffness = 0;
      LinearSystem  linear_system;
      ExternalLoads loads;
      BoltSprings   bolts;
      /// The frame of every block, which turns with it; the element
      /// matrices and the linear solve are in these frames.
      BlockFrames frames;
      /// The block kinematics models in use, by name.
      std::vector<
        std::pair<std::string, std::unique_ptr<kinematics::BlockKinematics>>>
        models;
      /// The model of every cell (of its block).
      std::vector<const kinematics::BlockKinematics *> cell_model;
      /// Whether every cell's block has Kinematics = auto.
      std::vector<bool> cell_auto;
      /// The blocks that move with fewer unknowns than their mesh has.
      kinematics::ReducedBlocks reduced_blocks;
      /// What the blocks' finite rotation needs of the nodes, made with
      /// the mass matrix (assemble()).
      BlockNodes block_nodes;
      /// The processes that solve the linear systems together (the
      /// Simulator's; one process unless it was given more).
      MPI_Comm communicator = MPI_COMM_SELF;
      /// The active cells split among those processes for the per-cell
      /// work (setup_dofs()).
      OwnedCells owned_cells;

    private:
      SectionTimer &timer;
      /// straining_blocks(), made by setup_system().
      std::vector<bool> straining;
    };
  } // namespace scene
} // namespace ndda

#endif
