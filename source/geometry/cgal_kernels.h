// SPDX-License-Identifier: GPL-3.0-or-later
//
// Private header of source/geometry/: the CGAL kernels and arrangement types,
// the plain structs that travel between the steps of mesh_scene() (Polygon,
// Domain), small helpers, and the functions that one unit of source/geometry/
// calls in another. It is not in include/: nothing of CGAL leaks into the
// public headers. The units that include it are compiled without debug
// information (CMakeLists.txt).
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
#ifndef ndda_source_geometry_cgal_kernels_h
#define ndda_source_geometry_cgal_kernels_h

#include <ndda/geometry/block_mesh.h>

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>

#include <array>
#include <cmath>
#include <iomanip>
#include <queue>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace ndda
{
  namespace geometry
  {
    /**
     * Implementation of mesh_scene(), shared by the translation units of
     * source/geometry/ that use CGAL.
     */
    namespace internal
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

      using Edge = std::array<unsigned int, 2>;


      inline std::string
      format_point(const double x, const double y)
      {
        std::ostringstream s;
        s << std::setprecision(10) << "(" << x << ", " << y << ")";
        return s.str();
      }


      inline std::string
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
      inline double
      to_double_exactly(const EK::FT &x)
      {
        return CGAL::to_double(CGAL::exact(x));
      }


      inline std::string
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
        /// The boundary edges that lie on holes of the block or region, as
        /// end points (for the size field: they stay hole edges when
        /// required vertices split them).
        std::vector<std::array<IPoint, 2>> hole_edges;
        double                             area     = 0.;
        double                             diameter = 0.;
      };


      inline CGAL::Bbox_2
      bbox_of(const std::vector<IPoint> &points)
      {
        return CGAL::bbox_2(points.begin(), points.end());
      }


      inline double
      diagonal(const CGAL::Bbox_2 &box)
      {
        return std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin());
      }


      inline ISegment
      ring_edge(const std::vector<IPoint> &ring, const std::size_t i)
      {
        return ISegment(ring[i], ring[(i + 1) % ring.size()]);
      }


      inline EK::Point_2
      exact_point(const IPoint &p)
      {
        return EK::Point_2(p.x(), p.y());
      }


      /**
       * Add the edges of a ring to @p curves, all with the curve id @p id.
       */
      inline void
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


      // --- scene_validation.cc ---

      /**
       * Check the whole input of mesh_scene() before anything is cut or
       * meshed, so that the user sees the input errors at once: the scene's
       * settings, every block (rings, mesh size, cracks) and region (rings,
       * mesh size, joints), in input order, and that no two of them
       * overlap. Returns the validated polygons: the blocks' in input
       * order, then the regions'.
       */
      std::vector<Polygon>
      validate_scene(const SceneGeometry &geometry);

      /**
       * The scene's size: the diagonal of the bounding box of the outer
       * rings of all blocks and regions.
       */
      double
      scene_size(const SceneGeometry &geometry);

      /**
       * @p geometry with the corners of its blocks' and regions' rings
       * snapped: a corner within geometry.snap_tolerance * scene_size() of
       * a corner of an earlier block or region (in input order, blocks
       * before regions) takes that corner's coordinates. Corners of one
       * block are not snapped to each other. Linear in the number of
       * corners (a hash grid of the tolerance's size).
       */
      SceneGeometry
      snap_corners(SceneGeometry geometry);


      // --- block_cutting.cc ---

      /**
       * An explicit block: all faces inside the polygon form one domain;
       * crack segments (and the edges between faces that cracks separate)
       * become crack edges.
       */
      Domain
      block_domain(const Polygon &polygon, const BlockDescription &block);

      /**
       * Cut a region into blocks: every face of the arrangement of its
       * rings and joints that lies inside the region is one block, numbered
       * by its lowest-then-leftmost vertex.
       */
      std::vector<Domain>
      region_domains(const Polygon &polygon, const RegionDescription &region);


      // --- block_meshing.cc ---

      /**
       * Mesh one domain and split its vertices along its cracks. The
       * result is a mesh of this block alone, with its own vertex numbers
       * starting at zero. @p required are the points that become vertices
       * if they lie in the closed domain; @p shape_bound is sin^2 of the
       * minimum angle; @p size_field bounds the longest edge of the
       * triangles (size_field_of()).
       */
      BlockMesh
      mesh_domain(Domain                      &domain,
                  const std::vector<Point<2>> &required,
                  const double                 shape_bound,
                  const SizeField             &size_field);

      /**
       * The size field of a domain: its size bound (its mesh size, or the
       * one for its target number of elements), finer near its holes,
       * crack tips and notches and near the loaded and refinement points of
       * @p grading that can reach it.
       */
      SizeField
      size_field_of(const Domain &domain, const MeshGrading &grading);

      /**
       * About how many cells the mesher makes in @p domain with
       * @p size_field: equilateral triangles of the mean edge
       * H / SizeField::size_bound_over_mean_edge over the domain, and what
       * the features add (SizeField::extra_cells()).
       */
      double
      expected_cells(const Domain &domain, const SizeField &size_field);
    } // namespace internal
  }   // namespace geometry
} // namespace ndda

#endif
