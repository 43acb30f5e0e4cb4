// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_geometry_size_field_h
#define ndda_geometry_size_field_h

#include <deal.II/base/point.h>

#include <vector>

namespace ndda
{
  namespace geometry
  {
    using dealii::Point;

    /**
     * Where a scene's meshes are to be finer than their blocks' mesh sizes:
     * what Geometry/Mesh grading in the `.prm` file gives. A size of zero
     * switches that kind of feature off; with all sizes zero and no
     * refinement points the meshes are uniform, as without grading.
     *
     * The sizes bound the longest edge of a triangle, as a block's mesh
     * size does. Away from a feature the bound grows linearly with the
     * distance d, as h_f + (g - 1) d for the growth rate g: neighbouring
     * triangles then differ in size by about the factor g (doc/theory.md,
     * "Graded meshes").
     *
     * @ingroup geometry
     */
    struct MeshGrading
    {
      /// g > 1: the ratio of the sizes of neighbouring triangles.
      double growth_rate = 1.3;
      /// Size at the boundary of every hole of a block or region.
      double hole_size = 0.;
      /// Size at every crack tip: an end of a crack (or of a dangling
      /// joint) inside a block.
      double crack_tip_size = 0.;
      /// Size at every notch: a corner of a block where the material's
      /// angle exceeds notch_angle.
      double notch_size = 0.;
      /// Size at every loaded point (loaded_points).
      double loaded_point_size = 0.;
      /// Point loads, ends of line loads, points of boundary conditions,
      /// ends of bolts: where a concentrated force acts.
      std::vector<Point<2>> loaded_points;
      /// Further points with their own sizes (Refinement points).
      std::vector<std::pair<Point<2>, double>> refinement_points;

      /// A corner is a notch when the material's angle at it exceeds this
      /// (degrees): the elastic stress is singular at every re-entrant
      /// corner, and 10 degrees above a straight line keeps the vertices
      /// of finely drawn convex outlines out.
      static constexpr double notch_angle = 190.;

      /** Whether any feature asks for a finer mesh. */
      bool
      is_active() const;
    };


    /**
     * The largest allowed longest edge of a triangle at a point: the
     * block's own size bound H, or less near features (points and
     * segments with sizes h_f):
     *   h(x) = min(H, min_f (h_f + (g - 1) dist(x, f))).
     * The function is Lipschitz with constant g - 1, which Delaunay
     * refinement needs to grade a mesh without jumps.
     *
     * @ingroup geometry
     */
    class SizeField
    {
    public:
      /**
       * @param background The block's size bound H (m), > 0.
       * @param growth_rate g > 1.
       */
      SizeField(const double background, const double growth_rate);

      /** A point feature of size @p size; ignored if not below H. */
      void
      add_point(const Point<2> &p, const double size);

      /** A segment feature of size @p size; ignored if not below H. */
      void
      add_segment(const Point<2> &a, const Point<2> &b, const double size);

      /** h(x). */
      double
      operator()(const Point<2> &x) const;

      /** Whether h is H everywhere (no features below H). */
      bool
      is_uniform() const;

      /** H. */
      double
      background() const;

      /**
       * About how many triangles the features add to the ones of size H,
       * over the whole plane, each feature on its own. Per unit area the
       * mesher makes 1/(c h^2) triangles with c = sqrt(3)/4 /
       * size_bound_over_mean_edge^2 (equilateral triangles of the mean
       * edge). Integrated over a feature's reach r = (H - h)/k, k = g - 1:
       * 2 pi / (c k^2) (ln(H/h) + h/H - 1) - pi r^2 / (c H^2) for a point,
       * and 2 l / (c k) (1/h - 1/H) - 2 l r / (c H^2) for a segment of
       * length l, both sides and no end caps (segments come as the sides
       * of polygons, whose caps overlap). An estimate: features overlap,
       * and a hole's segments have material on one side only (up to 2
       * times too many there). Used to refuse absurd sizes before meshing
       * and to bound the mesher's steps.
       */
      double
      extra_cells() const;

      /**
       * The ratio of the size bound (the longest edge allowed) to the mean
       * edge of the triangles CGAL's mesher makes with it. Measured on a
       * square, a 64-gon and a 8:1 rectangle: within 5 % from 400 to
       * 100000 cells (coarser meshes are ruled by the boundary).
       */
      static constexpr double size_bound_over_mean_edge = 1.47;

    private:
      struct Feature
      {
        Point<2> a;
        Point<2> b;
        double   size;
      };

      double               H;
      double               slope;
      std::vector<Feature> features;
    };
  } // namespace geometry
} // namespace ndda

#endif
