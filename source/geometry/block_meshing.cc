// SPDX-License-Identifier: GPL-3.0-or-later
//
// Meshing of one block (thesis chapter 4): the required vertices that lie in
// the block become part of its Domain, CGAL's constrained Delaunay mesher
// refines it, and the vertices along its cracks are split
// (split_vertices_along_edges(), split_vertices.cc), giving the BlockMesh of
// the block alone.
//
// Decisions that the header leaves open:
//  - Every block is meshed alone, so the vertices on a joint shared by two
//    blocks need not match: blocks are separate bodies that touch.
//  - A graded mesh (Geometry/Mesh grading) uses the same mesher with the
//    size bound of each triangle taken from the SizeField at its centroid:
//    CGAL's own size test, with a local bound. Without grading the field is
//    absent and the meshes are the uniform ones, bit for bit.
//  - With a minimum angle above 20.7 degrees Delaunay refinement is not
//    proven to terminate. A block whose refinement runs past a step budget
//    is meshed again with 20.7 degrees, and a warning goes to std::cerr.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <ndda/base/utilities.h>
#include <ndda/geometry/block_mesh.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <string>
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
        using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<
          unsigned int,
          IK,
          CGAL::Delaunay_mesh_vertex_base_2<IK>>;
        using FaceBase = CGAL::Delaunay_mesh_face_base_2<IK>;
        using TriangulationDataStructure =
          CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
        using CDT = CGAL::Constrained_Delaunay_triangulation_2<
          IK,
          TriangulationDataStructure,
          CGAL::Exact_predicates_tag>;
        using SizeCriteria = CGAL::Delaunay_mesh_size_criteria_2<CDT>;


        /**
         * CGAL's size and shape criteria with the size bound of every
         * triangle taken from a SizeField at its centroid, or the constant
         * bound if there is no field. The quality's size part is the
         * longest edge relative to the local bound, so the mesher splits
         * the triangles most above their own bound first.
         */
        class GradedCriteria : public SizeCriteria
        {
        public:
          GradedCriteria(const double     shape_bound,
                         const double     size_bound,
                         const SizeField *field)
            : CGAL::Delaunay_mesh_criteria_2<CDT>(shape_bound)
            , SizeCriteria(shape_bound, size_bound)
            , field(field)
          {}

          class Is_bad : public SizeCriteria::Is_bad
          {
          public:
            Is_bad(const double       shape_bound,
                   const double       size_bound,
                   const Geom_traits &traits,
                   const SizeField   *field)
              : SizeCriteria::Is_bad(shape_bound, size_bound, traits)
              , field(field)
            {}

            using SizeCriteria::Is_bad::operator();

            CGAL::Mesh_2::Face_badness
            operator()(const CDT::Face_handle &face, Quality &quality) const
            {
              if (field == nullptr)
                return SizeCriteria::Is_bad::operator()(face, quality);
              const IPoint  &a = face->vertex(0)->point();
              const IPoint  &b = face->vertex(1)->point();
              const IPoint  &c = face->vertex(2)->point();
              const Point<2> centroid((a.x() + b.x() + c.x()) / 3.,
                                      (a.y() + b.y() + c.y()) / 3.);
              return SizeCriteria::Is_bad(this->B,
                                          (*field)(centroid),
                                          this->traits)(face, quality);
            }

          private:
            const SizeField *field;
          };

          Is_bad
          is_bad_object() const
          {
            return Is_bad(this->bound(), size_bound(), this->traits, field);
          }

        private:
          const SizeField *field;
        };

        using Mesher = CGAL::Delaunay_mesher_2<CDT, GradedCriteria>;


        /**
         * Shape bound for which CGAL's Delaunay refinement is proven to
         * terminate: sin^2(20.7 degrees).
         */
        constexpr double guaranteed_shape_bound = 0.125;



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
                                return CGAL::squared_distance(p, q) <=
                                       tolerance2;
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
              if (!on_edge &&
                  domain_contains(domain.points, domain.boundary, p))
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
              const IPoint centroid =
                CGAL::centroid(largest->vertex(0)->point(),
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
               const SizeField  &size_field,
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

          Mesher mesher(cdt,
                        GradedCriteria(shape_bound,
                                       size_field.background(),
                                       size_field.is_uniform() ? nullptr :
                                                                 &size_field));
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
         * The size bound of the mesher, which bounds the longest edge: the
         * domain's mesh size, or, for a target number of cells, the edge of
         * equilateral triangles of the mean area scaled by
         * SizeField::size_bound_over_mean_edge (the mesher's triangles are
         * smaller than the bound, so the bound has to be larger than the
         * mean edge to get about target_n_cells triangles).
         */
        double
        size_bound_of(const Domain &domain)
        {
          double size_bound = domain.mesh_size;
          if (size_bound <= 0.)
            size_bound =
              SizeField::size_bound_over_mean_edge *
              std::sqrt(4. * domain.area /
                        (std::sqrt(3.) * double(domain.target_n_cells)));
          return size_bound;
        }


        /**
         * The crack tips of a domain: ends of crack edges that no other
         * crack edge and no boundary edge meets.
         */
        std::vector<IPoint>
        crack_tips(const Domain &domain)
        {
          std::vector<unsigned int> crack_degree(domain.points.size(), 0);
          std::vector<bool>         on_boundary(domain.points.size(), false);
          for (const Edge &e : domain.cracks)
            for (const unsigned int v : e)
              ++crack_degree[v];
          for (const Edge &e : domain.boundary)
            for (const unsigned int v : e)
              on_boundary[v] = true;
          std::vector<IPoint> tips;
          for (unsigned int v = 0; v < domain.points.size(); ++v)
            if (crack_degree[v] == 1 && !on_boundary[v])
              tips.push_back(domain.points[v]);
          return tips;
        }


        /**
         * The notches of a domain: boundary points with one incoming and
         * one outgoing boundary edge where the material's angle (the
         * domain lies to the left of its boundary edges) exceeds
         * MeshGrading::notch_angle.
         */
        std::vector<IPoint>
        notches(const Domain &domain)
        {
          constexpr unsigned int none = dealii::numbers::invalid_unsigned_int;
          std::vector<unsigned int> in(domain.points.size(), none);
          std::vector<unsigned int> out(domain.points.size(), none);
          std::vector<unsigned int> degree(domain.points.size(), 0);
          for (unsigned int k = 0; k < domain.boundary.size(); ++k)
            {
              out[domain.boundary[k][0]] = k;
              in[domain.boundary[k][1]]  = k;
              ++degree[domain.boundary[k][0]];
            }
          // A right turn of more than notch_angle - 180 degrees.
          const double sine = std::sin((MeshGrading::notch_angle - 180.) *
                                       dealii::numbers::PI / 180.);
          std::vector<IPoint> result;
          for (unsigned int v = 0; v < domain.points.size(); ++v)
            {
              if (degree[v] != 1 || in[v] == none)
                continue;
              const IPoint &p  = domain.points[domain.boundary[in[v]][0]];
              const IPoint &q  = domain.points[domain.boundary[out[v]][1]];
              const auto    d1 = domain.points[v] - p;
              const auto    d2 = q - domain.points[v];
              const double  cross =
                CGAL::to_double(d1.x() * d2.y() - d1.y() * d2.x());
              const double dot = CGAL::to_double(d1 * d2);
              const double l1  = std::sqrt(CGAL::to_double(d1 * d1));
              const double l2  = std::sqrt(CGAL::to_double(d2 * d2));
              // Right turn by more than the threshold: sin of the turn
              // above the bound, or a turn of more than 90 degrees.
              if (cross < 0. && (-cross > sine * l1 * l2 || dot < 0.))
                result.push_back(domain.points[v]);
            }
          return result;
        }


        /**
         * refine() with the given shape bound, and if that does not finish
         * within @p max_steps steps, once more with the shape bound for which
         * the refinement is guaranteed to finish (with a warning). Throws if
         * the refinement still does not finish, or if the given shape bound
         * was the guaranteed one already.
         */
        void
        refine_or_fall_back(const Domain     &domain,
                            const double      shape_bound,
                            const SizeField  &size_field,
                            const std::size_t max_steps,
                            CDT              &cdt)
        {
          if (refine(domain, shape_bound, size_field, max_steps, cdt))
            return;
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
          const bool done =
            refine(domain, guaranteed_shape_bound, size_field, max_steps, cdt);
          AssertThrow(done,
                      dealii::ExcMessage(
                        "Geometry: block '" + domain.name +
                        "': the Delaunay refinement did not finish within " +
                        std::to_string(max_steps) +
                        " steps, even with a minimum angle of 20.7 degrees. "
                        "Check the block for very short edges or very "
                        "small angles between its edges and cracks."));
        }


        /**
         * The triangles of the refined triangulation that lie in the domain,
         * as a BlockMesh without crack edges, and the constrained edges with
         * the domain on both sides (the cracks), sorted and unique.
         */
        BlockMesh
        block_mesh_of(CDT &cdt, std::vector<Edge> &cracks)
        {
          // Number the vertices in the order the domain's faces meet them.
          for (auto v = cdt.finite_vertices_begin();
               v != cdt.finite_vertices_end();
               ++v)
            v->info() = dealii::numbers::invalid_unsigned_int;
          BlockMesh mesh;
          cracks.clear();
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
                      mesh.vertices.emplace_back(v->point().x(),
                                                 v->point().y());
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
          // The cells along a Hilbert curve through their centroids: the
          // mesher lists them in the order of its refinement, all over the
          // block, and every loop over the cells (and deal.II's dof
          // numbering, cell by cell) would miss the cache.
          std::vector<dealii::Point<2>> centroids;
          centroids.reserve(mesh.triangles.size());
          for (const auto &t : mesh.triangles)
            centroids.emplace_back((mesh.vertices[t[0]] + mesh.vertices[t[1]] +
                                    mesh.vertices[t[2]]) /
                                   3.);
          std::vector<std::array<unsigned int, 3>> ordered;
          ordered.reserve(mesh.triangles.size());
          for (const unsigned int c : hilbert_order(centroids))
            ordered.push_back(mesh.triangles[c]);
          mesh.triangles.swap(ordered);
          // The vertices in the order these cells first meet them: a pass
          // over the cells then reads the vertices nearly in order too.
          std::vector<unsigned int> new_index(
            mesh.vertices.size(), dealii::numbers::invalid_unsigned_int);
          std::vector<dealii::Point<2>> vertices;
          vertices.reserve(mesh.vertices.size());
          for (auto &t : mesh.triangles)
            for (unsigned int &v : t)
              {
                if (new_index[v] == dealii::numbers::invalid_unsigned_int)
                  {
                    new_index[v] = vertices.size();
                    vertices.push_back(mesh.vertices[v]);
                  }
                v = new_index[v];
              }
          mesh.vertices.swap(vertices);
          for (Edge &e : cracks)
            e = {{std::min(new_index[e[0]], new_index[e[1]]),
                  std::max(new_index[e[0]], new_index[e[1]])}};
          std::sort(cracks.begin(), cracks.end());
          return mesh;
        }
      } // namespace



      SizeField
      size_field_of(const Domain &domain, const MeshGrading &grading)
      {
        const double size_bound = size_bound_of(domain);
        SizeField    field(size_bound, grading.growth_rate);
        if (!grading.is_active())
          return field;
        const auto to_point = [](const IPoint &p) {
          return Point<2>(p.x(), p.y());
        };
        for (const auto &e : domain.hole_edges)
          field.add_segment(to_point(e[0]), to_point(e[1]), grading.hole_size);
        for (const IPoint &p : crack_tips(domain))
          field.add_point(to_point(p), grading.crack_tip_size);
        for (const IPoint &p : notches(domain))
          field.add_point(to_point(p), grading.notch_size);
        // A point feature reaches (H - h)/(g - 1) from itself.
        const auto   box   = bbox_of(domain.points);
        const double slope = grading.growth_rate - 1.;
        const auto   near  = [&](const Point<2> &p, const double size) {
          const double reach = (size_bound - size) / slope;
          return p[0] > box.xmin() - reach && p[0] < box.xmax() + reach &&
                 p[1] > box.ymin() - reach && p[1] < box.ymax() + reach;
        };
        if (grading.loaded_point_size > 0.)
          for (const Point<2> &p : grading.loaded_points)
            if (near(p, grading.loaded_point_size))
              field.add_point(p, grading.loaded_point_size);
        for (const auto &[p, size] : grading.refinement_points)
          if (near(p, size))
            field.add_point(p, size);
        return field;
      }



      double
      expected_cells(const Domain &domain, const SizeField &size_field)
      {
        const double h =
          size_field.background() / SizeField::size_bound_over_mean_edge;
        return domain.area / (std::sqrt(3.) / 4. * h * h) +
               size_field.extra_cells();
      }



      BlockMesh
      mesh_domain(Domain                      &domain,
                  const std::vector<Point<2>> &required,
                  const double                 shape_bound,
                  const SizeField             &size_field)
      {
        add_required_vertices(domain, required, 1e-12 * domain.diameter);

        // The step budget counts the uniform part as equilateral triangles
        // of edge H, as it always has.
        const double H = size_field.background();
        const double n_cells =
          domain.area / (std::sqrt(3.) / 4. * H * H) + size_field.extra_cells();
        const std::size_t max_steps =
          200000 + 50 * std::size_t(std::min(n_cells, 1e9));

        CDT cdt;
        refine_or_fall_back(domain, shape_bound, size_field, max_steps, cdt);

        std::vector<Edge> cracks;
        BlockMesh         mesh = block_mesh_of(cdt, cracks);
        split_vertices_along_edges(mesh, cracks);
        return mesh;
      }
    } // namespace internal
  }   // namespace geometry
} // namespace ndda
