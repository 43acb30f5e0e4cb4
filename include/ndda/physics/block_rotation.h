// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_block_rotation_h
#define ndda_physics_block_rotation_h

#include <deal.II/base/array_view.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ndda/mesh/crackable_mesh.h>
#include <ndda/physics/bolts.h>
#include <ndda/physics/constraints.h>
#include <ndda/physics/dof_map.h>
#include <ndda/physics/element_cache.h>
#include <ndda/physics/stress_field.h>

#include <utility>
#include <vector>

namespace ndda
{
  class BlockFrames;

  /**
   * What the finite rotation of the blocks (rotate_blocks(),
   * block_rotations()) needs of the nodes and does not change from step
   * to step: the block of every node (invalid for a node of no cell),
   * which nodes are constrained and how many of each block are, and every
   * node's mass (the row sum of the mass matrix: 1^T M v is the momentum
   * for the consistent mass too). Made again whenever the mass matrix is
   * (Discretization::assemble()), which follows every change of the mesh
   * or the constraints.
   *
   * @ingroup physics
   */
  struct BlockNodes
  {
    std::vector<unsigned int> block;
    std::vector<bool>         constrained;
    std::vector<unsigned int> n_constrained;
    std::vector<double>       mass;

    /** Of @p mesh, @p dof_map, @p constraints and @p mass_matrix. */
    void
    setup(const CrackableMesh        &mesh,
          const DofMap               &dof_map,
          const Constraints          &constraints,
          const SparseMatrix<double> &mass_matrix);
  };

  /**
   * The finite rotation of every block over a step, as DDA post-corrects
   * its block rotation (doc/theory.md, "Finite rotation"). The linear
   * solve of a step gives an increment @p d whose rigid rotation is
   * linearised: d = t + theta J r + w (r relative to the block's centre,
   * J the quarter turn, w the deformation), which moves points along the
   * tangent and would enlarge a spinning block by theta^2 a step. For each
   * block, with theta the area-weighted mean rotation of its cells in
   * @p d (from @p stresses, on the present geometry):
   *
   * - @p d: theta J r is replaced by the exact (R(theta) - I) r, so that a
   *   rigid rotation of any size moves every point on its circle;
   * - @p velocity and @p inertia_force (the integrator's end state, from
   *   the linear d) turn by R(theta) relative to the centre: the block's
   *   motion turns with it (the centripetal acceleration of the rigid
   *   rotation); so does @p acceleration, the acceleration vector of a
   *   scheme that keeps one (generalized-α), if given;
   * - @p velocity takes the Coriolis term that the turn leaves out,
   *   -(theta / dt) J R w (@p dt the step), w the deformation in d,
   *   less its part along the radial field r, which would change the
   *   block's spin: without it two strain modes of the same frequency (a
   *   square's two shears) flutter (doc/theory.md, "Spin and strain").
   *
   * The centre is the block's centre of mass (the nodal masses of
   * @p nodes), which the correction does not move, so momentum is kept;
   * for a block with one constrained node it is that node, so that a
   * pinned block turns about its pin exactly. A block with two or more
   * constrained nodes is left as solved: its constraints hold its
   * rotation small, and a correction would move its constrained nodes off
   * their prescribed values.
   *
   * @p solved_rotation is block_rotations() of @p d if the caller has
   * it, else empty. Returns the rotation theta of every block (0 for those
   * left).
   *
   * @ingroup physics
   */
  std::vector<double>
  rotate_blocks(const CrackableMesh       &mesh,
                const DofMap              &dof_map,
                const StressField         &stresses,
                const BlockNodes          &nodes,
                const std::vector<double> &solved_rotation,
                const double               dt,
                Vector<double>            &d,
                Vector<double>            &velocity,
                Vector<double>            &inertia_force,
                Vector<double>            *acceleration = nullptr);


  /**
   * The rotation theta of every block in the increment @p d: the
   * area-weighted mean rotation of its cells (from @p stresses, on the
   * present geometry); 0 for a block with two or more constrained nodes
   * (@p nodes), as rotate_blocks() leaves it.
   */
  std::vector<double>
  block_rotations(const CrackableMesh  &mesh,
                  const DofMap         &dof_map,
                  const StressField    &stresses,
                  const BlockNodes     &nodes,
                  const Vector<double> &d);


