// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_contact_contact_detection_h
#define ndda_contact_contact_detection_h

#include <deal.II/base/point.h>

#include <ndda/mesh/boundary_edges.h>

#include <vector>

namespace ndda
{
  /**
   * Contact between blocks (and between the faces of a crack or a notch of
   * one block): detection. It finds the vertex-edge and vertex-vertex
   * candidates of one time step as plain data, between the boundary edges
   * of the mesh (ndda::boundary_edges(), mesh/boundary_edges.h).
   * ContactHandler turns the candidates into contacts; the contact law
   * (ContactLaw) gives them their springs.
   *
   * Detection has two phases:
   * - broad phase: one axis-aligned box per boundary edge, grown by the
   *   detection threshold, packed into a boost R-tree through deal.II's
   *   pack_rtree(); each edge queries the tree with its own (not grown)
   *   box, so a pair of edges is reported exactly when their boxes are at
   *   most the threshold apart along each axis. Cost O(n log n) for n
   *   boundary edges (plus the number of reported pairs).
   * - narrow phase: for every reported pair of edges that share no vertex,
   *   each end vertex of one edge is tested against the other edge
   *   (vertex_edge_candidate()). Edge-edge contact is two vertex-edge
   *   contacts.
   *
   * Nothing here depends on the Simulator or on a Triangulation.
   *
   * @ingroup contact
   */
  namespace contact
  {
    using dealii::Point;

    /**
     * Kind of a contact candidate.
     */
    enum class CandidateType
    {
      /// The vertex projects into the interior of the edge.
      vertex_edge,
      /// The closest point of the edge is one of its end points: the
      /// contact direction is not given by the edge alone (chapter 6).
      vertex_vertex
    };

    /**
     * A vertex close to a boundary edge it is not part of.
     */
    struct Candidate
    {
      /// The vertex (index into the vertices).
      unsigned int vertex;
      /// The edge (index into the boundary edges handed to detect()).
      unsigned int edge;
      /// vertex_edge or vertex_vertex, see vertex_edge_candidate().
      CandidateType type;
      /// Signed distance from the vertex to the closest point of the edge:
      /// its length, positive when the vertex lies outside the edge's body
      /// (on the right of v0->v1 or on its line), negative when it lies on
      /// the left (penetration).
      double distance;
      /// Position of the vertex's projection on the edge, clamped to [0,1]:
      /// 0 at v0, 1 at v1.
      double edge_ratio;
    };

    /**
     * Projection ratios within this distance of 0 or 1 make a candidate
     * vertex_vertex.
     */
    constexpr double vertex_vertex_tolerance = 1e-9;

    /**
     * Narrow-phase test of one vertex against one boundary edge.
     *
     * Computes the closest point of the segment edges[edge] to
     * vertices[vertex]. If their distance is at most @p threshold, writes
     * the candidate to @p candidate and returns true; it is a vertex_vertex
     * candidate when the unclamped projection ratio lies outside
     * (vertex_vertex_tolerance, 1 - vertex_vertex_tolerance), a vertex_edge
     * candidate otherwise. Does not check whether the vertex is an end point
     * of the edge; detect() never asks for that.
     */
    bool
    vertex_edge_candidate(const std::vector<Point<2>>     &vertices,
                          const unsigned int               vertex,
                          const std::vector<BoundaryEdge> &edges,
                          const unsigned int               edge,
                          const double                     threshold,
                          Candidate                       &candidate);

    /**
     * All contact candidates between the boundary edges @p edges with
     * vertex positions @p vertices (the current, moved positions).
     *
     * Broad phase with an R-tree of edge boxes grown by @p threshold; narrow
     * phase for every pair of edges within reach that share no vertex
     * (edges of the same block count too: the faces of a crack, the sides
     * of a concave notch): each end vertex of one edge is tested against
     * the other edge with vertex_edge_candidate(). Duplicates (same vertex,
     * same edge, found through both edges at the vertex) are removed; the
     * result is sorted by vertex, then edge. Cost O(n log n) for n edges
     * when every edge has a bounded number of neighbours within reach.
     *
     * @param vertices Vertex positions.
     * @param edges Boundary edges, for example from ndda::boundary_edges().
     * @param threshold Detection distance (m), non-negative.
     */
    std::vector<Candidate>
    detect(const std::vector<Point<2>>     &vertices,
           const std::vector<BoundaryEdge> &edges,
           const double                     threshold);

