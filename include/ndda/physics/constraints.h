// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_constraints_h
#define ndda_physics_constraints_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ndda/base/expression.h>
#include <ndda/mesh/crackable_mesh.h>
#include <ndda/physics/dof_map.h>
#include <ndda/physics/physics_parameters.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace ndda
{
  namespace kinematics
  {
    class ReducedBlocks;
  }

  /**
   * The nodes of the finite element space, located: the support point and
   * vector component of every dof, the other dof of the same node, and
   * which dofs lie on the boundary. Constraints and bolts find their nodes
   * through it.
   *
   * @ingroup physics
   */
  struct NodeLocator
  {
    using index = dealii::types::global_dof_index;

    /**
     * Locate the nodes of @p dof_map (built from @p dof_handler on
     * @p mesh). Cells are straight triangles (ndda's mapping is linear), so
     * a support point is the affine image of the element's unit support
     * point: one pass over the cells, where deal.II's
     * DoFTools::map_dofs_to_support_points() evaluates the mapping per
     * cell (0.19 s of a 0.21 s locator at 1e5 cells; doc/performance.md).
     */
    NodeLocator(const CrackableMesh         &mesh,
                const dealii::DoFHandler<2> &dof_handler,
                const DofMap                &dof_map);

    /**
     * The x dofs of the nodes at the mesh vertex at @p p (one per block
     * that has a vertex there); throws naming @p entry if @p p is not a
     * vertex of the mesh.
     */
    std::vector<index>
    nodes_at_vertex(const Point<2> &p, const std::string &entry) const;

    /** The x dofs of the boundary nodes on the segment @p segment. */
    std::vector<index>
    boundary_nodes_on(const geometry::Segment &segment) const;

    const CrackableMesh      &mesh;
    std::vector<Point<2>>     support_points;
    std::vector<unsigned int> component;
    std::vector<index>        partner;
    std::vector<bool>         on_boundary;
    double                    tolerance;
  };

  /**
   * Displacement constraints (thesis 3.9): fixed points, rollers at any
   * angle and prescribed displacement or velocity histories, on points and
   * boundary segments. Exact constraints go through deal.II's
   * AffineConstraints (homogeneous; the prescribed values enter as an
   * increment added after the solve); the thesis's penalty springs stay
   * available (Control/Constraint method).
   *
   * @ingroup physics
   */
  class Constraints
  {
  public:
    using index = dealii::types::global_dof_index;

    /** A constrained node: its two dofs and what prescribes them. */
    struct NodeConstraint
    {
      std::array<index, 2>       dofs;
      Point<2>                   position;
      parameters::ConstraintType type;
      /// Unit normal of a roller (the constrained direction).
      Tensor<1, 2> normal;
      /// Index into the history functions (displacement/velocity/roller).
      unsigned int function = dealii::numbers::invalid_unsigned_int;
      std::string  name;
    };

    /**
     * Find the constrained nodes of @p conditions (throws naming the entry
     * for a point that is not a vertex or a segment without boundary
     * nodes) and build the AffineConstraints of the exact method.
     */
    void
    setup(const parameters::BoundaryConditions &conditions,
          const parameters::ConstraintMethod    method,
          const NodeLocator                    &nodes);

    /**
     * Tie the nodes of the reduced blocks (rigid, affine) to their
     * unknowns: their lines replace the lines of their nodes' exact
     * constraints, which @p blocks took into account, and
     * prescribed_increment() fills their nodes (@p blocks is referenced).
     * setup() unties them again.
     */
    void
    tie_blocks(const kinematics::ReducedBlocks &blocks);

    /** Whether @p dof belongs to a reduced block (tie_blocks()). */
    bool
    in_reduced_block(const index dof) const;

    const dealii::AffineConstraints<double> &
    affine_constraints() const
    {
      return constraints;
    }

    const std::vector<NodeConstraint> &
    constrained_nodes() const
    {
      return node_constraints;
    }

    bool
    exact() const
    {
      return method == parameters::ConstraintMethod::exact;
    }

    /**
     * The increment that brings every constrained node from its present
     * displacement (@p displacement) to its prescribed value at
     * @p t0 + @p dt (so that no error accumulates); zero elsewhere.
     */
    void
    prescribed_increment(const double          t0,
                         const double          dt,
                         const Vector<double> &displacement,
                         Vector<double>       &increment) const;

    /**
     * Evaluate every prescribed value's expression, every component, at
     * the nodes it constrains and at each of @p times: throws naming the
     * entry on the first value that is not finite.
     */
    void
    check_expressions(const std::vector<double> &times);

    /** Penalty method: add the springs of stiffness @p k to @p matrix. */
    void
    add_penalty_springs(const double                  k,
                        dealii::SparseMatrix<double> &matrix) const;

    /**
     * Penalty method: add the springs' forces k * prescribed to @p rhs.
     */
    void
    add_penalty_forces(const double          k,
                       const Vector<double> &prescribed,
                       Vector<double>       &rhs) const;

  private:
    /** The AffineConstraints of the exact constraints of the nodes of
     * meshed blocks and the lines of the reduced blocks. */
    void
    build_lines();

    /** The increment (global components) that brings the node of @p nc
     * to its prescribed value at @p t0 + @p dt. */
    Tensor<1, 2>
    target_increment(const NodeConstraint &nc,
                     const double          t0,
                     const double          dt,
                     const Vector<double> &displacement) const;

    parameters::ConstraintMethod method = parameters::ConstraintMethod::exact;
    const kinematics::ReducedBlocks         *reduced = nullptr;
    dealii::AffineConstraints<double>        constraints;
    std::vector<NodeConstraint>              node_constraints;
    std::vector<std::unique_ptr<Expression>> functions;
  };
} // namespace ndda

#endif
