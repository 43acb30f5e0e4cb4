// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/parallel.h>

#include <deal.II/numerics/rtree.h>

#include <ndda/contact/contact_detection.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
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


      /** Whether two boxes overlap or touch (as boost's intersects()). */
      bool
      touch(const BoundingBox<2> &a, const BoundingBox<2> &b)
      {
        for (unsigned int d = 0; d < 2; ++d)
          if (a.upper_bound(d) < b.lower_bound(d) ||
              a.lower_bound(d) > b.upper_bound(d))
            return false;
        return true;
      }


      /** An edge's box grown by @p reach, as for_each_edge_pair() grows
       * it. */
      BoundingBox<2>
      grown_box(const std::vector<Point<2>> &vertices,
                const BoundaryEdge          &e,
                const double                 reach)
      {
        BoundingBox<2> box = edge_box(vertices, e);
        box.extend(reach);
        return box;
      }


      /**
       * Broad phase: calls @p f(i, j) once for every pair of edges i < j
       * that share no vertex and whose boxes are at most @p reach apart
       * along each axis. The tree holds the grown boxes; every edge
       * queries it with its own box. Two boxes at most `reach` apart along
       * each axis are reported, which every vertex-edge distance <= reach
       * implies. The relation is symmetric, so each pair is handled once,
       * by its lower edge index.
       */
      template <typename Function>
      void
      for_each_edge_pair(const std::vector<Point<2>>     &vertices,
                         const std::vector<BoundaryEdge> &edges,
                         const double                     reach,
                         const Function                  &f)
      {
        namespace bgi = boost::geometry::index;
        using Leaf    = std::pair<BoundingBox<2>, unsigned int>;

        std::vector<Leaf>           grown(edges.size());
        std::vector<BoundingBox<2>> own(edges.size());
        for (unsigned int e = 0; e < edges.size(); ++e)
          {
            own[e]   = edge_box(vertices, edges[e]);
            grown[e] = {own[e], e};
            grown[e].first.extend(reach);
          }
        const auto tree = dealii::pack_rtree(grown);

        std::vector<Leaf> hits;
        for (unsigned int i = 0; i < edges.size(); ++i)
          {
            hits.clear();
            tree.query(bgi::intersects(own[i]), std::back_inserter(hits));
            for (const Leaf &hit : hits)
              {
                const unsigned int j = hit.second;
                if (j > i && !share_vertex(edges[i], edges[j]))
                  f(i, j);
              }
          }
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

      // Most tests fail: by the square first (with a margin for its
      // rounding), the root only for the few near enough.
      const double distance2 = (ap - clamped * t).norm_square();
      if (distance2 > (1. + 1e-10) * threshold * threshold)
        return false;
      const double distance = std::sqrt(distance2);
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
      // Narrow phase for every pair within reach: the end vertices of each
      // edge against the other edge.
      std::vector<Candidate> candidates;
      Candidate              candidate;
      for_each_edge_pair(
        vertices,
        edges,
        threshold,
        [&](const unsigned int i, const unsigned int j) {
          for (const unsigned int v : {edges[j].v0, edges[j].v1})
            if (vertex_edge_candidate(
                  vertices, v, edges, i, threshold, candidate))
              candidates.push_back(candidate);
          for (const unsigned int v : {edges[i].v0, edges[i].v1})
            if (vertex_edge_candidate(
                  vertices, v, edges, j, threshold, candidate))
              candidates.push_back(candidate);
        });

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



    NeighbourList::NeighbourList(const double skin_factor)
      : skin_factor(skin_factor)
    {
      AssertThrow(skin_factor >= 0.,
                  dealii::ExcMessage("The skin of a neighbour list must not "
                                     "be negative."));
    }



    void
    NeighbourList::clear()
    {
      tests.clear();
      boundary_vertices.clear();
      built_at.clear();
      reach = -1;
    }



    bool
    NeighbourList::covers(const std::vector<Point<2>>     &vertices,
                          const std::vector<BoundaryEdge> &edges,
                          const double                     threshold,
                          const double                     wanted) const
    {
      if (reach < 0 || edges.size() != n_edges ||
          vertices.size() != n_vertices || reach > 4. * wanted)
        return false;
      // The largest motion m of an end point since the build, against
      // threshold + 2 m <= reach.
      const double allowed = 0.5 * (reach - threshold);
      if (allowed < 0)
        return false;
      const double allowed2 = allowed * allowed;
      for (unsigned int k = 0; k < boundary_vertices.size(); ++k)
        if (vertices[boundary_vertices[k]].distance_square(built_at[k]) >
            allowed2)
          return false;
      return true;
    }



    void
    NeighbourList::set_owned_vertices(std::vector<bool> owned_in)
    {
      owned = std::move(owned_in);
      clear();
    }



    std::size_t
    NeighbourList::add_owned_tests(const std::vector<Point<2>>     &vertices,
                                   const std::vector<BoundaryEdge> &edges,
                                   const double                     reach)
    {
      namespace bgi = boost::geometry::index;
      using Leaf    = std::pair<BoundingBox<2>, unsigned int>;
      AssertThrow(owned.size() == vertices.size(),
                  dealii::ExcMessage(
                    "NeighbourList: the owned vertices were set for " +
                    std::to_string(owned.size()) + " vertices, detect() got " +
                    std::to_string(vertices.size()) + "."));

      // The own edges and the box around them.
      std::vector<unsigned int> own_edges;
      for (unsigned int e = 0; e < edges.size(); ++e)
        if (owned[edges[e].v0] || owned[edges[e].v1])
          own_edges.push_back(e);
      if (own_edges.empty())
        return 0;
      BoundingBox<2> region = edge_box(vertices, edges[own_edges[0]]);
      for (const unsigned int e : own_edges)
        region.merge_with(edge_box(vertices, edges[e]));
      // The pairs are those of for_each_edge_pair(): (i, j), i < j, with
      // i's box touching j's grown box. An own edge i queries with its
      // box grown by a rounding margin, so that it finds the pairs in
      // which it is the larger index too (the relation is symmetric but
      // for the rounding of the growth); each pair found is then tested
      // as for_each_edge_pair() tests it.
      const double margin =
        1e-10 * (reach + std::max({std::abs(region.lower_bound(0)),
                                   std::abs(region.lower_bound(1)),
                                   std::abs(region.upper_bound(0)),
                                   std::abs(region.upper_bound(1))}));
      region.extend(margin);

      // The ghost edges: every edge whose grown box reaches the region.
      std::vector<Leaf> grown;
      for (unsigned int e = 0; e < edges.size(); ++e)
        {
          const BoundingBox<2> box = grown_box(vertices, edges[e], reach);
          if (touch(box, region))
            grown.emplace_back(box, e);
        }
      const auto tree = dealii::pack_rtree(grown);

      std::vector<Leaf> hits;
      for (const unsigned int i : own_edges)
        {
          const BoundingBox<2> own_i = edge_box(vertices, edges[i]);
          BoundingBox<2>       query = own_i;
          query.extend(margin);
          hits.clear();
          tree.query(bgi::intersects(query), std::back_inserter(hits));
          for (const Leaf &hit : hits)
            {
              const unsigned int j = hit.second;
              if (j == i || share_vertex(edges[i], edges[j]))
                continue;
              const bool pair =
                (i < j ? touch(own_i, hit.first) :
                         touch(edge_box(vertices, edges[j]),
                               grown_box(vertices, edges[i], reach)));
              if (pair)
                for (const unsigned int v : {edges[i].v0, edges[i].v1})
                  if (owned[v])
                    tests.emplace_back(v, j);
            }
        }
      return grown.size();
    }



    void
    NeighbourList::build(const std::vector<Point<2>>     &vertices,
                         const std::vector<BoundaryEdge> &edges,
                         const double                     reach_in)
    {
      reach = reach_in;
      tests.clear();
      if (owned.empty())
        {
          for_each_edge_pair(vertices,
                             edges,
                             reach,
                             [&](const unsigned int i, const unsigned int j) {
                               tests.emplace_back(edges[j].v0, i);
                               tests.emplace_back(edges[j].v1, i);
                               tests.emplace_back(edges[i].v0, j);
                               tests.emplace_back(edges[i].v1, j);
                             });
          local_edges = edges.size();
        }
      else
        local_edges = add_owned_tests(vertices, edges, reach);
      std::sort(tests.begin(), tests.end());
      tests.erase(std::unique(tests.begin(), tests.end()), tests.end());

      // Every boundary vertex is watched, also on several processes: an
      // edge that is not a ghost now may move within reach (a block thrown
      // from afar), and the list is then built again, as on one process.
      boundary_vertices.clear();
      for (const BoundaryEdge &e : edges)
        {
          boundary_vertices.push_back(e.v0);
          boundary_vertices.push_back(e.v1);
        }
      std::sort(boundary_vertices.begin(), boundary_vertices.end());
      boundary_vertices.erase(std::unique(boundary_vertices.begin(),
                                          boundary_vertices.end()),
                              boundary_vertices.end());
      built_at.resize(boundary_vertices.size());
      for (unsigned int k = 0; k < boundary_vertices.size(); ++k)
        built_at[k] = vertices[boundary_vertices[k]];
      n_edges    = edges.size();
      n_vertices = vertices.size();
      ++builds;
    }



    std::vector<Candidate>
    NeighbourList::detect(const std::vector<Point<2>>     &vertices,
                          const std::vector<BoundaryEdge> &edges,
                          const double                     threshold,
                          const double                     min_skin)
    {
      AssertThrow(threshold >= 0.,
                  dealii::ExcMessage("The contact detection threshold must "
                                     "not be negative."));
      const double wanted =
        threshold + std::max(skin_factor * threshold, min_skin);
      if (!covers(vertices, edges, threshold, wanted))
        build(vertices, edges, wanted);
      // The tests on deal.II's threads in chunks, each chunk's candidates
      // into a list of its own; the lists joined in the order of the tests.
      const std::size_t  chunk    = 4096;
      const unsigned int n_chunks = (tests.size() + chunk - 1) / chunk;
      std::vector<std::vector<Candidate>> found(n_chunks);
      dealii::parallel::apply_to_subranges(
        0u,
        n_chunks,
        [&](const unsigned int begin, const unsigned int end) {
          Candidate candidate;
          for (unsigned int k = begin; k < end; ++k)
            for (std::size_t i = k * chunk;
                 i < std::min(tests.size(), (k + 1) * chunk);
                 ++i)
              if (vertex_edge_candidate(vertices,
                                        tests[i].first,
                                        edges,
                                        tests[i].second,
                                        threshold,
                                        candidate))
                found[k].push_back(candidate);
        },
        1);
      std::vector<Candidate> candidates;
      for (const auto &f : found)
        candidates.insert(candidates.end(), f.begin(), f.end());
      return candidates;
    }
  } // namespace contact
} // namespace ndda