    /**
     * Contact detection that keeps its broad phase from step to step (a
     * Verlet neighbour list, as particle codes keep theirs): the (vertex,
     * edge) pairs detect() would test with the detection distance grown by
     * a skin, sorted by vertex, then edge. A later call reuses them as long
     * as no boundary vertex has moved more than half the skin since they
     * were built, less what the detection distance itself has grown, and
     * only runs the narrow phase (vertex_edge_candidate()) over them: the
     * candidates are exactly those of detect(), in the same order, without
     * its R-tree and its sort.
     *
     * Why the list stays complete: a candidate (v, e) within the threshold
     * t now has v on an edge whose box lies within t of e's box along each
     * axis. The box of an edge whose end points each moved at most m lies
     * in its old box grown by m, so the two boxes were within t + 2 m at
     * the build, which the build's reach (its threshold plus the skin)
     * covers while t + 2 m stays below it.
     *
     * A list built for a far larger distance than a later call asks for
     * (its reach more than four times what a build for the call would
     * have) is built again, so that a detection distance that falls (a
     * scene that comes to rest) does not keep testing the pairs of the
     * larger one.
     *
     * The list belongs to one set of boundary edges and one numbering of
     * the vertices: clear() it when they change (a crack).
     *
     * On several processes (set_owned_vertices()) each process keeps only
     * the tests of the vertices it owns: the broad phase runs over its own
     * edges (those with an owned end vertex) and the ghost edges within
     * reach of them (the edges of other processes' blocks whose boxes come
     * within the reach of the box around its own edges), and the narrow
     * phase tests its own vertices only. The tests of all processes
     * together are exactly those of one process: a test (v, e) comes from
     * a pair of edges within reach, one of which has v as an end point;
     * its owner holds that edge as its own and e as own or ghost. Every
     * process watches the motion of every boundary vertex, as one process
     * does, so that an edge that was no ghost at the build (a block thrown
     * from afar) cannot come within reach unseen.
     */
    class NeighbourList
    {
    public:
      /**
       * The skin is @p skin_factor times the detection distance of the
       * call that builds the list.
       */
      explicit NeighbourList(const double skin_factor = 1.);

      /** Forget the list: the next detect() builds it. */
      void
      clear();

      /**
       * Keep only the tests of the vertices @p owned marks (by vertex
       * index), the others being some other process's; empty: every
       * vertex, as on one process. Forgets the list.
       */
      void
      set_owned_vertices(std::vector<bool> owned);

      /** The boundary edges the last build held: every edge on one
       * process, the own and the ghost edges on several. */
      std::size_t
      n_local_edges() const
      {
        return local_edges;
      }

      /**
       * The candidates of detect(vertices, edges, threshold). A build
       * gives the list a skin of at least @p min_skin (m): a detection
       * distance that follows the motion would otherwise give it a skin
       * of a step's motion, and build it every other step.
       */
      std::vector<Candidate>
      detect(const std::vector<Point<2>>     &vertices,
             const std::vector<BoundaryEdge> &edges,
             const double                     threshold,
             const double                     min_skin = 0.);

      /** How often the list was built since construction. */
      unsigned int
      n_builds() const
      {
        return builds;
      }

      /** The number of (vertex, edge) pairs in the list. */
      std::size_t
      size() const
      {
        return tests.size();
      }

    private:
      /** True if the list covers distance @p threshold on @p vertices
       * and is not far larger than a build with reach @p wanted. */
      bool
      covers(const std::vector<Point<2>>     &vertices,
             const std::vector<BoundaryEdge> &edges,
             const double                     threshold,
             const double                     wanted) const;

      void
      build(const std::vector<Point<2>>     &vertices,
            const std::vector<BoundaryEdge> &edges,
            const double                     reach);

      /** The tests of build() for the owned vertices only
       * (set_owned_vertices()); returns the number of own and ghost
       * edges. */
      std::size_t
      add_owned_tests(const std::vector<Point<2>>     &vertices,
                      const std::vector<BoundaryEdge> &edges,
                      const double                     reach);

      double skin_factor;
      /// (vertex, edge), sorted and unique.
      std::vector<std::pair<unsigned int, unsigned int>> tests;
      /// The end points of the edges, and where they were at the build.
      std::vector<unsigned int> boundary_vertices;
      std::vector<Point<2>>     built_at;
      /// Threshold plus skin of the build; negative: no list.
      double      reach   = -1;
      std::size_t n_edges = 0, n_vertices = 0;
      /// The vertices whose tests this list keeps; empty: all.
      std::vector<bool> owned;
      std::size_t       local_edges = 0;
      unsigned int      builds      = 0;
    };
  } // namespace contact
} // namespace ndda

#endif
