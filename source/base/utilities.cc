// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/numbers.h>

#include <ndda/base/utilities.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
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



  std::vector<unsigned int>
  hilbert_order(const std::vector<dealii::Point<2>> &points)
  {
    std::vector<unsigned int> order(points.size());
    std::iota(order.begin(), order.end(), 0u);
    if (points.size() < 3)
      return order;
    dealii::Point<2> lower = points[0], upper = points[0];
    for (const auto &p : points)
      for (unsigned int d = 0; d < 2; ++d)
        {
          lower[d] = std::min(lower[d], p[d]);
          upper[d] = std::max(upper[d], p[d]);
        }
    const double side = std::max(upper[0] - lower[0], upper[1] - lower[1]);
    constexpr std::uint32_t n     = 1u << 16;
    const double            scale = side > 0. ? (n - 1) / side : 0.;
    // The curve's index of a grid cell (x, y): per level, the quadrant's
    // place along the curve, then the coordinates turned into the
    // quadrant's own frame.
    const auto index = [&](const dealii::Point<2> &p) {
      auto          x = std::uint32_t((p[0] - lower[0]) * scale);
      auto          y = std::uint32_t((p[1] - lower[1]) * scale);
      std::uint64_t d = 0;
      for (std::uint32_t s = n / 2; s > 0; s /= 2)
        {
          const std::uint32_t rx = (x & s) ? 1 : 0;
          const std::uint32_t ry = (y & s) ? 1 : 0;
          d += std::uint64_t(s) * s * ((3 * rx) ^ ry);
          if (ry == 0)
            {
              if (rx == 1)
                {
                  x = n - 1 - x;
                  y = n - 1 - y;
                }
              std::swap(x, y);
            }
        }
      return d;
    };
    std::vector<std::uint64_t> key(points.size());
    for (unsigned int i = 0; i < points.size(); ++i)
      key[i] = index(points[i]);
    std::stable_sort(order.begin(),
                     order.end(),
                     [&](const unsigned int a, const unsigned int b) {
                       return key[a] < key[b];
                     });
    return order;
  }
} // namespace ndda
