// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <ndda/geometry/size_field.h>

#include <algorithm>
#include <cmath>

namespace ndda
{
  namespace geometry
  {
    bool
    MeshGrading::is_active() const
    {
      return hole_size > 0. || crack_tip_size > 0. || notch_size > 0. ||
             (loaded_point_size > 0. && !loaded_points.empty()) ||
             !refinement_points.empty();
    }



    SizeField::SizeField(const double background, const double growth_rate)
      : H(background)
      , slope(growth_rate - 1.)
    {
      Assert(background > 0., dealii::ExcInternalError());
      Assert(growth_rate > 1., dealii::ExcInternalError());
    }



    void
    SizeField::add_point(const Point<2> &p, const double size)
    {
      add_segment(p, p, size);
    }



    void
    SizeField::add_segment(const Point<2> &a,
                           const Point<2> &b,
                           const double    size)
    {
      if (size > 0. && size < H)
        features.push_back({a, b, size});
    }



    double
    SizeField::operator()(const Point<2> &x) const
    {
      double h = H;
      for (const Feature &f : features)
        {
          const dealii::Tensor<1, 2> ab  = f.b - f.a;
          const double               ab2 = ab.norm_square();
          double                     t   = 0.;
          if (ab2 > 0.)
            t = std::clamp(((x - f.a) * ab) / ab2, 0., 1.);
          const double d = x.distance(f.a + t * ab);
          h              = std::min(h, f.size + slope * d);
        }
      return h;
    }



    bool
    SizeField::is_uniform() const
    {
      return features.empty();
    }



    double
    SizeField::background() const
    {
      return H;
    }



    double
    SizeField::extra_cells() const
    {
      const double c = std::sqrt(3.) / 4. /
                       (size_bound_over_mean_edge * size_bound_over_mean_edge);
      const double pi = dealii::numbers::PI;
      double       n  = 0.;
      for (const Feature &f : features)
        {
          const double h = f.size, reach = (H - h) / slope;
          const double l = f.a.distance(f.b);
          if (l == 0.)
            n +=
              2. * pi / (c * slope * slope) * (std::log(H / h) + h / H - 1.) -
              pi * reach * reach / (c * H * H);
          else
            n += 2. * l / (c * slope) * (1. / h - 1. / H) -
                 2. * l * reach / (c * H * H);
        }
      return n;
    }
  } // namespace geometry
} // namespace ndda
