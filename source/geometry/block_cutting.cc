// SPDX-License-Identifier: GPL-3.0-or-later
//
// Block cutting (thesis chapter 4): the rings of a validated polygon and its
// joints or cracks go into one CGAL Arrangement_2 with exact constructions;
// the faces inside the polygon are found by the parity of ring crossings,
// and become the Domains that block_meshing.cc meshes.
//
// Decisions that the header leaves open:
//  - BlockMesh::crack_edges holds the faces of explicit cracks and of kept
//    dangling joints, that is the edges that were split. Joint faces between
//    two blocks cut from one region are ordinary block boundaries (the two
//    blocks have different names "<region>.<k>"), not crack edges.
//  - Blocks are numbered: explicit blocks in input order, then the blocks of
//    every region in input order, each region's blocks sorted by their
//    lowest, then leftmost vertex.

#include <ndda/geometry/block_mesh.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "cgal_kernels.h"

namespace ndda
{
  namespace geometry
  {
    namespace internal
    {
      namespace
      {
        /**
         * Collect the boundary and crack edges of a set of arrangement faces
         * into a Domain. A halfedge whose other side is in the set too is a
         * crack (or a dangling joint); otherwise it is a boundary edge, and
         * a hole edge too if it lies on one of the polygon's holes (curve
         * ids 1 to @p n_rings - 1).
         */
        template <typename InGroup>
        Domain
        extract_domain(const std::vector<FaceHandle> &faces,
                       const InGroup                 &in_group,
                       const bool                     keep_cracks,
                       const unsigned int             n_rings)
        {
          Domain                                         domain;
          std::unordered_map<const void *, unsigned int> vertex_index;
          std::unordered_set<const void *>               crack_seen;
          const auto index_of = [&](const VertexHandle &v) {
            const auto it = vertex_index.find(&*v);
            if (it != vertex_index.end())
              return it->second;
            const unsigned int index = domain.points.size();
            domain.points.emplace_back(to_double_exactly(v->point().x()),
                                       to_double_exactly(v->point().y()));
            vertex_index.emplace(&*v, index);
            return index;
          };

          for (const FaceHandle &face : faces)
            for_each_boundary_halfedge(face, [&](const HalfedgeHandle &h) {
              if (in_group(h->twin()->face()))
                {
                  const void *edge = std::min<const void *>(&*h, &*h->twin());
                  if (keep_cracks && crack_seen.insert(edge).second)
                    domain.cracks.push_back(
                      {{index_of(h->source()), index_of(h->target())}});
                }
              else
                {
                  domain.boundary.push_back(
                    {{index_of(h->source()), index_of(h->target())}});
                  const auto &ids = h->curve().data();
                  if (std::any_of(ids.begin(),
                                  ids.end(),
                                  [&](const unsigned int id) {
                                    return id > 0 && id < n_rings;
                                  }))
                    domain.hole_edges.push_back(
                      {{domain.points[domain.boundary.back()[0]],
                        domain.points[domain.boundary.back()[1]]}});
                }
            });

          // Shoelace formula over the oriented boundary.
          for (const Edge &e : domain.boundary)
            {
              const IPoint &a = domain.points[e[0]];
              const IPoint &b = domain.points[e[1]];
              domain.area += 0.5 * (a.x() * b.y() - b.x() * a.y());
            }
          domain.diameter = diagonal(bbox_of(domain.points));
          return domain;
        }


        /**
         * Number of ids in an edge's list that are ring ids (smaller than
         * @p n_rings), modulo 2: crossing such an edge enters or leaves the
         * polygon.
         */
        bool
        crosses_ring(const HalfedgeHandle &h, const unsigned int n_rings)
        {
          bool odd = false;
          for (const unsigned int id : h->curve().data())
            if (id < n_rings)
              odd = !odd;
          return odd;
        }


