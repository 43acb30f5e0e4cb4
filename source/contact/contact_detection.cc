// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/exceptions.h>

#include <deal.II/numerics/rtree.h>

#include <ndda/contact/contact_detection.h>

#include <algorithm>
#include <iterator>
#include <tuple>
#include <utility>

namespace ndda
{
  namespace contact
  {
    using dealii::BoundingBox;

    namespace
    {
      /** True if the two edges have a vertex in common. */
      bool
      share_vertex(const BoundaryEdge &a, const BoundaryEdge &b)
      {
        return a.v0 == b.v0 || a.v0 == b.v1 || a.v1 == b.v0 || a.v1 == b.v1;
      }


      /** The axis-aligned box of an edge. */
      BoundingBox<2>
      edge_box(const std::vector<Point<2>> &vertices, const BoundaryEdge &e)
      {
        const Point<2> &a = vertices[e.v0];
        const Point<2> &b = vertices[e.v1];
        return BoundingBox<2>(
          std::make_pair(Point<2>(std::min(a[0], b[0]), std::min(a[1], b[1])),
                         Point<2>(std::max(a[0], b[0]), std::max(a[1], b[1]))));
      }
    } // namespace



    bool
    vertex_edge_candidate(const std::vector<Point<2>>     &vertices,
                          const unsigned int               vertex,
                          const std::vector<BoundaryEdge> &edges,
                          const unsigned int               edge,
                          const double                     threshold,
                          Candidate                       &candidate)
    {
      const Point<2> &a = vertices[edges[edge].v0];
      const Point<2> &b = vertices[edges[edge].v1];
      const Point<2> &p = vertices[vertex];

      const dealii::Tensor<1, 2> t       = b - a;
      const dealii::Tensor<1, 2> ap      = p - a;
      const double               length2 = t.norm_square();
      // A degenerate edge is a point: its closest point is its end point.
      const double ratio   = (length2 > 0. ? (ap * t) / length2 : 0.);
      const double clamped = std::min(1., std::max(0., ratio));

      const double distance = (ap - clamped * t).norm();
      if (distance > threshold)
        return false;

      // Cross product t x ap: positive when p lies on the left of a->b,
      // i.e. on the side of the edge's body.
      const double cross        = t[0] * ap[1] - t[1] * ap[0];
      const bool   at_end_point = !(ratio > vertex_vertex_tolerance &&
                                  ratio < 1. - vertex_vertex_tolerance);

      candidate.vertex     = vertex;
      candidate.edge       = edge;
      candidate.type       = (at_end_point ? CandidateType::vertex_vertex :
                                             CandidateType::vertex_edge);
      candidate.distance   = (cross > 0. ? -distance : distance);
      candidate.edge_ratio = clamped;
      return true;
    }



    std::vector<Candidate>
    detect(const std::vector<Point<2>>     &vertices,
           const std::vector<BoundaryEdge> &edges,
           const double                     threshold)
    {
      AssertThrow(threshold >= 0.,
                  dealii::ExcMessage("The contact detection threshold must "
                                     "not be negative."));
      namespace bgi = boost::geometry::index;
      using Leaf    = std::pair<BoundingBox<2>, unsigned int>;

      // Broad phase: the tree holds the grown boxes; every edge queries it
      // with its own box. Two boxes at most `threshold` apart along each
      // axis are reported, which every vertex-edge distance <= threshold
      // implies. The relation is symmetric, so each pair is handled once,
      // by its lower edge index.
      std::vector<Leaf>           grown(edges.size());
      std::vector<BoundingBox<2>> own(edges.size());
      for (unsigned int e = 0; e < edges.size(); ++e)
        {
          own[e]   = edge_box(vertices, edges[e]);
          grown[e] = {own[e], e};
          grown[e].first.extend(threshold);
        }
      const auto tree = dealii::pack_rtree(grown);

      std::vector<Candidate> candidates;
      std::vector<Leaf>      hits;
      Candidate              candidate;
      for (unsigned int i = 0; i < edges.size(); ++i)
        {
          hits.clear();
          tree.query(bgi::intersects(own[i]), std::back_inserter(hits));
          for (const Leaf &hit : hits)
            {
              const unsigned int j = hit.second;
              if (j <= i || share_vertex(edges[i], edges[j]))
                continue;
              // Narrow phase: the end vertices of each edge against the
              // other edge.
              for (const unsigned int v : {edges[j].v0, edges[j].v1})
                if (vertex_edge_candidate(
                      vertices, v, edges, i, threshold, candidate))
                  candidates.push_back(candidate);
              for (const unsigned int v : {edges[i].v0, edges[i].v1})
                if (vertex_edge_candidate(
                      vertices, v, edges, j, threshold, candidate))
                  candidates.push_back(candidate);
            }
        }

      // A vertex is an end point of two (or more) boundary edges, so it may
      // have been tested against the same edge more than once, always with
      // the same result.
      const auto by_vertex_edge = [](const Candidate &a, const Candidate &b) {
        return std::tie(a.vertex, a.edge) < std::tie(b.vertex, b.edge);
      };
      std::sort(candidates.begin(), candidates.end(), by_vertex_edge);
      candidates.erase(std::unique(candidates.begin(),
                                   candidates.end(),
                                   [](const Candidate &a, const Candidate &b) {
                                     return a.vertex == b.vertex &&
                                            a.edge == b.edge;
                                   }),
                       candidates.end());
      return candidates;
    }
  } // namespace contact
} // namespace ndda
