// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_base_utilities_h
#define ndda_base_utilities_h

#include <deal.II/base/point.h>

#include <ndda/geometry/block_mesh.h>

#include <memory>
#include <string>
#include <vector>

namespace ndda
{
  /** "(x, y)" for messages. */
  std::string
  to_string(const dealii::Point<2> &p);

  /** Distance (m) of @p p to the segment @p s. */
  double
  distance_to_segment(const dealii::Point<2> &p, const geometry::Segment &s);

  /**
   * The distance below which two points of a scene are the same point:
   * 1e-8 of the diagonal of the box @p lower - @p upper, at least 1e-8 m.
   */
  double
  point_tolerance(const dealii::Point<2> &lower, const dealii::Point<2> &upper);

  /**
   * The indices of @p points in the order a Hilbert curve through their
   * bounding square meets them (on a grid of 2^16 x 2^16; points in the
   * same grid cell keep their order). Points near each other along the
   * result lie near each other in the plane: loops over cells numbered so
   * touch memory in the order of the plane.
   */
  std::vector<unsigned int>
  hilbert_order(const std::vector<dealii::Point<2>> &points);
} // namespace ndda

#endif