        /**
         * Build the arrangement of a polygon's rings and the given segments,
         * and return the faces inside the polygon together with their
         * inside/outside states.
         */
        void
        arrange_polygon(const Polygon                          &polygon,
                        const std::vector<Segment>             &segments,
                        Arrangement                            &arrangement,
                        std::unordered_map<const void *, bool> &inside,
                        std::vector<FaceHandle>                &inside_faces)
        {
          std::vector<ArrangementCurve> curves;
          add_ring_curves(polygon.outer, 0, curves);
          for (unsigned int h = 0; h < polygon.holes.size(); ++h)
            add_ring_curves(polygon.holes[h], h + 1, curves);
          const unsigned int n_rings = polygon.holes.size() + 1;
          for (const Segment &s : segments)
            curves.emplace_back(EK::Segment_2(EK::Point_2(s.a[0], s.a[1]),
                                              EK::Point_2(s.b[0], s.b[1])),
                                n_rings);
          CGAL::insert(arrangement, curves.begin(), curves.end());

          inside = propagate_over_faces(
            arrangement, false, [&](const bool state, const HalfedgeHandle &h) {
              return state != crosses_ring(h, n_rings);
            });
          for (auto face = arrangement.faces_begin();
               face != arrangement.faces_end();
               ++face)
            if (inside.at(&*face))
              inside_faces.push_back(face);
        }


        /**
         * The lowest, then leftmost vertex of a face's outer boundary and the
         * direction in which the boundary leaves it, as a sort key: faces
         * that share their lowest vertex leave it in different directions.
         */
        struct FaceKey
        {
          EK::Point_2 lowest;
          double      angle = 0.;
        };


        FaceKey
        face_key(const FaceHandle &face)
        {
          FaceKey key;
          bool    first = true;
          auto    h     = face->outer_ccb();
          do
            {
              const EK::Point_2 &p = h->source()->point();
              if (first || CGAL::compare_y(p, key.lowest) == CGAL::SMALLER ||
                  (CGAL::compare_y(p, key.lowest) == CGAL::EQUAL &&
                   CGAL::compare_x(p, key.lowest) == CGAL::SMALLER))
                {
                  key.lowest           = p;
                  const EK::Vector_2 d = h->target()->point() - p;
                  key.angle            = std::atan2(to_double_exactly(d.y()),
                                         to_double_exactly(d.x()));
                  first                = false;
                }
          } while (++h != face->outer_ccb());
          return key;
        }

      } // namespace



      Domain
      block_domain(const Polygon &polygon, const BlockDescription &block)
      {
        Arrangement                            arrangement;
        std::unordered_map<const void *, bool> inside;
        std::vector<FaceHandle>                faces;
        arrange_polygon(polygon, block.cracks, arrangement, inside, faces);

        Domain domain = extract_domain(
          faces,
          [&](const FaceHandle &f) { return inside.at(&*f); },
          true,
          polygon.holes.size() + 1);
        domain.name           = block.name;
        domain.material_id    = block.material_id;
        domain.mesh_size      = block.mesh_size;
        domain.target_n_cells = block.target_n_cells;
        return domain;
      }



      std::vector<Domain>
      region_domains(const Polygon &polygon, const RegionDescription &region)
      {
        Arrangement                            arrangement;
        std::unordered_map<const void *, bool> inside;
        std::vector<FaceHandle>                faces;
        arrange_polygon(polygon, region.joints, arrangement, inside, faces);

        std::vector<std::pair<FaceKey, FaceHandle>> keyed;
        for (const FaceHandle &f : faces)
          keyed.emplace_back(face_key(f), f);
        std::stable_sort(
          keyed.begin(), keyed.end(), [](const auto &a, const auto &b) {
            const auto cy = CGAL::compare_y(a.first.lowest, b.first.lowest);
            if (cy != CGAL::EQUAL)
              return cy == CGAL::SMALLER;
            const auto cx = CGAL::compare_x(a.first.lowest, b.first.lowest);
            if (cx != CGAL::EQUAL)
              return cx == CGAL::SMALLER;
            return a.first.angle < b.first.angle;
          });

        std::vector<Domain> domains;
        for (const auto &entry : keyed)
          {
            const FaceHandle face   = entry.second;
            Domain           domain = extract_domain(
              {face},
              [&](const FaceHandle &f) { return f == face; },
              region.keep_dangling_as_cracks,
              polygon.holes.size() + 1);
            domain.name = region.name + "." + std::to_string(domains.size());
            domain.material_id    = region.material_id;
            domain.mesh_size      = region.mesh_size;
            domain.target_n_cells = region.target_n_cells;
            domains.push_back(std::move(domain));
          }
        return domains;
      }
    } // namespace internal
  }   // namespace geometry
} // namespace ndda
