// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_physics_bolts_h
#define ndda_physics_bolts_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <ndda/physics/constraints.h>
#include <ndda/physics/physics_parameters.h>

#include <array>
#include <utility>
#include <vector>

namespace ndda
{
  /**
   * Bolts (thesis 3.6): axial springs between two anchor nodes, which may
   * lie in different blocks, with a pretension. The spring acts along the
   * present direction between the anchors; its force accumulates k times
   * the elongation of each step.
   *
   * @ingroup physics
   */
  class BoltSprings
  {
  public:
    using index = dealii::types::global_dof_index;

    /**
     * Find the anchor nodes of @p bolts (throws naming the entry for an
     * end point that is not a mesh vertex). Forces start at zero.
     */
    void
    setup(const parameters::Bolts &bolts, const NodeLocator &nodes);

    /** Add the couplings of the anchors' dofs to @p dsp. */
    void
    add_couplings(dealii::DynamicSparsityPattern &dsp) const;

    /**
     * Add k L L^T of every bolt to @p matrix, with L the unit vector
     * between the anchors displaced by @p displacement.
     */
    void
    add_stiffness(const Vector<double>         &displacement,
                  dealii::SparseMatrix<double> &matrix) const;

    /** Add the spring forces (pulling the anchors together) to @p force. */
    void
    add_internal_force(const Vector<double> &displacement,
                       Vector<double>       &force) const;

    /** Add the pretension forces to @p force (an external load). */
    void
    add_pretension(const Vector<double> &displacement,
                   Vector<double>       &force) const;

    /**
     * Accumulate the spring forces of a step with increment @p d, from the
     * displacement @p displacement at its start.
     */
    void
    update(const Vector<double> &displacement, const Vector<double> &d);

    /** The axial force of every bolt (N, tension positive). */
    std::vector<double>
    axial_forces() const;

    /** Set the axial forces (after a crack has rebuilt the bolts). */
    void
    set_axial_forces(const std::vector<double> &forces);

    bool
    empty() const
    {
      return bolts.empty();
    }

    /** The x dof of every anchor node. */
    std::vector<index>
    anchor_dofs() const
    {
      std::vector<index> dofs;
      for (const auto &bolt : bolts)
        dofs.insert(dofs.end(), {bolt.dofs[0], bolt.dofs[2]});
      return dofs;
    }

    /** Write the bolts (anchors, forces) to a checkpoint or read them
     * (Archive). */
    template <class Archive>
    void
    serialize(Archive &ar)
    {
      ar &bolts;
    }

  private:
    struct Spring
    {
      std::array<index, 4> dofs;
      Point<2>             first, second;
      double               stiffness;
      double               pretension;
      /// Spring force k * elongation, accumulated (N, tension positive).
      double axial_force = 0;

      template <class Archive>
      void
      serialize(Archive &ar)
      {
        ar &dofs &first &second &stiffness &pretension &axial_force;
      }
    };

    /** The unit vector from the second anchor to the first, displaced. */
    static Tensor<1, 2>
    direction(const Spring &bolt, const Vector<double> &displacement);

    std::vector<Spring> bolts;
  };
} // namespace ndda

#endif
