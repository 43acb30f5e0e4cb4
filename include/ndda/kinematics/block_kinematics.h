// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_kinematics_block_kinematics_h
#define ndda_kinematics_block_kinematics_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <ndda/base/plugin_registry.h>

#include <memory>
#include <string>
#include <vector>

namespace ndda
{
  /**
   * How a block moves: the space its displacement increments lie in.
   *
   * @ingroup kinematics
   */
  namespace kinematics
  {
    /**
     * Interface of a block kinematics model. A model with n_unknowns() = 0
     * leaves every node of the block free: the block is its finite element
     * mesh ('meshed'). A model with n_unknowns() = k > 0 ties every node of
     * the block to k unknowns of the block: the increment at a node at r
     * is u(r) = B(r) q, with B(r) the 2 x k matrix basis(); ReducedBlocks
     * turns this into AffineConstraints of the block's nodal dofs
     * (doc/design.md, "Block kinematics"). Contacts, loads, constraints,
     * bolts, stresses and output stay those of the nodes, whatever the
     * model.
     *
     * The positions r handed to basis() are relative to the block's
     * centroid, in the block's frame (BlockFrames), and divided by the
     * block's size, so that the unknowns have comparable scales. The space
     * must hold the rigid motions (translations and the linearised
     * rotation), which rotate_blocks() then makes exact; ReducedBlocks
     * checks this.
     *
     * A model is a plugin (NDDA_REGISTER_BLOCK_KINEMATICS): `set
     * Kinematics = name` in `subsection Control` (the scene's default)
     * and in a block's or region's subsection selects it.
     */
    class BlockKinematics
    {
    public:
      virtual ~BlockKinematics() = default;

      /** Declares nothing; a model with entries declares its own. */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Reads nothing; a model with entries overrides this. */
      virtual void
      parse_parameters(dealii::ParameterHandler &prm);

      /** The number k of unknowns of a block; 0: every node is free. */
      virtual unsigned int
      n_unknowns() const = 0;

      /**
       * The rows of B(@p r): the x component of the increment at @p r is
       * @p row_x . q, the y component @p row_y . q (each of size
       * n_unknowns()).
       */
      virtual void
      basis(const dealii::Tensor<1, 2> &r,
            double                     *row_x,
            double                     *row_y) const = 0;

      /**
       * Whether the space maps to itself under any affine change of the
       * positions (then a block's constraint lines do not depend on its
       * orientation): true for the affine model, false for the rigid one
       * (the default).
       */
      virtual bool
      affine_invariant() const
      {
        return false;
      }

      /**
       * Whether the space holds strains (then the block's element
       * matrices act on its increments): true but for the rigid model.
       */
      virtual bool
      strains() const
      {
        return true;
      }

      /** For messages (PluginRegistry). */
      static const char *
      plugin_kind()
      {
        return "block kinematics model";
      }

      static const char *
      plugin_kinds()
      {
        return "block kinematics models";
      }

      static const char *
      selection_entry()
      {
        return "Kinematics";
      }

      /** Keep the built-in models in every program. */
      static void
      link_builtin_plugins();
    };

    /** The registry of block kinematics models. */
    using BlockKinematicsRegistry = PluginRegistry<BlockKinematics>;

    /**
     * Throw an ExcMessage naming @p entry, @p name and the known models if
     * @p name is not a registered model.
     */
    void
    check_name(const std::string &name, const std::string &entry);

    /**
     * The built-in model of a meshed block: no unknowns of its own, every
     * node free (co-rotational finite elements, doc/theory.md).
     */
    class Meshed : public BlockKinematics
    {
    public:
      unsigned int
      n_unknowns() const override
      {
        return 0;
      }

      void
      basis(const dealii::Tensor<1, 2> &, double *, double *) const override
      {}
    };

    /**
     * Shi's DDA block: translation, rotation and a constant strain, six
     * unknowns, u(r) = a + G r with a general 2 x 2 G.
     */
    class Affine : public BlockKinematics
    {
    public:
      unsigned int
      n_unknowns() const override
      {
        return 6;
      }

      void
      basis(const dealii::Tensor<1, 2> &r,
            double                     *row_x,
            double                     *row_y) const override;

      bool
      affine_invariant() const override
      {
        return true;
      }
    };

    /**
     * A rigid block: translation and rotation, three unknowns,
     * u(r) = a + theta (-r_y, r_x).
     */
    class Rigid : public BlockKinematics
    {
    public:
      unsigned int
      n_unknowns() const override
      {
        return 3;
      }

      void
      basis(const dealii::Tensor<1, 2> &r,
            double                     *row_x,
            double                     *row_y) const override;

      bool
      strains() const override
      {
        return false;
      }
    };

  } // namespace kinematics
} // namespace ndda

/**
 * Register the block kinematics model @p classname under @p name with
 * @p description (at the end of its `.cc` file, inside namespace
 * ndda::kinematics).
 */
#define NDDA_REGISTER_BLOCK_KINEMATICS(classname, name, description) \
  NDDA_REGISTER_PLUGIN(ndda::kinematics::BlockKinematics,            \
                       classname,                                    \
                       name,                                         \
                       description)

#endif
