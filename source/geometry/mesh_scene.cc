// SPDX-License-Identifier: GPL-3.0-or-later
//
// From scene geometry to a BlockMesh: validation of the polygons, block
// cutting of regions by joints (CGAL Arrangement_2), and meshing of every
// block on its own (CGAL constrained Delaunay mesher). All CGAL code of ndda
// lives in this translation unit; nothing of it leaks into a header.
//
// Two kernels are used on purpose:
//  - the exact-constructions kernel (EK) for the arrangements, because joint
//    intersections are new points whose exact position decides the topology
//    of the blocks;
//  - the exact-predicates kernel (IK) for the validation and the meshing:
//    its predicates are exact, and the mesher's Steiner points are rounded
//    anyway.
// The vertices of the cut blocks are rounded to double once, when a block
// leaves the arrangement; two blocks that share a joint see the same rounded
// points.
//
// Decisions that the header leaves open:
//  - BlockMesh::crack_edges holds the faces of explicit cracks and of kept
//    dangling joints, that is the edges that were split. Joint faces between
//    two blocks cut from one region are ordinary block boundaries (the two
//    blocks have different names "<region>.<k>"), not crack edges.
//  - Blocks are numbered: explicit blocks in input order, then the blocks of
//    every region in input order, each region's blocks sorted by their
//    lowest, then leftmost vertex.
//  - Every block is meshed alone, so the vertices on a joint shared by two
//    blocks need not match: blocks are separate bodies that touch.
//  - With a minimum angle above 20.7 degrees Delaunay refinement is not
//    proven to terminate. A block whose refinement runs past a step budget
//    is meshed again with 20.7 degrees, and a warning goes to std::cerr.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/types.h>

