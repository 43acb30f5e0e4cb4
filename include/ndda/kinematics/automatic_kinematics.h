// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_kinematics_automatic_kinematics_h
#define ndda_kinematics_automatic_kinematics_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <deal.II/fe/fe_system.h>

#include <deal.II/lac/vector.h>

#include <ndda/fracture/fracture_criterion.h>
#include <ndda/mesh/boundary_edges.h>
#include <ndda/mesh/crackable_mesh.h>
#include <ndda/physics/dof_map.h>

#include <optional>
#include <string>
#include <vector>

namespace ndda
{
  namespace kinematics
  {
    /** The Kinematics value that lets ndda choose and switch the model. */
    inline const std::string automatic_name = "auto";

    /**
     * `subsection Control / subsection Automatic kinematics`: the settings
     * of `Kinematics = auto` (doc/theory.md, "Automatic kinematics").
     */
    struct AutomaticSettings
    {
      /// The model an auto block starts with and returns to (a model
      /// with unknowns: affine or rigid).
      std::string start_model = "affine";
      /// A reduced block is meshed when a stress of it, scaled by
      /// 1 / promotion_fraction, fails the fracture criterion.
      double promotion_fraction = 0.5;
      /// A meshed auto block is unloaded when every stress of it, scaled
      /// by 1 / demotion_fraction, is safe.
      double demotion_fraction = 0.25;
      /// Steps in a row an auto block must be unloaded before it returns
      /// to the start model.
      unsigned int demotion_steps = 100;

      /** Declare the subsection (inside subsection Control). */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** Read and check it (inside subsection Control). */
      void
      parse_parameters(dealii::ParameterHandler &prm);
    };

    /**
     * Whether @p stress, scaled by 1 / @p fraction, fails @p criterion
     * with @p strength on some plane (18 planes 10 degrees apart, the
     * first normal to the larger principal stress): whether the load
     * factor that would break the material at this point is at most
     * 1 / @p fraction. Uses only the criterion's interface, so any
     * registered criterion works.
     */
    bool
    near_failure(const fracture::FractureCriterion   &criterion,
                 const fracture::Strength            &strength,
                 const dealii::SymmetricTensor<2, 2> &stress,
                 const double                         fraction);

    /**
     * The stress at a point of a block's boundary with outward unit
     * normal @p normal where a contact applies the traction @p traction,
     * from the stress @p stress of the cell there: @p stress plus the
     * symmetric tensor D with D n = t - stress n and no part tangential
     * to the boundary (D = e (x) n + n (x) e - (e . n) n (x) n, e = t -
     * stress n). For a block whose stress is constant (affine, rigid) it
     * is the stress a mesh would show next to the contact.
     */
    dealii::SymmetricTensor<2, 2>
    boundary_stress(const dealii::SymmetricTensor<2, 2> &stress,
                    const dealii::Tensor<1, 2>          &normal,
                    const dealii::Tensor<1, 2>          &traction);

    /**
     * The automatic choice of block kinematics (`Kinematics = auto`):
     * an auto block moves with the start model (affine or rigid) while
     * its stresses are far from its strength, is promoted to its mesh
     * when one of them comes within the promotion fraction of the
     * fracture criterion, and is demoted back when it has been unloaded
     * (below the demotion fraction) for a number of steps in a row and no
     * crack touches it.
     *
     * The stresses of a block are the mean stress of each of its cells
     * (of a reduced block: its area-weighted mean, which is its stress)
     * and, on every boundary edge a contact loads, the boundary_stress()
     * of the edge's cell under the edge's traction: the contact forces on
     * the edge's nodes (a vertex's force shared by its two boundary edges)
     * over the edge's length and the thickness. A contact force that
     * varies over a block gives tractions that its constant stress does
     * not carry: this part of the indicator measures how poor a constant
     * strain is, in the units that matter (the strength).
     *
     * @ingroup kinematics
     */
    class AutomaticKinematics
    {
    public:
      /** The state the indicator looks at. */
      struct BlockStresses
      {
        /// The mean stress and the area of every cell.
        const std::vector<dealii::SymmetricTensor<2, 2>> &cell_stress;
        const std::vector<double>                        &cell_area;
        /// The contact forces on the nodes (global components; empty:
        /// none).
        const dealii::Vector<double> &contact_force;
        /// The scene's thickness (m).
        double thickness;
      };

