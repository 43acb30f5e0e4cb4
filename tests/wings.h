// SPDX-License-Identifier: GPL-3.0-or-later
//
// Wing cracks from a pre-existing straight crack: the maximum tangential
// stress (MTS) angle, and where and in which direction the new cracks of
// a run leave the crack's tips. Shared by tests/inclined_crack.cc and
// tests/brazilian_disc_crack.cc.
//
// New cracks are recorded in the initial geometry: cells keep their index
// and vertex order through every crack, so a side of a cell (side j of
// cell c runs from its corner j to corner j + 1) names the same piece of
// material all run long, whatever the vertices are called now.
#ifndef ndda_tests_wings_h
#define ndda_tests_wings_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <ndda/simulator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace ndda_tests
{
  namespace wings
  {
    using dealii::Point;
    using dealii::Tensor;

    constexpr double degree    = M_PI / 180.;
    constexpr double tolerance = 1e-9; // coincident points (m)

    /** Signed angle (degrees) from @p from to @p to, counter-clockwise
     * positive, in (-180, 180]. */
    inline double
    angle_between(const Tensor<1, 2> &from, const Tensor<1, 2> &to)
    {
      return std::atan2(from[0] * to[1] - from[1] * to[0], from * to) / degree;
    }

    /** The MTS angle (degrees from the crack's direction, counter-clockwise
     * positive) for the stress intensity factors @p KI and @p KII: the
     * maximum of the hoop stress
     *   sigma_tt ~ cos(t/2) [K_I cos^2(t/2) - 3/2 K_II sin t],
     * and the residual of thesis 7.11, K_I sin t + K_II (3 cos t - 1),
     * there. */
    inline std::pair<double, double>
    mts_angle(const double KI, const double KII)
    {
      const auto hoop = [&](const double t) {
        return std::cos(t / 2) *
               (KI * std::pow(std::cos(t / 2), 2) - 1.5 * KII * std::sin(t));
      };
      double best = 0;
      for (double t = -M_PI + 1e-6; t < M_PI; t += 1e-6)
        if (hoop(t) > hoop(best))
          best = t;
      return {best / degree,
              KI * std::sin(best) + KII * (3 * std::cos(best) - 1)};
    }

    /** The MTS angle at a tip whose crack points along @p x (outwards),
     * under the far-field stress @p sigma (an open crack): K_I ~ y'.sigma.y'
     * and K_II ~ x'.sigma.y', y' turned +90 degrees from x'. */
    inline std::pair<double, double>
    mts_angle(const Tensor<1, 2> &x, const dealii::SymmetricTensor<2, 2> &sigma)
    {
      Tensor<1, 2> y;
      y[0] = -x[1];
      y[1] = x[0];
      return mts_angle(y * (sigma * y), x * (sigma * y));
    }

    inline bool
    contains(const std::vector<Point<2>> &points, const Point<2> &p)
    {
      return std::any_of(points.begin(), points.end(), [&](const Point<2> &q) {
        return q.distance(p) < tolerance;
      });
    }

    /** A new crack edge: its ends in the initial geometry, and the step it
     * appeared in. */
    using NewEdge = std::pair<std::array<Point<2>, 2>, unsigned int>;

    /**
     * The crack faces of a run, as sides of cells in the initial geometry:
     * construct it after setup, call record() after every step.
     */
    class CrackRecorder
    {
    public:
      explicit CrackRecorder(const ndda::Simulator<2> &simulator)
        : simulator(simulator)
      {
        const auto &start = simulator.get_mesh().get_block_mesh();
        corner.resize(start.triangles.size());
        for (unsigned int c = 0; c < corner.size(); ++c)
          for (unsigned int j = 0; j < 3; ++j)
            corner[c][j] = start.vertices[start.triangles[c][j]];
        initial_sides = crack_sides();
      }

      /** Note the crack faces that are new since the last call. */
      void
      record()
      {
        const unsigned int step = simulator.get_step_number();
        for (const unsigned int s : crack_sides())
          if (initial_sides.count(s) == 0 && new_sides.count(s) == 0)
            new_sides[s] = step;
      }

      /** The new crack edges, each once, with the step they appeared in. */
      std::vector<NewEdge>
      new_edges() const
      {
        std::vector<NewEdge> edges;
        for (const auto &[s, step] : new_sides)
          {
            const auto e = ends(s);
            if (std::none_of(edges.begin(), edges.end(), [&](const auto &f) {
                  return (f.first[0].distance(e[0]) < tolerance &&
                          f.first[1].distance(e[1]) < tolerance) ||
                         (f.first[0].distance(e[1]) < tolerance &&
                          f.first[1].distance(e[0]) < tolerance);
                }))
              edges.emplace_back(e, step);
          }
        return edges;
      }

      bool
      has_new_cracks() const
      {
        return !new_sides.empty();
      }

      /** Number of crack faces at the start. */
      unsigned int
      n_initial_faces() const
      {
        return initial_sides.size();
      }

      /** Initial corners of every cell. */
      const std::vector<std::array<Point<2>, 3>> &
      corners() const
      {
        return corner;
      }

    private:
      std::array<Point<2>, 2>
      ends(const unsigned int side) const
      {
        return {{corner[side / 3][side % 3], corner[side / 3][(side + 1) % 3]}};
      }

      /** The sides of cells that are crack faces now. */
      std::set<unsigned int>
      crack_sides() const
      {
        const auto &m = simulator.get_mesh().get_block_mesh();
        std::map<std::pair<unsigned int, unsigned int>, unsigned int> side_of;
        for (unsigned int c = 0; c < m.triangles.size(); ++c)
          for (unsigned int j = 0; j < 3; ++j)
            side_of[{m.triangles[c][j], m.triangles[c][(j + 1) % 3]}] =
              3 * c + j;
        std::set<unsigned int> sides;
        for (const auto &e : m.crack_edges)
          sides.insert(side_of.at({e[0], e[1]}));
        return sides;
      }

      const ndda::Simulator<2>            &simulator;
      std::vector<std::array<Point<2>, 3>> corner;
      std::set<unsigned int>               initial_sides;
      std::map<unsigned int, unsigned int> new_sides; // side -> step
    };

    struct Wing
    {
      Point<2>            tip;
      Tensor<1, 2>        outward;            // x'
      double              mts   = 0;          // degrees from x'
      bool                found = false;      // a wing starts on this half
      Point<2>            start;              // its end on the crack
      unsigned int        step = 0;           // step it appeared in
      double              kink = 0;           // degrees from x'
      std::vector<double> edge_angles;        // mesh edges at the start
      double              nearest        = 0; // of those, nearest to mts
      double              mean_direction = 0; // degrees from x'
      unsigned int        n_points       = 0; // crack points used for it
      bool                exits          = false;
      Point<2>            exit;           // where it leaves the body
      double              exit_angle = 0; // tip -> exit, from the x axis
    };

    /**
     * Trace the wing at @p wing.tip (tip, outward and mts set) of the
     * straight crack from @p crack_a to @p crack_b:
     *  - where it starts: the new crack edges that end on the crack, on
     *    this tip's half; of those that appear in the earliest step, the
     *    one nearest to the tip. Its end on the crack is the start.
     *  - the kink angle: from x' to that edge; and the directions of all
     *    mesh edges that leave the start (not along the crack), and of
     *    those the one nearest to the MTS angle.
     *  - the mean direction: from the start to the centroid of the new
     *    crack points within @p radius of the start that lie nearer to
     *    this tip than to the other (cracks branch and leave small
     *    pieces, so they are not followed edge by edge).
     *  - where it leaves the body: of those points on the outer boundary
     *    (@p on_boundary), the one farthest from the tip.
     */
    inline void
    trace_wing(Wing                                        &wing,
               const std::vector<NewEdge>                  &edges,
               const CrackRecorder                         &recorder,
               const Point<2>                              &crack_a,
               const Point<2>                              &crack_b,
               const double                                 radius,
               const std::function<bool(const Point<2> &)> &on_boundary)
    {
      const Point<2>     centre   = 0.5 * (crack_a + crack_b);
      const double       half     = 0.5 * crack_a.distance(crack_b);
      const Tensor<1, 2> along    = (crack_b - crack_a) / (2 * half);
      const auto         on_crack = [&](const Point<2> &p) {
        const Tensor<1, 2> r = p - centre;
        return std::abs(r[0] * along[1] - r[1] * along[0]) < tolerance &&
               std::abs(r * along) < half + tolerance;
      };

      Point<2> other;
      for (const auto &[e, step] : edges)
        for (unsigned int i = 0; i < 2; ++i)
          if (on_crack(e[i]) && !on_crack(e[1 - i]) &&
              e[i].distance(wing.tip) < half &&
              (!wing.found || step < wing.step ||
               (step == wing.step &&
                e[i].distance(wing.tip) < wing.start.distance(wing.tip))))
            {
              wing.found = true;
              wing.start = e[i];
              wing.step  = step;
              other      = e[1 - i];
            }
      if (!wing.found)
        return;
      wing.kink = angle_between(wing.outward, other - wing.start);
      for (const auto &corner : recorder.corners())
        for (unsigned int j = 0; j < 3; ++j)
          if (corner[j].distance(wing.start) < tolerance)
            for (const unsigned int o : {1u, 2u})
              {
                const Point<2> &q = corner[(j + o) % 3];
                if (on_crack(q))
                  continue; // along the pre-existing crack
                const double a = angle_between(wing.outward, q - wing.start);
                if (std::none_of(wing.edge_angles.begin(),
                                 wing.edge_angles.end(),
                                 [&](const double b) {
                                   return std::abs(a - b) < 1e-6;
                                 }))
                  wing.edge_angles.push_back(a);
              }
      std::sort(wing.edge_angles.begin(), wing.edge_angles.end());
      wing.nearest = *std::min_element(wing.edge_angles.begin(),
                                       wing.edge_angles.end(),
                                       [&](const double a, const double b) {
                                         return std::abs(a - wing.mts) <
                                                std::abs(b - wing.mts);
                                       });

      std::vector<Point<2>> points;
      for (const auto &[e, step] : edges)
        for (const auto &p : e)
          if (!on_crack(p) && !contains(points, p) &&
              p.distance(wing.tip) < p.distance(centre + (centre - wing.tip)))
            points.push_back(p);
      Point<2> centroid;
      for (const auto &p : points)
        if (p.distance(wing.start) < radius)
          {
            centroid += p;
            ++wing.n_points;
          }
      if (wing.n_points > 0)
        wing.mean_direction =
          angle_between(wing.outward, centroid / wing.n_points - wing.start);
      for (const auto &p : points)
        if (on_boundary(p) && (!wing.exits || p.distance(wing.tip) >
                                                wing.exit.distance(wing.tip)))
          {
            wing.exits = true;
            wing.exit  = p;
          }
      if (wing.exits)
        {
          const Tensor<1, 2> d = wing.exit - wing.tip;
          wing.exit_angle      = std::atan2(d[1], d[0]) / degree;
        }
    }
  } // namespace wings
} // namespace ndda_tests

#endif
