// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_fracture_edge_failure_check_h
#define ndda_fracture_edge_failure_check_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <ndda/fracture/edge_stress.h>
#include <ndda/fracture/fracture_criterion.h>
#include <ndda/fracture/nonlocal_average.h>
#include <ndda/mesh/crackable_mesh.h>

#include <array>
#include <optional>
#include <vector>

namespace ndda
{
  namespace fracture
  {
    /**
     * The earliest edge failure of a run: its time (s), the edge's
     * midpoint at the end of the step, and the mode (none before any edge
     * fails).
     */
    struct FailureRecord
    {
      FailureMode      mode = FailureMode::none;
      double           time = 0;
      dealii::Point<2> location;

      template <class Archive>
      void
      serialize(Archive &ar)
      {
        ar &mode &time &location;
      }
    };

    /**
     * One side of a step for the fracture check: the vertex positions of
     * the block mesh and the area-weighted mean stress of every cell.
     */
    struct BlockState
    {
      const std::vector<dealii::Point<2>>              &vertices;
      const std::vector<dealii::SymmetricTensor<2, 2>> &cell_stress;
    };

    /**
     * The fracture check of a step (thesis 5.3): the interior edges of the
     * blocks that may fracture, their strengths, and which of them fail
     * between the step's start and its trial end, and when. Detection
     * only: CrackableMesh::crack() splits the edges.
     *
     * @ingroup fracture
     */
    class EdgeFailureCheck
    {
    public:
      /**
       * Find the interior edges of @p mesh between two cells whose
       * materials fracture (@p material_strength of the cell's material id,
       * from @p cell_material, is set), except cracks that are closed at
       * both tips, and except edges of cells that @p may_crack excludes
       * (if not empty: the cells of blocks that are not meshed); the
       * strength of an edge is the weaker of its two cells'. A positive
       * @p nonlocal_radius computes the weights of the nonlocal average
       * (EdgeStressMethod::nonlocal_average) on the initial geometry,
       * keeping the rows far from any crack made since the last call.
       */
      void
      setup(const CrackableMesh                        &mesh,
            const std::vector<unsigned int>            &cell_material,
            const std::vector<std::optional<Strength>> &material_strength,
            const std::vector<bool>                    &may_crack       = {},
            const double                                nonlocal_radius = 0.);

      /** Whether some material of the scene fractures. */
      bool
      enabled() const
      {
        return any_material_fractures;
      }

      /** The edges that may fail (none: nothing to check). */
      const std::vector<InteriorEdge> &
      get_edges() const
      {
        return edges;
      }

      /**
       * Check every edge with @p parameters' criterion from @p start to
       * @p end, the two ends of a step of length @p dt that starts at
       * @p time, on the triangles of the block mesh with areas
       * @p cell_area. Returns the edges (vertex pairs) that crack now: the
       * earliest failing ones, within the crack window. Counts the failing
       * edges, and the first check that finds any keeps the earliest
       * failure of the run.
       */
      std::vector<std::array<unsigned int, 2>>
      check(const parameters::Fracture                     &parameters,
            const std::vector<std::array<unsigned int, 3>> &triangles,
            const std::vector<double>                      &cell_area,
            const BlockState                               &start,
            const BlockState                               &end,
            const double                                    time,
            const double                                    dt);

      /** Edges that failed in the last check. */
      unsigned int
      n_failing_edges() const
      {
        return n_failing;
      }

      const FailureRecord &
      first_failure() const
      {
        return first;
      }

      /** Write the first failure and the last check's count to a
       * checkpoint or read them (Archive); the edges come from setup(). */
      template <class Archive>
      void
      serialize(Archive &ar)
      {
        ar &first &n_failing;
      }

    private:
      bool                      any_material_fractures = false;
      std::vector<InteriorEdge> edges;
      std::vector<Strength>     strength;
      /// Weights of the nonlocal edge stress (set up for a positive radius).
      NonlocalAverage nonlocal;
      bool            has_nonlocal = false;
      FailureRecord   first;
      unsigned int    n_failing = 0;
    };
  } // namespace fracture
} // namespace ndda

#endif
