// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_fracture_edge_stress_h
#define ndda_fracture_edge_stress_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <array>
#include <vector>

namespace ndda
{
  /**
   * Fracture along mesh edges (thesis chapter 5): the stress on the
   * interior edges of the blocks, the fracture criteria that decide when in
   * a step an edge fails, and their parameters. The derivations are in
   * doc/fracture.md.
   *
   * Everything here works on plain arrays (vertex positions, triangles as
   * vertex index triples, one stress and one area per cell), as in
   * geometry::BlockMesh, so that it does not depend on how the simulator
   * stores its mesh. Stresses are in Pa, tension positive, as everywhere in
   * ndda.
   *
   * @ingroup fracture
   */
  namespace fracture
  {
    using dealii::Point;
    using dealii::SymmetricTensor;

    /**
     * An edge shared by two triangles (a "grid line" of the thesis). Only
     * such edges can crack: a boundary edge of a block, and the two faces of
     * a crack, belong to one triangle each.
     *
     * Orientation: `vertices[0] < vertices[1]`, and `cells[0]` is the
     * triangle that runs from `vertices[0]` to `vertices[1]` in its
     * counter-clockwise order, i.e. the triangle on the left of that
     * direction; `cells[1]` is on the right.
     */
    struct InteriorEdge
    {
      std::array<unsigned int, 2> vertices;
      std::array<unsigned int, 2> cells;
    };

    /**
     * The stress on an edge: the stress tensor assigned to the edge, and
     * the normal and shear stress it gives on the edge.
     */
    struct EdgeState
    {
      /// The edge's stress tensor (Pa, tension positive).
      SymmetricTensor<2, 2> stress;
      /// Normal stress n.sigma.n on the edge (Pa, tension positive).
      double normal_stress = 0.;
      /// Shear stress t.sigma.n on the edge (Pa). Its sign is that of the
      /// shear component in the frame (n, t); it does not change when the
      /// edge's ends are swapped (t and n both flip). Criteria use |tau|.
      double shear_stress = 0.;
    };

    /** How an edge's stress tensor is obtained from the cell stresses. */
    enum class EdgeStressMethod
    {
      /// Mean of the stresses of the two cells beside the edge (thesis
      /// 5.21).
      cell_average,
      /// Mean of the nodal stresses of the edge's two vertices, a nodal
      /// stress being the area-weighted mean of the cells around the vertex
      /// (thesis 8.2 recommends nodal stresses for smoother crack paths;
      /// the thesis does not define them, see doc/fracture.md).
      nodal_average,
      /// Weighted mean of the cell stresses within a material radius of
      /// the edge's midpoint (NonlocalAverage): a length scale for crack
      /// initiation (doc/fracture.md).
      nonlocal_average
    };

    /**
     * Normal and shear stress of the stress tensor @p stress on the edge
     * from @p a to @p b (thesis 5.22, 5.23, see doc/fracture.md for the
     * relation of the thesis's angle and signs to these). With the unit
     * tangent t = (b - a)/|b - a| and the unit normal n = (t_y, -t_x) (on
     * the right of a -> b, the outward normal of the triangle on the left):
     * normal stress n.sigma.n (tension positive), shear stress t.sigma.n.
     * Swapping @p a and @p b changes neither.
     *
     * @param stress The stress tensor (Pa, tension positive).
     * @param a First end of the edge.
     * @param b Second end of the edge; must differ from @p a.
     * @return The state with @p stress and its normal and shear stress.
     */
    EdgeState
    edge_state(const SymmetricTensor<2, 2> &stress,
               const Point<2>              &a,
               const Point<2>              &b);

