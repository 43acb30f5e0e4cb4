// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_fracture_crack_tips_h
#define ndda_fracture_crack_tips_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <ndda/fracture/edge_stress.h>
#include <ndda/mesh/crackable_mesh.h>

#include <array>
#include <vector>

namespace ndda
{
  namespace fracture
  {
    /**
     * A crack tip inside a block: a vertex where a crack ends, kept single
     * by node splitting (CrackableMesh::crack()), whose two last crack
     * faces meet there and end, behind the tip, at two copies of one
     * vertex.
     *
     * @ingroup fracture
     */
    struct CrackTip
    {
      /// The tip vertex.
      unsigned int vertex = 0;
      /// Two copies of one crack node behind the tip, where the faces'
      /// jump is read: behind[0] on the side of +y' (the faces whose cells
      /// lie there), behind[1] on the side of -y'. The far ends of the last
      /// two faces, or up to three faces back while the crack runs
      /// straight (each further face pair within 15 degrees of the
      /// direction of the last one).
      std::array<unsigned int, 2> behind = {{0, 0}};
      /// x': the crack's direction at the tip, pointing out of the crack,
      /// from the middle of the two behind nodes to the tip (unit, present
      /// geometry). y' is x' turned by +90 degrees.
      dealii::Tensor<1, 2> outward;
    };

    /**
     * The crack tips of the mesh. A vertex is a tip when exactly two of the
     * sides of its triangles lie on a boundary, both are crack faces
     * (CrackableMesh::is_cracked()), one runs into the vertex and one out
     * of it, and their far ends are different copies of one vertex (the
     * same initial position). Cracks with both
     * ends inside a block and still closed (thesis figure 5.4) have no
     * tip here: their faces share both vertices. O(n log n).
     */
    std::vector<CrackTip>
    find_crack_tips(const CrackableMesh &mesh);

    /**
     * The same on plain arrays: @p mesh with its crack faces
     * (geometry::BlockMesh::crack_edges) and the initial positions of its
     * vertices, as CrackableMesh::crack() has them before it rebuilds the
     * triangulation.
     */
    std::vector<CrackTip>
    find_crack_tips(const geometry::BlockMesh           &mesh,
                    const std::vector<dealii::Point<2>> &initial_vertices);

    /**
     * K_I and K_II at a tip up to a common positive factor, by
     * displacement correlation: the jump of displacement across the crack
     * at the nodes behind the tip (CrackTip::behind; the +y' face's node
     * minus the -y' face's), on x' for K_II and y' for K_I. Both modes
     * share the factor (kappa + 1)/(2 mu) sqrt(r/(2 pi)) of the
     * near-tip field, so the ratio is free of material constants. The jump
     * is the present gap minus the initial one (@p initial_vertices):
     * faces of a crack that the scene starts with may be apart already.
     */
    std::array<double, 2>
    stress_intensity_ratio(const CrackTip                      &tip,
                           const std::vector<dealii::Point<2>> &vertices,
                           const std::vector<dealii::Point<2>> &initial);

    /**
     * The angle theta (radians, counter-clockwise from x') at which the
     * hoop stress of the near-tip field is largest (maximum tangential
     * stress, thesis 7.11): theta = -2 atan(2 K_II / (K_I + sqrt(K_I^2 +
     * 8 K_II^2))), the root of K_I sin theta + K_II (3 cos theta - 1) = 0
     * with theta in (-70.53, 70.53) degrees. A closed crack (K_I < 0)
     * counts as K_I = 0. Without either mode, 0.
     */
    double
    maximum_tangential_stress_angle(double k_I, const double k_II);

    /**
     * One advance of a crack tip (plan_crack_advance()).
     */
    struct TipAdvance
    {
      /// Start of the step in which the tip advanced (set by the caller).
      double time = 0;
      /// The tip vertex and the vertex the crack advances to.
      unsigned int tip = 0, target = 0;
      /// The tip's position, the target's before and after it was moved
      /// (the same if it was not), in the present geometry.
      dealii::Point<2> tip_position, target_from, target_to;
      /// The same three in the initial geometry.
      dealii::Point<2> initial_tip, initial_target_from, initial_target_to;
      /// The maximum tangential stress angle (radians from x') and the
      /// angle of the edge that cracks, both from x'.
      double mts_angle = 0, edge_angle = 0;
      /// K_I and K_II up to a common factor (stress_intensity_ratio()).
      std::array<double, 2> k = {{0, 0}};
      /// Whether the target vertex was moved.
      bool moved = false;
    };

    /**
     * A crack event with tip advances: the edges to crack and the vertices
     * to move first.
     */
    struct AdvancePlan
    {
      /// Edges to crack (vertex pairs of the mesh).
      std::vector<std::array<unsigned int, 2>> edges;
      /// Vertices to move before the crack, their new position in the
      /// present geometry and in the initial one.
      std::vector<unsigned int>     moved;
      std::vector<dealii::Point<2>> position, initial_position;
      /// One entry per tip that advances.
      std::vector<TipAdvance> advances;
    };

    /**
     * Turn failing edges into crack growth that follows the stress
     * (`Crack path = maximum tangential stress`, doc/fracture.md). A
     * failing edge whose midpoint lies within the tip zone of a crack tip
     * of its block
     * (radius max(@p zone_radius, twice the mean length of the tip's
     * edges), nearest tip) is not cracked: the tip advances instead, once
     * per event. The direction d is the maximum tangential stress angle
     * for the tip's stress intensity ratio. Among the edges from the tip
     * that may crack, the one nearest to d in angle cracks; if it is
     * more than 0.5 degrees off, its far vertex is first moved onto the ray
     * from the tip along d (at its distance from the tip, or 0.8, 1.2, 0.6,
     * 1.4, 0.5 times that), provided it is an interior vertex of its
     * block, not in @p fixed, inside one material, not moved yet in this
     * event, and the triangles around it
     * stay counter-clockwise with their smallest angle at least
     * min(15 degrees, the smallest angle they had). The next-nearest edges
     * are tried in turn (up to 60 degrees off d); if no vertex may move,
     * the nearest edge cracks as it is. The total area of the mesh is
     * unchanged by a move (the outline of the moved vertex's triangles
     * stays), and the moved vertex's initial position is interpolated
     * linearly in the triangle that held the new position.
     * Failing edges outside every tip zone crack as they are.
     *
     * @param trial_vertices The vertices at the end of the step being
     *   solved (the state the failure was found in): the faces' jump is
     *   read there, so that a tip created earlier in the same step (whose
     *   faces have not opened in the present geometry) has its own ratio.
     * @param crackable The edges that may crack (both cells of a
     *   fracturing material: EdgeFailureCheck::get_edges()); a tip
     *   advances only along one of them.
     * @param fixed Vertices that must not move (constraints, bolt
     *   anchors); empty: none. A vertex between cells of different
     *   materials does not move either (the interface would).
     */
    AdvancePlan
    plan_crack_advance(const CrackableMesh                            &mesh,
                       const std::vector<std::array<unsigned int, 2>> &failing,
                       const std::vector<dealii::Point<2>> &trial_vertices,
                       const double                         zone_radius,
                       const std::vector<InteriorEdge>     &crackable,
                       const std::vector<bool>             &fixed);
  } // namespace fracture
} // namespace ndda

#endif