  /**
   * Add to a step's right-hand side @p rhs the stiffness force that the
   * solve of increment @p d gave its blocks' rotations @p rotation
   * (block_rotations(); 0: leave the block) and should not have
   * (doc/theory.md, "Spin and strain"). The element matrices, kept in
   * the blocks' @p frames, take the force Q K Q^T d; the step's end has
   * the stresses turned by R(theta) and strained by the deformation
   * w = d - theta J x alone, whose force on the turned block is
   * Q K Q^T R^T w. So the solve counted z = Q K Q^T (d - R^T w) too much;
   * solved again with rhs + z, the step is consistent to O(theta^2).
   */
  void
  add_rotation_correction(const CrackableMesh       &mesh,
                          const DofMap              &dof_map,
                          const ElementCache<2>     &element_cache,
                          const BlockFrames         &frames,
                          const std::vector<double> &rotation,
                          const Vector<double>      &d,
                          Vector<double>            &rhs);


  /**
   * A frame per block that turns with it, in which the linear system of a
   * step is solved (doc/theory.md, "Finite rotation"). With Q the
   * rotation of every node by its block's frame angle, the stiffness of a
   * block that turned rigidly by its frame's angle since its element
   * matrices were built is Q K Q^T, K the matrices as built (turned to
   * the frame at the time: ElementCache keeps them so), and the mass
   * matrix is Q M Q^T = M. So the system (A + S) d = b is solved as
   * (A + Q^T S Q) (Q^T d) = Q^T b with A assembled once: a turning block
   * changes neither its element matrices nor the factorization. The
   * contact springs S are turned block by block as they are assembled
   * (turn()).
   *
   * A block with a roller or a bolt anchor keeps the global frame (angle
   * 0): rollers and bolt springs act in global directions. Constraints of
   * both components of a node (fixed, displacement, velocity) hold in any
   * frame (d = g is Q^T d = Q^T g), exact or penalty (k I = Q^T k I Q).
   * Angles are kept per cell (a crack keeps cell indices; the two sides
   * of a cracked block start with its angle).
   *
   * @ingroup physics
   */
  class BlockFrames
  {
  public:
    using index = types::global_dof_index;

    /** Zero angles for @p n_cells cells. */
    void
    reinit(const unsigned int n_cells);

    /**
     * After a refinement (CrackableMesh::refine()): every cell takes the
     * angle of the cell it lies in, @p cell_origin[c] (cells of one block
     * share their block's angle).
     */
    void
    carry_to_cells(const std::vector<unsigned int> &cell_origin);

    /**
     * Which blocks keep the global frame (those with a roller of
     * @p constraints or an anchor of @p bolts), and the frame of every
     * node of @p dof_map. Call after the dofs, constraints or bolts
     * change.
     */
    void
    setup(const CrackableMesh &mesh,
          const DofMap        &dof_map,
          const Constraints   &constraints,
          const BoltSprings   &bolts);

    /** Turn the frame of every free block by @p block_rotation. */
    void
    turn(const std::vector<double> &block_rotation);

    /** The frame angle of every cell (rad). */
    const std::vector<double> &
    cell_angles() const
    {
      return angle;
    }

    /** The cos and sin of the frame of node @p node (of the DofMap). */
    std::pair<double, double>
    node_rotation(const unsigned int node) const
    {
      return {node_cos[node], node_sin[node]};
    }

    /** Whether block @p block keeps the global frame. */
    bool
    keeps_global_frame(const unsigned int block) const
    {
      return global_frame[block];
    }

    /** Whether any frame is turned (else every transformation is the
     * identity and is skipped). */
    bool
    turned() const
    {
      return any_turned;
    }

    /** v <- Q^T v: global components to frame components. */
    void
    to_frame(Vector<double> &v) const;

    /** v <- Q v: frame components to global components. */
    void
    to_global(Vector<double> &v) const;

    /**
     * @p k <- Q^T @p k Q for a dense block @p k on the dofs @p dofs (both
     * dofs of each node among them): a spring block assembled in global
     * components, turned into the frames of its nodes.
     */
    void
    turn(const ArrayView<const index> &dofs, FullMatrix<double> &k) const;

    /** Write the cells' frame angles to a checkpoint or read them
     * (Archive); setup() follows. */
    template <class Archive>
    void
    serialize(Archive &ar)
    {
      ar &angle;
    }

  private:
    /** Refresh the nodes' cos and sin from the cells' angles. */
    void
    update_nodes();

    const DofMap             *dof_map = nullptr;
    std::vector<double>       angle;
    std::vector<bool>         global_frame;
    std::vector<unsigned int> cell_block;
    /// cos and sin of the frame of every node.
    std::vector<double> node_cos, node_sin;
    bool                any_turned = false;
  };
} // namespace ndda

#endif
