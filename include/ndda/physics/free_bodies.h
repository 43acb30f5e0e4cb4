// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_free_bodies_h
#define ndda_physics_free_bodies_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <ndda/geometry/block_mesh.h>
#include <ndda/physics/bolts.h>
#include <ndda/physics/constraints.h>
#include <ndda/physics/dof_map.h>

#include <array>
#include <string>
#include <vector>

namespace ndda
{
  using dealii::Point;
  using dealii::Tensor;

  /**
   * Something that holds the rigid-body motion of a body along one
   * direction at one point: a constrained node (against the ground) or a
   * link between two nodes of two bodies (a bolt, a contact that touches
   * when the run starts).
   *
   * @ingroup physics
   */
  struct RigidSupport
  {
    using index = dealii::types::global_dof_index;

    /// A dof of the node held, and of the node it is linked to
    /// (invalid: the ground).
    std::array<index, 2> dofs = {
      {dealii::numbers::invalid_dof_index, dealii::numbers::invalid_dof_index}};
    /// Where each node is.
    std::array<Point<2>, 2> points;
    /// The direction held: the relative displacement of the nodes along it
    /// is zero.
    Tensor<1, 2> direction;
  };

  /** A rigid-body motion that nothing holds. */
  struct FreeMotion
  {
    /// The blocks that move (indices into the mesh's block names).
    std::vector<unsigned int> blocks;
    /// What the motion is, in words ("translate along (1, 0)",
    /// "rotate about (2, 3)"); empty when the blocks touch nothing held.
    std::string motion;
  };

  /**
   * The rigid-body motions of the bodies of @p mesh that @p supports do
   * not hold: the null space of the stiffness matrix of a problem without
   * inertia (quasi-static analysis).
   *
   * The bodies are the connected pieces of the mesh (a block, or the
   * pieces of a block that its cracks separate). A group of bodies linked
   * by supports that has no support against the ground moves freely as a
   * whole. A group held against the ground is checked for a mechanism: the
   * rank of its support rows, each row the held direction applied to the
   * rigid motions (translation and rotation about the body's centre) of
   * its bodies, is found by a symmetric eigenvalue decomposition of the
   * normal matrix, for groups of at most @p max_bodies bodies (larger
   * groups are taken as held).
   *
   * @ingroup physics
   */
  std::vector<FreeMotion>
  free_rigid_motions(const geometry::BlockMesh       &mesh,
                     const DofMap                    &dof_map,
                     const std::vector<RigidSupport> &supports,
                     const unsigned int               max_bodies = 200);

  /**
   * The supports of a scene on its present geometry: every constrained
   * node (two directions, a roller one), every bolt (along it), and, when
   * @p touch_distance is not negative, every boundary vertex within
   * @p touch_distance of another body's edge (two directions: a contact
   * that touches when a step starts is closed and locked).
   */
  std::vector<RigidSupport>
  rigid_supports(const geometry::BlockMesh &mesh,
                 const DofMap              &dof_map,
                 const Constraints         &constraints,
                 const BoltSprings         &bolts,
                 const double               touch_distance);

  /**
   * Throw a message that names every block free_rigid_motions() finds and
   * its motion, saying that @p analysis needs them held; nothing when
   * every body is held.
   */
  void
  require_held_bodies(const geometry::BlockMesh       &mesh,
                      const DofMap                    &dof_map,
                      const std::vector<RigidSupport> &supports,
                      const std::string               &analysis);
} // namespace ndda

#endif