    /**
     * The interior edges of a triangle mesh, ordered by their first and
     * then their second vertex. O(number of triangles).
     *
     * Throws dealii::ExcMessage if an edge is shared by more than two
     * triangles or if two triangles beside an edge run through it in the
     * same direction (one of them is clockwise).
     *
     * @param triangles Triangles as vertex index triples, counter-clockwise.
     * @param n_vertices Number of vertices; every index must be below it.
     */
    std::vector<InteriorEdge>
    find_interior_edges(
      const std::vector<std::array<unsigned int, 3>> &triangles,
      const unsigned int                              n_vertices);

    /**
     * The nodal stresses of a triangle mesh: at each vertex, the
     * area-weighted mean of the stresses of the triangles that use it,
     * sigma_v = sum_c A_c sigma_c / sum_c A_c. This is the lumped-mass L2
     * projection of the piecewise constant stress onto continuous linear
     * functions (doc/fracture.md). Blocks never share vertices, and the two
     * sides of a crack have their own vertices, so the mean never mixes
     * blocks or reaches across a crack. A vertex that no triangle uses gets
     * a zero stress. O(number of triangles).
     *
     * @param triangles Triangles as vertex index triples.
     * @param cell_stresses One stress per triangle (for elements whose
     *   stress varies inside the cell: the cell's mean stress).
     * @param cell_areas One area per triangle, positive.
     * @param n_vertices Number of vertices.
     */
    std::vector<SymmetricTensor<2, 2>>
    nodal_stresses(const std::vector<std::array<unsigned int, 3>> &triangles,
                   const std::vector<SymmetricTensor<2, 2>> &cell_stresses,
                   const std::vector<double>                &cell_areas,
                   const unsigned int                        n_vertices);

    /**
     * Stress tensor of each edge as the mean of the stresses of its two
     * cells, (sigma_1 + sigma_2)/2 (thesis 5.21).
     */
    std::vector<SymmetricTensor<2, 2>>
    cell_average_edge_stresses(
      const std::vector<InteriorEdge>          &edges,
      const std::vector<SymmetricTensor<2, 2>> &cell_stresses);

    /**
     * Stress tensor of each edge as the mean of the nodal stresses of its
     * two vertices, (sigma_a + sigma_b)/2: the value at the edge's midpoint
     * (and the mean along the edge) of the linear field that interpolates
     * the nodal stresses.
     *
     * @param edges The edges.
     * @param nodal_stresses One stress per vertex, from nodal_stresses().
     */
    std::vector<SymmetricTensor<2, 2>>
    nodal_average_edge_stresses(
      const std::vector<InteriorEdge>          &edges,
      const std::vector<SymmetricTensor<2, 2>> &nodal_stresses);

    /**
     * The state of every edge: its stress tensor @p edge_stresses and the
     * normal and shear stress on it at the given vertex positions. Call it
     * once with the positions and stresses at the start of the step and
     * once with those at the end, with the same @p edges, so that the i-th
     * states of the two calls belong to the same edge.
     */
    std::vector<EdgeState>
    edge_states(const std::vector<InteriorEdge>          &edges,
                const std::vector<Point<2>>              &vertices,
                const std::vector<SymmetricTensor<2, 2>> &edge_stresses);

    /**
     * As above with the edge stresses formed by @p method from the cell
     * stresses; @p method must be cell_average or nodal_average (the
     * nonlocal average needs its weights, NonlocalAverage).
     *
     * @param edges Interior edges, from find_interior_edges().
     * @param vertices Vertex positions.
     * @param triangles Triangles as vertex index triples.
     * @param cell_stresses One stress per triangle.
     * @param cell_areas One area per triangle (used by the nodal average
     *   only).
     * @param method Cell average or nodal average.
     */
    std::vector<EdgeState>
    edge_states(const std::vector<InteriorEdge>                &edges,
                const std::vector<Point<2>>                    &vertices,
                const std::vector<std::array<unsigned int, 3>> &triangles,
                const std::vector<SymmetricTensor<2, 2>>       &cell_stresses,
                const std::vector<double>                      &cell_areas,
                const EdgeStressMethod                          method);
  } // namespace fracture
} // namespace ndda

#endif