#include <ndda/geometry/block_mesh.h>

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <queue>
#include <sstream>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace ndda
{
  namespace geometry
  {
    namespace
    {
      using IK       = CGAL::Exact_predicates_inexact_constructions_kernel;
      using EK       = CGAL::Exact_predicates_exact_constructions_kernel;
      using IPoint   = IK::Point_2;
      using ISegment = IK::Segment_2;
      using IPolygon = CGAL::Polygon_2<IK>;

      // Every curve of an arrangement carries an id: the index of the ring
      // it comes from, or a larger number for joints and cracks. Where
      // curves overlap, the ids are consolidated into one list per edge.
      using ArrangementTraits = CGAL::Arr_consolidated_curve_data_traits_2<
        CGAL::Arr_segment_traits_2<EK>,
        unsigned int>;
      using Arrangement      = CGAL::Arrangement_2<ArrangementTraits>;
      using ArrangementCurve = ArrangementTraits::Curve_2;
      using FaceHandle       = Arrangement::Face_const_handle;
      using HalfedgeHandle   = Arrangement::Halfedge_const_handle;
      using VertexHandle     = Arrangement::Vertex_const_handle;

      using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<
        unsigned int,
        IK,
        CGAL::Delaunay_mesh_vertex_base_2<IK>>;
      using FaceBase = CGAL::Delaunay_mesh_face_base_2<IK>;
      using TriangulationDataStructure =
        CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
      using CDT =
        CGAL::Constrained_Delaunay_triangulation_2<IK,
                                                   TriangulationDataStructure,
                                                   CGAL::Exact_predicates_tag>;
      using MeshCriteria = CGAL::Delaunay_mesh_size_criteria_2<CDT>;
      using Mesher       = CGAL::Delaunay_mesher_2<CDT, MeshCriteria>;

      using Edge = std::array<unsigned int, 2>;

      /**
       * Shape bound for which CGAL's Delaunay refinement is proven to
       * terminate: sin^2(20.7 degrees).
       */
      constexpr double guaranteed_shape_bound = 0.125;

      /**
       * Ratio of the size bound S (longest edge) to the edge length of an
       * equilateral triangle of the wanted area: the mesher's triangles are
       * smaller than the bound, so the bound has to be larger than the mean
       * edge to get about target_n_cells triangles. Measured on a square, a
       * 64-gon and a 8:1 rectangle: within 5 % from 400 to 100000 cells
       * (coarser meshes are ruled by the boundary).
       */
      constexpr double size_bound_over_mean_edge = 1.47;


      std::string
      format_point(const double x, const double y)
      {
        std::ostringstream s;
        s << std::setprecision(10) << "(" << x << ", " << y << ")";
        return s.str();
      }


      std::string
      format_point(const IPoint &p)
      {
        return format_point(p.x(), p.y());
      }


      /**
       * Round an exact number to double from its exact value. Plain
       * CGAL::to_double() of a lazy number returns the middle of its current
       * interval, which gets narrower once anything has asked for the exact
       * value (CGAL's own assertions in a Debug build do): the rounded
       * points, and so the meshes, would depend on the build type.
       */
      double
      to_double_exactly(const EK::FT &x)
      {
        return CGAL::to_double(CGAL::exact(x));
      }


      std::string
      format_point(const EK::Point_2 &p)
      {
        return format_point(to_double_exactly(p.x()), to_double_exactly(p.y()));
      }


      /**
       * A validated block or region polygon. Rings have at least three
       * points, no repeated closing point and no consecutive duplicates,
       * and are simple.
       */
      struct Polygon
      {
        /// "block" or "region", for messages.
        std::string                      kind;
        std::string                      name;
        std::vector<IPoint>              outer;
        std::vector<std::vector<IPoint>> holes;
        /// Diagonal of the bounding box of the outer ring.
        double diameter = 0.;

        /** Start of every error message about this polygon. */
        std::string
        where() const
        {
          return "Geometry: " + kind + " '" + name + "': ";
        }
      };


      /**
       * The geometry of one block as it goes into the mesher: points, the
       * boundary edges (oriented so that the block lies to their left) and
       * the crack edges. Edges do not cross and do not contain points in
       * their interior.
       */
      struct Domain
      {
        std::string         name;
        unsigned int        material_id    = 0;
        double              mesh_size      = 0.;
        unsigned int        target_n_cells = 0;
        std::vector<IPoint> points;
        std::vector<Edge>   boundary;
        std::vector<Edge>   cracks;
        double              area     = 0.;
        double              diameter = 0.;
      };


      CGAL::Bbox_2
      bbox_of(const std::vector<IPoint> &points)
      {
        return CGAL::bbox_2(points.begin(), points.end());
      }


      double
      diagonal(const CGAL::Bbox_2 &box)
      {
        return std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin());
      }


      ISegment
      ring_edge(const std::vector<IPoint> &ring, const std::size_t i)
      {
        return ISegment(ring[i], ring[(i + 1) % ring.size()]);
      }


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
                      format_point(ring[0]) + " and " + format_point(ring[1]) +
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
            AssertThrow(outer.bounded_side(hole[0]) == CGAL::ON_BOUNDED_SIDE,
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
       * Every crack has a length and lies in the closed block: it may end
       * on the boundary, but it may neither leave the block nor run along
       * its boundary.
       */
      void
      check_cracks(const Polygon &polygon, const std::vector<Segment> &cracks)
      {
        const IPolygon        outer(polygon.outer.begin(), polygon.outer.end());
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
                                     format_point(p) + " to " + format_point(q);
            AssertThrow(std::isfinite(p.x()) && std::isfinite(p.y()) &&
                          std::isfinite(q.x()) && std::isfinite(q.y()),
                        dealii::ExcMessage(polygon.where() + name +
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

            // Cut the crack where it touches the boundary; every piece in
            // between must lie in the open block.
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
          polygon.holes.push_back(
            clean_ring(holes[h], polygon.where(), "hole " + std::to_string(h)));
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
       * Call @p f for every halfedge on the boundary of @p face: outer CCBs
       * first, then the inner ones (holes, dangling edges). The face lies to
       * the left of every such halfedge.
       */
      template <typename Function>
      void
      for_each_boundary_halfedge(const FaceHandle &face, const Function &f)
      {
        for (auto ccb = face->outer_ccbs_begin(); ccb != face->outer_ccbs_end();
             ++ccb)
          {
            auto h = *ccb;
            do
              f(HalfedgeHandle(h));
            while (++h != *ccb);
          }
        for (auto ccb = face->inner_ccbs_begin(); ccb != face->inner_ccbs_end();
             ++ccb)
          {
            auto h = *ccb;
            do
              f(HalfedgeHandle(h));
            while (++h != *ccb);
          }
      }


      /**
       * Give every face of an arrangement a state by a breadth-first walk
       * from the unbounded face: the state of the face across a halfedge is
       * `transition(state, halfedge)`. Used for the inside/outside parity
       * of polygons with holes, which is what the arrangement itself does
       * not know.
       */
      template <typename State, typename Transition>
      std::unordered_map<const void *, State>
      propagate_over_faces(const Arrangement &arrangement,
                           const State       &outside,
                           const Transition  &transition)
      {
        std::unordered_map<const void *, State> states;
        std::queue<FaceHandle>                  queue;
        const FaceHandle unbounded = arrangement.unbounded_face();
        states.emplace(&*unbounded, outside);
        queue.push(unbounded);
        while (!queue.empty())
          {
            const FaceHandle face = queue.front();
            queue.pop();
            const State state = states.at(&*face);
            for_each_boundary_halfedge(face, [&](const HalfedgeHandle &h) {
              const FaceHandle other = h->twin()->face();
              if (states.count(&*other) == 0)
                {
                  states.emplace(&*other, transition(state, h));
                  queue.push(other);
                }
            });
          }
        return states;
      }


      EK::Point_2
      exact_point(const IPoint &p)
      {
        return EK::Point_2(p.x(), p.y());
      }


      /**
       * Add the edges of a ring to @p curves, all with the curve id @p id.
       */
      void
      add_ring_curves(const std::vector<IPoint>     &ring,
                      const unsigned int             id,
                      std::vector<ArrangementCurve> &curves)
      {
        for (std::size_t i = 0; i < ring.size(); ++i)
          curves.emplace_back(EK::Segment_2(exact_point(ring[i]),
                                            exact_point(
                                              ring[(i + 1) % ring.size()])),
                              id);
      }


      /**
       * No two blocks or regions may overlap; touching along edges or at
       * points is fine. All rings go into one arrangement; every face knows
       * the set of polygons it lies in (crossing an edge of a ring of a
       * polygon toggles that polygon), and a face in two polygons is an
       * overlap.
       */
      void
      check_overlaps(const std::vector<Polygon> &polygons)
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
       * Collect the boundary and crack edges of a set of arrangement faces
       * into a Domain. A halfedge whose other side is in the set too is a
       * crack (or a dangling joint); otherwise it is a boundary edge.
       */
      template <typename InGroup>
      Domain
      extract_domain(const std::vector<FaceHandle> &faces,
                     const InGroup                 &in_group,
                     const bool                     keep_cracks)
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
              domain.boundary.push_back(
                {{index_of(h->source()), index_of(h->target())}});
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

        inside =
          propagate_over_faces(arrangement,
                               false,
                               [&](const bool state, const HalfedgeHandle &h) {
                                 return state != crosses_ring(h, n_rings);
                               });
        for (auto face = arrangement.faces_begin();
             face != arrangement.faces_end();
             ++face)
          if (inside.at(&*face))
            inside_faces.push_back(face);
      }


      /**
       * An explicit block: all faces inside the polygon form one domain;
       * crack segments (and the edges between faces that cracks separate)
       * become crack edges.
       */
      Domain
      block_domain(const Polygon &polygon, const BlockDescription &block)
      {
        Arrangement                            arrangement;
        std::unordered_map<const void *, bool> inside;
        std::vector<FaceHandle>                faces;
        arrange_polygon(polygon, block.cracks, arrangement, inside, faces);

        Domain domain = extract_domain(
          faces, [&](const FaceHandle &f) { return inside.at(&*f); }, true);
        domain.name           = block.name;
        domain.material_id    = block.material_id;
        domain.mesh_size      = block.mesh_size;
        domain.target_n_cells = block.target_n_cells;
        return domain;
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


      /**
       * Cut a region into blocks: every face of the arrangement of its
       * rings and joints that lies inside the region is one block, numbered
       * by its lowest-then-leftmost vertex.
       */
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
              region.keep_dangling_as_cracks);
            domain.name = region.name + "." + std::to_string(domains.size());
            domain.material_id    = region.material_id;
            domain.mesh_size      = region.mesh_size;
            domain.target_n_cells = region.target_n_cells;
            domains.push_back(std::move(domain));
          }
        return domains;
      }


      /**
       * Parity of the crossings of a ray from @p p in +x direction with the
       * boundary edges: whether @p p lies in the domain. The half-open rule
       * on y counts a ray through a vertex once; the orientation predicate
       * is exact.
       */
      bool
      domain_contains(const std::vector<IPoint> &points,
                      const std::vector<Edge>   &boundary,
                      const IPoint              &p)
      {
        bool in = false;
        for (const Edge &e : boundary)
          {
            const IPoint &a = points[e[0]];
            const IPoint &b = points[e[1]];
            if ((a.y() > p.y()) != (b.y() > p.y()))
              {
                const CGAL::Orientation o = CGAL::orientation(a, b, p);
                if (b.y() > a.y() ? o == CGAL::LEFT_TURN :
                                    o == CGAL::RIGHT_TURN)
                  in = !in;
              }
          }
        return in;
      }


      /**
       * Make the required vertices that lie in the closed domain part of
       * it: points within @p tolerance of an existing point are dropped,
       * points within @p tolerance of an edge split that edge (at their
       * projection, so that the edge stays straight up to round-off), and
       * points inside become free points.
       */
      void
      add_required_vertices(Domain                      &domain,
                            const std::vector<Point<2>> &required,
                            const double                 tolerance)
      {
        if (required.empty())
          return;
        const double tolerance2 = tolerance * tolerance;
        const auto   box        = bbox_of(domain.points);

        // Split points per edge: (parameter, point index).
        using Splits =
          std::vector<std::vector<std::pair<double, unsigned int>>>;
        Splits boundary_splits(domain.boundary.size());
        Splits crack_splits(domain.cracks.size());

        for (const auto &r : required)
          {
            const IPoint p(r[0], r[1]);
            if (!std::isfinite(p.x()) || !std::isfinite(p.y()) ||
                p.x() < box.xmin() - tolerance ||
                p.x() > box.xmax() + tolerance ||
                p.y() < box.ymin() - tolerance ||
                p.y() > box.ymax() + tolerance)
              continue;
            if (std::any_of(domain.points.begin(),
                            domain.points.end(),
                            [&](const IPoint &q) {
                              return CGAL::squared_distance(p, q) <= tolerance2;
                            }))
              continue;

            bool on_edge = false;
            for (auto [edges, splits] :
                 {std::make_pair(&domain.boundary, &boundary_splits),
                  std::make_pair(&domain.cracks, &crack_splits)})
              for (std::size_t k = 0; k < edges->size() && !on_edge; ++k)
                {
                  const IPoint  &a = domain.points[(*edges)[k][0]];
                  const IPoint  &b = domain.points[(*edges)[k][1]];
                  const ISegment s(a, b);
                  if (CGAL::squared_distance(s, p) > tolerance2)
                    continue;
                  const double t = CGAL::to_double((p - a) * (b - a)) /
                                   CGAL::to_double(s.squared_length());
                  (*splits)[k].emplace_back(t, domain.points.size());
                  domain.points.push_back(
                    CGAL::collinear(a, b, p) ? p : a + t * (b - a));
                  on_edge = true;
                }
            if (!on_edge && domain_contains(domain.points, domain.boundary, p))
              domain.points.push_back(p);
          }

        const auto apply = [](std::vector<Edge> &edges, Splits &splits) {
          std::vector<Edge> result;
          for (std::size_t k = 0; k < edges.size(); ++k)
            {
              std::sort(splits[k].begin(), splits[k].end());
              unsigned int from = edges[k][0];
              for (const auto &split : splits[k])
                {
                  result.push_back({{from, split.second}});
                  from = split.second;
                }
              result.push_back({{from, edges[k][1]}});
            }
          edges = std::move(result);
        };
        apply(domain.boundary, boundary_splits);
        apply(domain.cracks, crack_splits);
      }


      /**
       * Mark the faces of the constrained triangulation that lie in the
       * domain. The constrained edges cut the triangulation into connected
       * components; the component of the infinite face is outside, and
       * every other component is inside if one of its faces is (parity test
       * against the boundary edges only, so that cracks, which have the
       * domain on both sides, do not count).
       */
      void
      mark_domain(CDT &cdt, const Domain &domain)
      {
        for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
          f->set_in_domain(false);

        std::unordered_set<const void *> visited;
        for (auto seed = cdt.all_faces_begin(); seed != cdt.all_faces_end();
             ++seed)
          {
            if (visited.count(&*seed) != 0)
              continue;
            std::vector<CDT::Face_handle> component = {seed};
            visited.insert(&*seed);
            bool touches_infinity = false;
            for (std::size_t i = 0; i < component.size(); ++i)
              {
                const CDT::Face_handle f = component[i];
                touches_infinity = touches_infinity || cdt.is_infinite(f);
                for (int j = 0; j < 3; ++j)
                  if (!f->is_constrained(j) &&
                      visited.insert(&*f->neighbor(j)).second)
                    component.push_back(f->neighbor(j));
              }
            if (touches_infinity)
              continue;

            // The largest face has the most robust centroid.
            CDT::Face_handle largest      = component[0];
            double           largest_area = -1.;
            for (const auto &f : component)
              {
                const double area = CGAL::to_double(cdt.triangle(f).area());
                if (area > largest_area)
                  {
                    largest_area = area;
                    largest      = f;
                  }
              }
            const IPoint centroid = CGAL::centroid(largest->vertex(0)->point(),
                                                   largest->vertex(1)->point(),
                                                   largest->vertex(2)->point());
            if (domain_contains(domain.points, domain.boundary, centroid))
              for (const auto &f : component)
                f->set_in_domain(true);
          }
      }


      /**
       * Build the constrained triangulation of a domain, mark the domain,
       * and refine it. Returns false if the refinement needed more than
       * @p max_steps steps (Delaunay refinement with a shape bound above
       * sin^2(20.7 degrees) is not proven to terminate).
       */
      bool
      refine(const Domain     &domain,
             const double      shape_bound,
             const double      size_bound,
             const std::size_t max_steps,
             CDT              &cdt)
      {
        cdt.clear();
        std::vector<CDT::Vertex_handle> handles(domain.points.size());
        CDT::Face_handle                hint;
        for (std::size_t i = 0; i < domain.points.size(); ++i)
          {
            handles[i] = cdt.insert(domain.points[i], hint);
            hint       = handles[i]->face();
          }
        for (const auto *edges : {&domain.boundary, &domain.cracks})
          for (const Edge &e : *edges)
            if (handles[e[0]] != handles[e[1]])
              cdt.insert_constraint(handles[e[0]], handles[e[1]]);

        mark_domain(cdt, domain);

        Mesher mesher(cdt, MeshCriteria(shape_bound, size_bound));
        // true: keep the in-domain marks set above instead of seeds.
        mesher.init(true);
        std::size_t steps = 0;
        while (!mesher.is_refinement_done())
          {
            mesher.step_by_step_refine_mesh();
            if (++steps > max_steps)
              return false;
          }
        return true;
      }


      /**
       * Mesh one domain and split its vertices along its cracks. The
       * result is a mesh of this block alone, with its own vertex numbers
       * starting at zero.
       */
      BlockMesh
      mesh_domain(Domain                      &domain,
                  const std::vector<Point<2>> &required,
                  const double                 shape_bound)
      {
        add_required_vertices(domain, required, 1e-12 * domain.diameter);

        // The size bound bounds the longest edge. For a target number of
        // cells, start from the edge of equilateral triangles of the mean
        // area.
        double size_bound = domain.mesh_size;
        if (size_bound <= 0.)
          size_bound =
            size_bound_over_mean_edge *
            std::sqrt(4. * domain.area /
                      (std::sqrt(3.) * double(domain.target_n_cells)));
        const double expected_cells =
          domain.area / (std::sqrt(3.) / 4. * size_bound * size_bound);
        const std::size_t max_steps =
          200000 + 50 * std::size_t(std::min(expected_cells, 1e9));

        CDT cdt;
        if (!refine(domain, shape_bound, size_bound, max_steps, cdt))
          {
            AssertThrow(shape_bound > guaranteed_shape_bound,
                        dealii::ExcMessage(
                          "Geometry: block '" + domain.name +
                          "': the Delaunay refinement did not finish within " +
                          std::to_string(max_steps) +
                          " steps. Check the block for very short edges or "
                          "very small angles between its edges and cracks."));
            std::cerr << "Warning: Geometry: block '" << domain.name
                      << "': the Delaunay refinement with the minimum angle "
                      << std::asin(std::sqrt(shape_bound)) * 180. /
                           dealii::numbers::PI
                      << " degrees did not finish within " << max_steps
                      << " steps; meshed again with 20.7 degrees, for which "
                         "it is guaranteed to finish."
                      << std::endl;
            const bool done = refine(
              domain, guaranteed_shape_bound, size_bound, max_steps, cdt);
            AssertThrow(done,
                        dealii::ExcMessage(
                          "Geometry: block '" + domain.name +
                          "': the Delaunay refinement did not finish within " +
                          std::to_string(max_steps) +
                          " steps, even with a minimum angle of 20.7 degrees. "
                          "Check the block for very short edges or very "
                          "small angles between its edges and cracks."));
          }

        // Number the vertices in the order the domain's faces meet them.
        for (auto v = cdt.finite_vertices_begin();
             v != cdt.finite_vertices_end();
             ++v)
          v->info() = dealii::numbers::invalid_unsigned_int;
        BlockMesh         mesh;
        std::vector<Edge> cracks;
        for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end();
             ++f)
          {
            if (!f->is_in_domain())
              continue;
            std::array<unsigned int, 3> triangle;
            for (int i = 0; i < 3; ++i)
              {
                const CDT::Vertex_handle v = f->vertex(i);
                if (v->info() == dealii::numbers::invalid_unsigned_int)
                  {
                    v->info() = mesh.vertices.size();
                    mesh.vertices.emplace_back(v->point().x(), v->point().y());
                  }
                triangle[i] = v->info();
              }
            // CGAL's faces are counter-clockwise.
            mesh.triangles.push_back(triangle);
            // A constrained edge with the domain on both sides is a crack.
            for (int i = 0; i < 3; ++i)
              if (f->is_constrained(i) && f->neighbor(i)->is_in_domain())
                {
                  const unsigned int a = triangle[(i + 1) % 3];
                  const unsigned int b = triangle[(i + 2) % 3];
                  cracks.push_back({{std::min(a, b), std::max(a, b)}});
                }
          }
        std::sort(cracks.begin(), cracks.end());
        cracks.erase(std::unique(cracks.begin(), cracks.end()), cracks.end());
        split_vertices_along_edges(mesh, cracks);
        return mesh;
      }
    } // namespace



    BlockMesh
    mesh_scene(const SceneGeometry &geometry)
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
                        "Geometry: required vertex " + std::to_string(i) + " " +
                        format_point(p[0], p[1]) +
                        " is not finite. Give finite coordinates."));
        }
      const double sine =
        std::sin(geometry.min_angle * dealii::numbers::PI / 180.);
      const double shape_bound = sine * sine;

      // Validate everything before meshing anything, so that the user sees
      // the input errors at once.
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
          const Polygon &polygon = polygons.back();
          check_mesh_size(polygon, region.mesh_size, region.target_n_cells);
          for (std::size_t j = 0; j < region.joints.size(); ++j)
            {
              const Segment &joint = region.joints[j];
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
      check_overlaps(polygons);

      std::vector<Domain> domains;
      for (std::size_t b = 0; b < geometry.blocks.size(); ++b)
        domains.push_back(block_domain(polygons[b], geometry.blocks[b]));
      for (std::size_t r = 0; r < geometry.regions.size(); ++r)
        for (auto &domain : region_domains(polygons[geometry.blocks.size() + r],
                                           geometry.regions[r]))
          domains.push_back(std::move(domain));

      // Every block is meshed on its own and gets its own range of vertex
      // numbers: blocks never share vertices.
      BlockMesh scene;
      for (unsigned int b = 0; b < domains.size(); ++b)
        {
          const BlockMesh block =
            mesh_domain(domains[b], geometry.required_vertices, shape_bound);
          const unsigned int offset = scene.vertices.size();
          scene.vertices.insert(scene.vertices.end(),
                                block.vertices.begin(),
                                block.vertices.end());
          for (const auto &t : block.triangles)
            scene.triangles.push_back(
              {{t[0] + offset, t[1] + offset, t[2] + offset}});
          scene.cell_block.insert(scene.cell_block.end(),
                                  block.triangles.size(),
                                  b);
          scene.cell_material.insert(scene.cell_material.end(),
                                     block.triangles.size(),
                                     domains[b].material_id);
          for (const auto &e : block.crack_edges)
            scene.crack_edges.push_back({{e[0] + offset, e[1] + offset}});
          scene.block_names.push_back(domains[b].name);
        }
      return scene;
    }
  } // namespace geometry
} // namespace ndda