      /**
       * On the present mesh: which blocks are auto (any of their cells
       * in @p cell_auto), the strength of every cell (@p cell_strength;
       * none: its material does not fracture), the boundary edges and the
       * nodes on each (from @p fe and @p dof_map), which blocks hold a
       * crack (a cell marked by mark_cracked(), or a slit in the mesh: a
       * crack face whose twin is a face of the same block). Keeps the
       * counts of switches and the unloaded steps of the blocks that keep
       * their index (a crack appends blocks).
       */
      void
      setup(const CrackableMesh                                  &mesh,
            const dealii::FESystem<2>                            &fe,
            const DofMap                                         &dof_map,
            const std::vector<bool>                              &cell_auto,
            const std::vector<std::optional<fracture::Strength>> &cell_strength,
            const AutomaticSettings                              &settings);

      /** The cells beside edges that cracked (call before setup()). */
      void
      mark_cracked(const std::vector<unsigned int> &cells);

      /** Whether the scene has auto blocks. */
      bool
      enabled() const
      {
        return any_auto;
      }

      /** Whether block @p b is auto. */
      bool
      is_auto(const unsigned int b) const
      {
        return block_auto[b];
      }

      /**
       * The reduced auto blocks to promote: those with a stress within
       * the Promotion fraction of @p criterion in @p state (stressed()),
       * @p meshed: whether each block is meshed now. With @p count, they
       * are counted as promotions (not at the start of a run, where they
       * are the blocks that start meshed).
       */
      std::vector<unsigned int>
      promotions(const CrackableMesh               &mesh,
                 const fracture::FractureCriterion &criterion,
                 const BlockStresses               &state,
                 const std::vector<bool>           &meshed,
                 const bool                         count = true);

      /**
       * After a step: count the unloaded steps in a row (no stress within
       * the Demotion fraction) of every meshed auto block that no crack
       * touches, and return (and count) those that reach Demotion steps.
       */
      std::vector<unsigned int>
      demotions(const CrackableMesh               &mesh,
                const fracture::FractureCriterion &criterion,
                const BlockStresses               &state,
                const std::vector<bool>           &meshed);

      /** Whether an auto block is (@p of_meshed) or is not meshed now. */
      bool
      any_auto_block(const std::vector<bool> &meshed,
                     const bool               of_meshed) const
      {
        for (unsigned int b = 0; b < meshed.size(); ++b)
          if (block_auto[b] && meshed[b] == of_meshed)
            return true;
        return false;
      }

      const AutomaticSettings &
      get_settings() const
      {
        return settings;
      }

      unsigned int
      n_promotions() const
      {
        return n_promoted;
      }

      unsigned int
      n_demotions() const
      {
        return n_demoted;
      }

      /** Write what the blocks went through (cracks, unloaded steps,
       * promotions and demotions) to a checkpoint or read it (Archive),
       * after setup(). */
      template <class Archive>
      void
      serialize(Archive &ar)
      {
        ar &block_cracked &cell_cracked &unloaded_steps &n_promoted &n_demoted;
      }

    private:
      /**
       * Whether a stress of each auto block that is meshed (@p of_meshed)
       * or reduced (not @p of_meshed), scaled by 1 / @p fraction, fails
       * @p criterion (false for the other blocks and for blocks of
       * materials without strength): the mean stress of each cell of a
       * meshed block, the stress of a reduced block (the area-weighted
       * mean of its cells), and on every boundary edge a contact loads
       * the boundary_stress() of the edge's cell (of a reduced block: the
       * block's stress).
       */
      std::vector<bool>
      stressed(const CrackableMesh               &mesh,
               const fracture::FractureCriterion &criterion,
               const BlockStresses               &state,
               const std::vector<bool>           &meshed,
               const bool                         of_meshed,
               const double                       fraction) const;

      /** A boundary edge and its nodes with their shares. */
      struct Edge
      {
        unsigned int              v0, v1, cell, block;
        std::vector<unsigned int> nodes;
        std::vector<double>       share;
      };

      /** The nodes of @p fe on each side of a cell (side i: from local
       * vertex i to i + 1) with their shares, by the base element's
       * support points. */
      static std::vector<std::vector<std::pair<unsigned int, double>>>
      side_nodes(const dealii::FESystem<2> &fe);

      AutomaticSettings settings;
      bool              any_auto = false;
      std::vector<bool> block_auto, block_cracked, cell_cracked;
      std::vector<std::optional<fracture::Strength>> cell_strength;
      std::vector<unsigned int>                      unloaded_steps;
      std::vector<Edge>                              edges;
      const DofMap                                  *dof_map = nullptr;
      unsigned int n_promoted = 0, n_demoted = 0;
    };
  } // namespace kinematics
} // namespace ndda

#endif
