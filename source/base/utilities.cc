// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/numbers.h>

#include <ndda/base/utilities.h>

#include <algorithm>
#include <sstream>

namespace ndda
{
  std::string
  to_string(const dealii::Point<2> &p)
  {
    std::ostringstream out;
    out << "(" << p[0] << ", " << p[1] << ")";
    return out.str();
  }



  double
  distance_to_segment(const dealii::Point<2> &p, const geometry::Segment &s)
  {
    const dealii::Tensor<1, 2> ab = s.b - s.a;
    const double t = std::clamp(((p - s.a) * ab) / ab.norm_square(), 0., 1.);
    return p.distance(s.a + t * ab);
  }



  double
  point_tolerance(const dealii::Point<2> &lower, const dealii::Point<2> &upper)
  {
    return 1e-8 * std::max(1., lower.distance(upper));
  }
} // namespace ndda
