// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_fracture_nonlocal_average_h
#define ndda_fracture_nonlocal_average_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <ndda/fracture/edge_stress.h>

#include <array>
#include <vector>

namespace ndda
{
  namespace fracture
  {
    /**
     * The nonlocal stress of the interior edges of a triangle mesh: at the
     * midpoint x of an edge, the weighted mean of the cell stresses around
     * it,
     *
     *   sigma_bar(x) = sum_c w_c sigma_c / sum_c w_c,
     *   w_c = A_c (1 - r_c^2 / R^2)^2   for r_c = |x_c - x| < R,
     *
     * with A_c the area and x_c the centroid of cell c and R the nonlocal
     * radius (the bell-shaped weight of nonlocal damage models, Bazant and
     * Jirasek 2002). R is a property of the material, not of the mesh: a
     * criterion that reads sigma_bar at a singular crack tip sees a stress
     * that stays finite and converges as the mesh is refined, so crack
     * initiation gets a length scale (doc/fracture.md, "Nonlocal edge
     * stress").
     *
     * Only cells that the edge's own cells reach through a chain of
     * passable edges (interior edges that are not cracks) with every
     * centroid inside the disc enter the mean: the average never reaches
     * across a crack or into another block, and goes around a crack's tip
     * the way the material does. An edge whose two cells both lie
     * outside the disc (R below about a third of the mesh size) gets the
     * plain mean of its two cells, as EdgeStressMethod::cell_average.
     *
     * The weights are computed once per mesh, in setup(), on the vertex
     * positions given there; apply() is then one sparse product per call.
     * A later setup() on the same cells with the same radius and the same
     * vertex positions (after a crack: cells keep their index, and the
     * caller passes the initial geometry) keeps the weights of every edge
     * (named by its two cells) whose disc holds no cell of a passage that
     * was opened or closed since (a cracked edge), and recomputes only the
     * others.
     *
     * @ingroup fracture
     */
    class NonlocalAverage
    {
    public:
      /**
       * Compute the weights of every edge of @p edges.
       *
       * @param edges The edges whose stress is wanted.
       * @param passable Interior edges through which the average may pass
       *   from a cell to its neighbour (a superset of @p edges is usual:
       *   every interior edge of the mesh except closed cracks).
       * @param vertices Vertex positions.
       * @param triangles Triangles as vertex index triples,
       *   counter-clockwise.
       * @param radius The nonlocal radius R (m), positive.
       */
      void
      setup(const std::vector<InteriorEdge>                &edges,
            const std::vector<InteriorEdge>                &passable,
            const std::vector<dealii::Point<2>>            &vertices,
            const std::vector<std::array<unsigned int, 3>> &triangles,
            const double                                    radius);

      /** The nonlocal stress of every edge given to setup(), in order. */
      std::vector<dealii::SymmetricTensor<2, 2>>
      apply(
        const std::vector<dealii::SymmetricTensor<2, 2>> &cell_stresses) const;

      /** The mean number of cells per edge's average (for reports). */
      double
      mean_cells_per_edge() const;

      /** How many edges the last setup() computed (not kept). */
      unsigned int
      n_computed_edges() const
      {
        return n_computed;
      }

    private:
      /// What a later setup() needs to keep rows: the radius, the number
      /// of cells, the row of each edge by its cell pair, and the passable
      /// cell pairs.
      double                                   last_radius  = 0;
      unsigned int                             last_n_cells = 0;
      std::vector<std::array<unsigned int, 2>> row_cells;
      std::vector<std::array<unsigned int, 2>> passable_cells;
      /// The cells' centroids last time: a cell that moved (a vertex
      /// relocated ahead of a crack tip) changes the rows around it.
      std::vector<dealii::Point<2>> last_centroid;
      unsigned int                  n_computed = 0;

      /// Compressed rows: the cells and normalised weights of edge e are
      /// at [offsets[e], offsets[e + 1]).
      std::vector<unsigned int> offsets = {0};
      std::vector<unsigned int> cells;
      std::vector<double>       weights;
    };
  } // namespace fracture
} // namespace ndda

#endif
