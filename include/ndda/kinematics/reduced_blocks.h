// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_kinematics_reduced_blocks_h
#define ndda_kinematics_reduced_blocks_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ndda/kinematics/block_kinematics.h>
#include <ndda/mesh/crackable_mesh.h>
#include <ndda/physics/block_rotation.h>
#include <ndda/physics/constraints.h>
#include <ndda/physics/dof_map.h>

#include <string>
#include <vector>

namespace ndda
{
  namespace kinematics
  {
    /**
     * The blocks of a scene that move with fewer unknowns than their mesh
     * has (rigid, affine, or any BlockKinematics with n_unknowns() > 0),
     * as constraints of their nodal dofs (doc/design.md, "Block
     * kinematics").
     *
     * For such a block with basis B (all its nodes' rows, 2n x k, in its
     * frame), the increment is d = B q. Its exact constraints (fixed,
     * displacement, velocity, roller; Constraints) are rows C d = g, that
     * is C B q = g: q = P g + N z, with P the pseudo-inverse of C B and N
     * a basis of its null space (m columns). So d = B P g + (B N) z. The
     * block's free unknowns z are represented by m of its dofs, the
     * masters, chosen by pivoting on the rows of B N; every other dof of
     * the block becomes an AffineConstraints line in terms of the masters
     * (homogeneous), and B P g is the block's part of the step's
     * prescribed increment (prescribed_increment()). The lines are in the
     * blocks' frames, like the linear system: there the positions of a
     * rigid block do not change, and an affine block's lines (the
     * coordinates of its nodes relative to the masters) do not change
     * under any affine motion, so the lines and the factorization stay as
     * long as the blocks turn in their frames. A rigid block in the
     * global frame (a roller or a bolt anchor) that turns needs new
     * coefficients (stale(), refresh()).
     *
     * With penalty constraints (Constraint method = penalty) the
     * constraints are springs; C is empty and every block keeps all k
     * unknowns.
     *
     * @ingroup kinematics
     */
    class ReducedBlocks
    {
    public:
      using index = dealii::types::global_dof_index;

      /**
       * The reduced blocks among the blocks of @p mesh: block b has the
       * model @p block_model[b] (nullptr or n_unknowns() = 0: meshed).
       * Node positions are those of the present geometry (in the frames
       * of @p frames, set up before); @p constraints gives the exact
       * constraints of the nodes. Throws if a model's space does not hold
       * the rigid motions of a block.
       */
      void
      setup(const CrackableMesh                        &mesh,
            const DofMap                               &dof_map,
            const BlockFrames                          &frames,
            const std::vector<const BlockKinematics *> &block_model,
            const Constraints                          &constraints);

      /** Whether there is any reduced block. */
      bool
      empty() const
      {
        return blocks.empty();
      }

      /** Whether the node of @p dof belongs to a reduced block. */
      bool
      is_reduced(const index dof) const
      {
        return !node_block.empty() &&
               node_block[dof_map->dof_to_node[dof]] != invalid;
      }

      /**
       * Add a line for every dof of a reduced block that is not a master
       * to @p lines (not closed).
       */
      void
      add_lines(dealii::AffineConstraints<double> &lines) const;

      /**
       * Fill the dofs of every reduced block that has exact constraints
       * with its part B P g of the prescribed increment (global
       * components), from @p target, the increment each constrained node
       * of Constraints::constrained_nodes() must take (global
       * components).
       */
      void
      prescribed_increment(const std::vector<dealii::Tensor<1, 2>> &target,
                           dealii::Vector<double> &increment) const;

      /**
       * Replace @p velocity on every reduced block by its projection on
       * the block's space that keeps momentum and angular momentum (the
       * mass-weighted least-squares fit, B (B^T M B)^-1 B^T M v); with
       * @p inertia_force, replace M a there by M B (B^T M B)^-1 B^T M a,
       * the inertia force of the fitted acceleration. Only the blocks of
       * the mesh blocks @p mesh_blocks selects, if not empty.
       */
      void
      project(const dealii::SparseMatrix<double> &mass,
              dealii::Vector<double>             &velocity,
              dealii::Vector<double>             *inertia_force = nullptr,
              const std::vector<bool>            &mesh_blocks   = {}) const;

      /**
       * Whether a block whose lines depend on its orientation in the
       * global frame (a rigid block with a roller or a bolt anchor) turned
       * by @p block_rotation: then setup() again on the present geometry.
       */
      bool
      stale(const std::vector<double> &block_rotation) const;

      /** The number of reduced blocks. */
      unsigned int
      n_reduced() const
      {
        return blocks.size();
      }

      /** The number of reduced blocks of each model (by pointer). */
      unsigned int
      n_blocks_of(const BlockKinematics *model) const;

    private:
      static constexpr unsigned int invalid =
        dealii::numbers::invalid_unsigned_int;

      /** One reduced block. */
      struct Block
      {
        unsigned int           mesh_block;
        const BlockKinematics *model;
        /// Its nodes; its dofs are their (x, y) dofs, rows 2i and 2i + 1.
        std::vector<unsigned int> nodes;
        /// B, 2n x k, in the block's frame at the setup.
        dealii::FullMatrix<double> basis;
        /// The rows of C in the block's frame (both components of a
        /// node, or a roller's normal), and the constrained node of each
        /// (an index into Constraints::constrained_nodes()).
        std::vector<dealii::Tensor<1, 2>> rows;
        std::vector<unsigned int>         row_constraint;
        /// The constrained node of each row, among the block's nodes.
        std::vector<unsigned int> row_node;
        /// P (k x rows), the pseudo-inverse of C B.
        dealii::FullMatrix<double> particular;
        /// The masters (rows of B N) and the lines: coefficient of each
        /// master for every row (2n x m).
        std::vector<unsigned int>  masters;
        dealii::FullMatrix<double> coefficients;
        /// Whether its frame is the global one.
        bool global_frame = false;
      };

      /** B of @p block (called @p name) on the nodes' @p position;
       * throws if it does not hold the rigid motions. */
      void
      build_basis(Block                               &block,
                  const std::vector<dealii::Point<2>> &position,
                  const std::string                   &name) const;

      /** The rows C of the exact @p constraints of the reduced blocks'
       * nodes, in their frames. */
      void
      add_constraint_rows(const Constraints &constraints);

      /** B N, the pseudo-inverse P and the lines of @p block. */
      void
      build_lines(Block &block) const;

      const DofMap      *dof_map = nullptr;
      const BlockFrames *frames  = nullptr;
      std::vector<Block> blocks;
      /// The reduced block of every node (invalid: meshed), and the
      /// node's index among the block's nodes.
      std::vector<unsigned int> node_block, node_local;
    };
  } // namespace kinematics
} // namespace ndda

#endif
