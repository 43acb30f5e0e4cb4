// SPDX-License-Identifier: GPL-3.0-or-later
//
// Input checking of mesh_scene(): the scene's settings, the rings of every
// block and region (closed, finite, simple, holes strictly inside and
// disjoint), the mesh sizes, the cracks of blocks, the joints of regions,
// and that no two blocks or regions overlap. Every refusal is a
// dealii::ExcMessage that names the block or region and the problem.

#include <deal.II/base/exceptions.h>

#include <ndda/geometry/block_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <unordered_map>
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
         * A point of the intersection of two segments that are known to
         * intersect.
         */
        IPoint
        intersection_point(const ISegment &s, const ISegment &t)
        {
          const auto result = CGAL::intersection(s, t);
          Assert(result, dealii::ExcInternalError());
          if (const IPoint *p = boost::get<IPoint>(&*result))
            return *p;
          return boost::get<ISegment>(&*result)->source();
        }


        /**
         * The first point where a ring that is known not to be simple
         * intersects itself. Quadratic, but only called to write the error
         * message.
         */
        IPoint
        first_self_intersection(const std::vector<IPoint> &ring)
        {
          const std::size_t n = ring.size();
          for (std::size_t i = 0; i < n; ++i)
            {
              const ISegment s = ring_edge(ring, i);
              for (std::size_t j = i + 1; j < n; ++j)
                {
                  const ISegment t = ring_edge(ring, j);
                  if (!CGAL::do_overlap(s.bbox(), t.bbox()) ||
                      !CGAL::do_intersect(s, t))
                    continue;
                  const bool adjacent = (j == i + 1) || (i == 0 && j == n - 1);
                  if (!adjacent)
                    return intersection_point(s, t);
                  // Neighbouring edges share a point; they are a defect only
                  // if they fold back onto each other.
                  const auto result = CGAL::intersection(s, t);
                  if (boost::get<ISegment>(&*result) != nullptr)
                    return (j == i + 1) ? ring[j] : ring[0];
                }
            }
          return ring[0];
        }


        /**
         * Check one ring of a polygon and return it without a repeated
         * closing point.
         */
        std::vector<IPoint>
        clean_ring(const std::vector<Point<2>> &input,
                   const std::string           &where,
                   const std::string           &ring_name)
        {
          std::vector<IPoint> ring;
          ring.reserve(input.size());
          for (const auto &p : input)
            {
              AssertThrow(std::isfinite(p[0]) && std::isfinite(p[1]),
                          dealii::ExcMessage(
                            where + ring_name + " has the point " +
                            format_point(p[0], p[1]) +
                            ", which is not finite. Give finite coordinates."));
              ring.emplace_back(p[0], p[1]);
            }
          // Rings may repeat the first point at the end.
          if (ring.size() >= 2 && ring.front() == ring.back())
            ring.pop_back();

          std::vector<IPoint> distinct = ring;
          std::sort(distinct.begin(), distinct.end());
          distinct.erase(std::unique(distinct.begin(), distinct.end()),
                         distinct.end());
          AssertThrow(distinct.size() >= 3,
                      dealii::ExcMessage(
                        where + ring_name + " has " +
                        std::to_string(distinct.size()) +
                        " distinct point(s): the polygon is not closed: it "
                        "needs at least three distinct points. List the "
                        "corners of the polygon in order."));

          const std::size_t n = ring.size();
          for (std::size_t i = 0; i < n; ++i)
            AssertThrow(ring[i] != ring[(i + 1) % n],
                        dealii::ExcMessage(
                          where + ring_name + " repeats the point " +
                          format_point(ring[i]) + " at positions " +
                          std::to_string(i) + " and " +
                          std::to_string((i + 1) % n) +
                          " (counted from 0): consecutive duplicate points are "
                          "not allowed. Remove the repeated point."));

          bool encloses_area = false;
          for (std::size_t i = 2; i < n && !encloses_area; ++i)
            encloses_area = !CGAL::collinear(ring[0], ring[1], ring[i]);
          AssertThrow(encloses_area,
                      dealii::ExcMessage(
                        where + ring_name +
                        " has zero area: all its points lie on one straight "
                        "line through " +
                        format_point(ring[0]) + " and " +
                        format_point(ring[1]) +
                        ". Give a polygon that encloses an area."));

          // (is_simple_2 with an explicit traits object: going through
          // Polygon_2::is_simple() makes GCC 12 warn about the empty traits.)
          AssertThrow(CGAL::is_simple_2(ring.begin(), ring.end(), IK()),
                      dealii::ExcMessage(
                        where + ring_name + " is self-intersecting at " +
                        format_point(first_self_intersection(ring)) +
                        ". Order the points along the boundary so that its "
                        "edges meet only at common end points, or split the "
                        "polygon into several blocks."));
          return ring;
        }


        /**
         * A point where two rings touch or cross, if they do.
         */
        bool
        rings_intersect(const std::vector<IPoint> &a,
                        const std::vector<IPoint> &b,
                        IPoint                    &where)
        {
          if (!CGAL::do_overlap(bbox_of(a), bbox_of(b)))
            return false;
          for (std::size_t i = 0; i < a.size(); ++i)
            {
              const ISegment s     = ring_edge(a, i);
              const auto     s_box = s.bbox();
              for (std::size_t j = 0; j < b.size(); ++j)
                {
                  const ISegment t = ring_edge(b, j);
                  if (CGAL::do_overlap(s_box, t.bbox()) &&
                      CGAL::do_intersect(s, t))
                    {
                      where = intersection_point(s, t);
                      return true;
                    }
                }
            }
          return false;
        }


        /**
         * Holes lie strictly inside the outer ring and are pairwise disjoint
         * (they may not even touch: a hole touching the outer ring or another
         * hole makes a vertex with two separate fans, which the mesh layer
         * would treat as two bodies glued at a point).
         */
        void
        check_holes(const Polygon &polygon)
        {
          const IPolygon outer(polygon.outer.begin(), polygon.outer.end());
          for (std::size_t h = 0; h < polygon.holes.size(); ++h)
            {
              const auto &hole = polygon.holes[h];
              IPoint      p;
              AssertThrow(!rings_intersect(hole, polygon.outer, p),
                          dealii::ExcMessage(
                            polygon.where() + "hole " + std::to_string(h) +
                            " is not strictly inside the outer ring: it "
                            "touches or crosses the outer ring at " +
                            format_point(p) +
                            ". Move the hole inside the outer ring, or make "
                            "the notch part of the outer ring."));
              AssertThrow(
                outer.bounded_side(hole[0]) == CGAL::ON_BOUNDED_SIDE,
                dealii::ExcMessage(
                  polygon.where() + "hole " + std::to_string(h) +
                  " is not strictly inside the outer ring: its point " +
                  format_point(hole[0]) +
                  " lies outside the outer ring. Move the hole "
                  "inside the outer ring."));
            }

          for (std::size_t h = 0; h < polygon.holes.size(); ++h)
            for (std::size_t k = h + 1; k < polygon.holes.size(); ++k)
              {
                const auto &a = polygon.holes[h];
                const auto &b = polygon.holes[k];
                IPoint      p;
                const bool  touch = rings_intersect(a, b, p);
                if (!touch)
                  {
                    const IPolygon pa(a.begin(), a.end());
                    const IPolygon pb(b.begin(), b.end());
                    if (pa.bounded_side(b[0]) == CGAL::ON_BOUNDED_SIDE)
                      p = b[0];
                    else if (pb.bounded_side(a[0]) == CGAL::ON_BOUNDED_SIDE)
                      p = a[0];
                    else
                      continue;
                  }
                AssertThrow(false,
                            dealii::ExcMessage(
                              polygon.where() + "holes " + std::to_string(h) +
                              " and " + std::to_string(k) +
                              " overlap or touch at " + format_point(p) +
                              ". Holes must be disjoint: merge the two holes "
                              "into one or move them apart."));
              }
        }


        /**
         * Whether a point lies in the closed (or, with @p strict, the open)
         * region of a polygon with holes.
         */
        bool
        polygon_contains(const IPolygon              &outer,
                         const std::vector<IPolygon> &holes,
                         const IPoint                &p,
                         const bool                   strict)
        {
          const CGAL::Bounded_side side = outer.bounded_side(p);
          if (side == CGAL::ON_UNBOUNDED_SIDE ||
              (strict && side == CGAL::ON_BOUNDARY))
            return false;
          for (const auto &hole : holes)
            {
              const CGAL::Bounded_side hole_side = hole.bounded_side(p);
              if (hole_side == CGAL::ON_BOUNDED_SIDE ||
                  (strict && hole_side == CGAL::ON_BOUNDARY))
                return false;
            }
          return true;
        }


        /**
         * A crack whose end points lie in the closed block still has to stay
         * in it: cut the crack where it touches the boundary; every piece in
         * between must lie in the open block, and no piece may run along the
         * boundary.
         */
        void
        check_crack_stays_inside(
          const Polygon                                  &polygon,
          const IPolygon                                 &outer,
          const std::vector<IPolygon>                    &holes,
          const std::vector<const std::vector<IPoint> *> &rings,
          const IPoint                                   &p,
          const IPoint                                   &q,
          const std::string                              &name)
        {
          const ISegment      s(p, q);
          const auto          s_box   = s.bbox();
          std::vector<double> cuts    = {0., 1.};
          const double        length2 = CGAL::to_double(s.squared_length());
          for (const auto *ring : rings)
            for (std::size_t i = 0; i < ring->size(); ++i)
              {
                const ISegment e = ring_edge(*ring, i);
                if (!CGAL::do_overlap(s_box, e.bbox()) ||
                    !CGAL::do_intersect(s, e))
                  continue;
                const auto result = CGAL::intersection(s, e);
                if (const ISegment *overlap = boost::get<ISegment>(&*result))
                  AssertThrow(false,
                              dealii::ExcMessage(
                                polygon.where() + name +
                                " is not inside the block: it runs along "
                                "the block boundary from " +
                                format_point(overlap->source()) + " to " +
                                format_point(overlap->target()) +
                                ". Remove it: the boundary is free "
                                "already."));
                const IPoint x = *boost::get<IPoint>(&*result);
                cuts.push_back(CGAL::to_double((x - p) * (q - p)) / length2);
              }
          std::sort(cuts.begin(), cuts.end());
          for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
            {
              if (cuts[i + 1] - cuts[i] < 1e-12)
                continue;
              const double t = 0.5 * (cuts[i] + cuts[i + 1]);
              const IPoint m = p + t * (q - p);
              AssertThrow(polygon_contains(outer, holes, m, true),
                          dealii::ExcMessage(
                            polygon.where() + name +
                            " is not inside the block: it leaves the block "
                            "near " +
                            format_point(m) +
                            ". Cracks must lie in the block; they may end "
                            "on its boundary."));
            }
        }


        /**
         * Every crack has a length and lies in the closed block: it may end
         * on the boundary, but it may neither leave the block nor run along
         * its boundary.
         */
        void
        check_cracks(const Polygon &polygon, const std::vector<Segment> &cracks)
        {
          const IPolygon outer(polygon.outer.begin(), polygon.outer.end());
          std::vector<IPolygon> holes;
          for (const auto &h : polygon.holes)
            holes.emplace_back(h.begin(), h.end());
          std::vector<const std::vector<IPoint> *> rings = {&polygon.outer};
          for (const auto &h : polygon.holes)
            rings.push_back(&h);

          for (std::size_t c = 0; c < cracks.size(); ++c)
            {
              const Segment    &crack = cracks[c];
              const IPoint      p(crack.a[0], crack.a[1]);
              const IPoint      q(crack.b[0], crack.b[1]);
              const std::string name = "crack " + std::to_string(c) + " from " +
                                       format_point(p) + " to " +
                                       format_point(q);
              AssertThrow(std::isfinite(p.x()) && std::isfinite(p.y()) &&
                            std::isfinite(q.x()) && std::isfinite(q.y()),
                          dealii::ExcMessage(
                            polygon.where() + name +
                            " has coordinates that are not "
                            "finite. Give finite coordinates."));
              AssertThrow(std::sqrt(CGAL::squared_distance(p, q)) >
                            1e-12 * polygon.diameter,
                          dealii::ExcMessage(
                            polygon.where() + name +
                            " is degenerate: it has zero length. Remove it or "
                            "give two different end points."));
              for (const IPoint &end : {p, q})
                AssertThrow(polygon_contains(outer, holes, end, false),
                            dealii::ExcMessage(
                              polygon.where() + name +
                              " is not inside the block: its end point " +
                              format_point(end) +
                              " lies outside the block. Cracks must lie in the "
                              "block; they may end on its boundary."));
              check_crack_stays_inside(
                polygon, outer, holes, rings, p, q, name);
            }
        }


        /**
         * Validate the rings of a block or region.
         */
        Polygon
        make_polygon(const std::string                        &kind,
                     const std::string                        &name,
                     const std::vector<Point<2>>              &outer,
                     const std::vector<std::vector<Point<2>>> &holes)
        {
          Polygon polygon;
          polygon.kind  = kind;
          polygon.name  = name;
          polygon.outer = clean_ring(outer, polygon.where(), "the outer ring");
          for (std::size_t h = 0; h < holes.size(); ++h)
            polygon.holes.push_back(clean_ring(holes[h],
                                               polygon.where(),
                                               "hole " + std::to_string(h)));
          polygon.diameter = diagonal(bbox_of(polygon.outer));
          check_holes(polygon);
          return polygon;
        }


        void
        check_mesh_size(const Polygon     &polygon,
                        const double       mesh_size,
                        const unsigned int target_n_cells)
        {
          AssertThrow(std::isfinite(mesh_size) && mesh_size >= 0.,
                      dealii::ExcMessage(
                        polygon.where() + "the mesh size is " +
                        std::to_string(mesh_size) +
                        ". Give a positive mesh size (longest triangle edge, "
                        "m), or zero to use the target number of cells."));
          AssertThrow(mesh_size > 0. || target_n_cells > 0,
                      dealii::ExcMessage(
                        polygon.where() +
                        "neither a mesh size nor a target number of cells is "
                        "given (mesh size 0, target number of cells 0). Set a "
                        "positive mesh size (longest triangle edge, m) or a "
                        "positive target number of cells."));
        }


        /**
         * No two blocks or regions may overlap; touching along edges or at
         * points is fine. All rings go into one arrangement; every face knows
         * the set of polygons it lies in (crossing an edge of a ring of a
         * polygon toggles that polygon), and a face in two polygons is an
         * overlap, unless it is thinner than @p thin (m): twice its area over
         * its perimeter, the width of a sliver, is at most @p thin. Corners
         * computed by trigonometry lie a rounding error off the edge they
         * should lie on.
         */
        void
        check_overlaps(const std::vector<Polygon> &polygons, const double thin)
        {
          if (polygons.size() < 2)
            return;
          std::vector<unsigned int>     ring_owner;
          std::vector<ArrangementCurve> curves;
          for (unsigned int k = 0; k < polygons.size(); ++k)
            {
              add_ring_curves(polygons[k].outer, ring_owner.size(), curves);
              ring_owner.push_back(k);
              for (const auto &hole : polygons[k].holes)
                {
                  add_ring_curves(hole, ring_owner.size(), curves);
                  ring_owner.push_back(k);
                }
            }
          Arrangement arrangement;
          CGAL::insert(arrangement, curves.begin(), curves.end());

          using Owners      = std::vector<unsigned int>;
          const auto states = propagate_over_faces(
            arrangement, Owners(), [&](Owners owners, const HalfedgeHandle &h) {
              for (const unsigned int ring : h->curve().data())
                {
                  const unsigned int owner = ring_owner[ring];
                  const auto         it =
                    std::lower_bound(owners.begin(), owners.end(), owner);
                  if (it != owners.end() && *it == owner)
                    owners.erase(it);
                  else
                    owners.insert(it, owner);
                }
              return owners;
            });

          for (auto face = arrangement.faces_begin();
               face != arrangement.faces_end();
               ++face)
            {
              const Owners &owners = states.at(&*face);
              if (owners.size() < 2)
                continue;
              if (thin > 0 && face->has_outer_ccb())
                {
                  double     area = 0, perimeter = 0;
                  const auto first = face->outer_ccb();
                  auto       h     = first;
                  do
                    {
                      const auto  &a  = h->source()->point();
                      const auto  &b  = h->target()->point();
                      const double ax = CGAL::to_double(a.x()),
                                   ay = CGAL::to_double(a.y()),
                                   bx = CGAL::to_double(b.x()),
                                   by = CGAL::to_double(b.y());
                      area += 0.5 * (ax * by - ay * bx);
                      perimeter += std::hypot(bx - ax, by - ay);
                  } while (++h != first);
                  if (2. * std::abs(area) <= thin * perimeter)
                    continue;
                }
              const Polygon &a = polygons[owners[0]];
              const Polygon &b = polygons[owners[1]];
              AssertThrow(false,
                          dealii::ExcMessage(
                            a.where() + "overlaps " + b.kind + " '" + b.name +
                            "': their interiors intersect in a region with a "
                            "corner at " +
                            format_point(face->outer_ccb()->source()->point()) +
                            ". Blocks and regions may touch but not overlap: "
                            "fix their outlines, or cut one region by joints "
                            "instead of giving overlapping blocks."));
            }
        }


        /**
         * Every joint of a region has finite coordinates and a length.
         */
        void
        check_joints(const Polygon &polygon, const std::vector<Segment> &joints)
        {
          for (std::size_t j = 0; j < joints.size(); ++j)
            {
              const Segment &joint = joints[j];
              AssertThrow(std::isfinite(joint.a[0]) &&
                            std::isfinite(joint.a[1]) &&
                            std::isfinite(joint.b[0]) &&
                            std::isfinite(joint.b[1]),
                          dealii::ExcMessage(
                            polygon.where() + "joint " + std::to_string(j) +
                            " has coordinates that are not finite. Give "
                            "finite coordinates."));
              AssertThrow(joint.a.distance(joint.b) > 1e-12 * polygon.diameter,
                          dealii::ExcMessage(
                            polygon.where() + "joint " + std::to_string(j) +
                            " from " + format_point(joint.a[0], joint.a[1]) +
                            " to " + format_point(joint.b[0], joint.b[1]) +
                            " is degenerate: it has zero length. Remove it "
                            "or give two different end points."));
            }
        }


        /**
         * The settings of the whole scene: something to mesh, a minimum
         * angle for which the refinement finishes, finite required vertices.
         */
        void
        check_scene_settings(const SceneGeometry &geometry)
        {
          AssertThrow(!geometry.blocks.empty() || !geometry.regions.empty(),
                      dealii::ExcMessage(
                        "Geometry: the scene has neither blocks nor regions. "
                        "Describe at least one block or region."));
          AssertThrow(geometry.min_angle > 0. && geometry.min_angle <= 33.,
                      dealii::ExcMessage(
                        "Geometry: the minimum angle of the mesh is " +
                        std::to_string(geometry.min_angle) +
                        " degrees. Give a value in (0, 33]; 30 is the usual "
                        "choice (Delaunay refinement does not finish for much "
                        "larger angles)."));
          for (std::size_t i = 0; i < geometry.required_vertices.size(); ++i)
            {
              const auto &p = geometry.required_vertices[i];
              AssertThrow(std::isfinite(p[0]) && std::isfinite(p[1]),
                          dealii::ExcMessage(
                            "Geometry: required vertex " + std::to_string(i) +
                            " " + format_point(p[0], p[1]) +
                            " is not finite. Give finite coordinates."));
            }
        }
      } // namespace



      namespace
      {
        double
        ring_area(const std::vector<IPoint> &ring)
        {
          double twice = 0;
          for (std::size_t i = 0; i < ring.size(); ++i)
            {
              const IPoint &a = ring[i], &b = ring[(i + 1) % ring.size()];
              twice += CGAL::to_double(a.x()) * CGAL::to_double(b.y()) -
                       CGAL::to_double(b.x()) * CGAL::to_double(a.y());
            }
          return std::abs(twice) / 2.;
        }



        /**
         * Refuse, before meshing, a scene whose blocks need more cells
         * than Geometry/Maximum number of cells: a mesh size far too small
         * would otherwise hang in the mesher with no word. The estimate is
         * a lower bound: no triangle with a longest edge h has more area
         * than the equilateral one, sqrt(3)/4 h^2.
         */
        void
        check_cell_count(const SceneGeometry        &geometry,
                         const std::vector<Polygon> &polygons)
        {
          std::vector<std::pair<double, std::string>> counts;
          double                                      total = 0;
          const auto add = [&](const Polygon     &polygon,
                               const double       mesh_size,
                               const unsigned int target_n_cells) {
            double area = ring_area(polygon.outer);
            for (const auto &hole : polygon.holes)
              area -= ring_area(hole);
            const double n =
              mesh_size > 0. ?
                area / (std::sqrt(3.) / 4. * mesh_size * mesh_size) :
                double(target_n_cells);
            std::ostringstream what;
            what << polygon.kind << " '" << polygon.name << "': area " << area
                 << " m^2, ";
            if (mesh_size > 0.)
              what << "mesh size " << mesh_size << " m";
            else
              what << "target number of elements " << target_n_cells;
            counts.emplace_back(n, what.str());
            total += n;
          };
          for (std::size_t b = 0; b < geometry.blocks.size(); ++b)
            add(polygons[b],
                geometry.blocks[b].mesh_size,
                geometry.blocks[b].target_n_cells);
          for (std::size_t r = 0; r < geometry.regions.size(); ++r)
            add(polygons[geometry.blocks.size() + r],
                geometry.regions[r].mesh_size,
                geometry.regions[r].target_n_cells);
          if (total <= geometry.max_cells)
            return;
          std::sort(counts.begin(), counts.end(), std::greater<>());
          std::ostringstream message;
          message << std::setprecision(3) << "Geometry: the scene needs at "
                  << "least " << total << " cells, more than Geometry/Maximum "
                  << "number of cells = " << geometry.max_cells
                  << " (a P1 cell takes about 6 kB in a run). The largest: ";
          for (std::size_t i = 0; i < std::min<std::size_t>(3, counts.size());
               ++i)
            message << (i > 0 ? "; " : "") << counts[i].second
                    << " -> at least " << counts[i].first << " cells";
          message << ". Give a larger mesh size, or raise the limit if the "
                     "machine holds such a scene.";
          AssertThrow(false, dealii::ExcMessage(message.str()));
        }
      } // namespace



      std::vector<Polygon>
      validate_scene(const SceneGeometry &geometry)
      {
        check_scene_settings(geometry);

        std::vector<Polygon> polygons;
        for (const auto &block : geometry.blocks)
          {
            polygons.push_back(
              make_polygon("block", block.name, block.outer, block.holes));
            check_mesh_size(polygons.back(),
                            block.mesh_size,
                            block.target_n_cells);
            check_cracks(polygons.back(), block.cracks);
          }
        for (const auto &region : geometry.regions)
          {
            polygons.push_back(
              make_polygon("region", region.name, region.outer, region.holes));
            check_mesh_size(polygons.back(),
                            region.mesh_size,
                            region.target_n_cells);
            check_joints(polygons.back(), region.joints);
          }
        check_cell_count(geometry, polygons);
        check_overlaps(polygons,
                       geometry.snap_tolerance * scene_size(geometry));
        return polygons;
      }



      double
      scene_size(const SceneGeometry &geometry)
      {
        const double infinity = std::numeric_limits<double>::infinity();
        Point<2>     lower(infinity, infinity), upper(-infinity, -infinity);
        const auto   add = [&](const std::vector<Point<2>> &ring) {
          for (const auto &p : ring)
            if (std::isfinite(p[0]) && std::isfinite(p[1]))
              for (unsigned int d = 0; d < 2; ++d)
                {
                  lower[d] = std::min(lower[d], p[d]);
                  upper[d] = std::max(upper[d], p[d]);
                }
        };
        for (const auto &block : geometry.blocks)
          add(block.outer);
        for (const auto &region : geometry.regions)
          add(region.outer);
        return lower[0] <= upper[0] ? upper.distance(lower) : 0.;
      }



      SceneGeometry
      snap_corners(SceneGeometry geometry)
      {
        const double tolerance = geometry.snap_tolerance;
        AssertThrow(tolerance >= 0 && tolerance <= 1e-3,
                    dealii::ExcMessage(
                      "Geometry/Snapping tolerance: " +
                      std::to_string(tolerance) +
                      " is not in [0, 1e-3]. It is relative to the scene's "
                      "size; the default 1e-9 covers rounding errors."));
        const double h = tolerance * scene_size(geometry);
        if (!(h > 0) || !std::isfinite(h))
          return geometry;

        // The rings in input order, each with its owner.
        std::vector<std::pair<unsigned int, std::vector<Point<2>> *>> rings;
        unsigned int                                                  owner = 0;
        for (auto &block : geometry.blocks)
          {
            rings.emplace_back(owner, &block.outer);
            for (auto &hole : block.holes)
              rings.emplace_back(owner, &hole);
            ++owner;
          }
        for (auto &region : geometry.regions)
          {
            rings.emplace_back(owner, &region.outer);
            for (auto &hole : region.holes)
              rings.emplace_back(owner, &hole);
            ++owner;
          }

        // A hash grid of cells of size h: a corner's match lies in one of
        // the nine cells around its own.
        struct Corner
        {
          Point<2>     position;
          unsigned int owner;
        };
        std::unordered_map<std::uint64_t, std::vector<Corner>> grid;
        const auto key = [](const std::int64_t i, const std::int64_t j) {
          return (static_cast<std::uint64_t>(i) << 32) ^
                 static_cast<std::uint64_t>(j & 0xffffffff);
        };
        for (auto &[ring_owner, ring] : rings)
          for (auto &p : *ring)
            {
              if (!std::isfinite(p[0]) || !std::isfinite(p[1]) ||
                  std::abs(p[0]) / h > 1e15 || std::abs(p[1]) / h > 1e15)
                continue;
              const auto    i = static_cast<std::int64_t>(std::floor(p[0] / h));
              const auto    j = static_cast<std::int64_t>(std::floor(p[1] / h));
              const Corner *match = nullptr;
              for (std::int64_t di = -1; di <= 1 && !match; ++di)
                for (std::int64_t dj = -1; dj <= 1 && !match; ++dj)
                  if (const auto cell = grid.find(key(i + di, j + dj));
                      cell != grid.end())
                    for (const auto &c : cell->second)
                      if (c.owner != ring_owner && c.position.distance(p) <= h)
                        {
                          match = &c;
                          break;
                        }
              if (match)
                p = match->position;
              else
                grid[key(i, j)].push_back({p, ring_owner});
            }
        return geometry;
      }
    } // namespace internal
  }   // namespace geometry
} // namespace ndda
