// SPDX-License-Identifier: GPL-3.0-or-later
#include <deal.II/base/numbers.h>

#include <ndda/fracture/crack_tips.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace ndda
{
  namespace fracture
  {
    namespace
    {
      using dealii::Point;
      using dealii::Tensor;

      /// How far behind a tip its faces' jump is read: at most this many
      /// faces, along a crack that turns by less than max_turn.
      constexpr unsigned int max_faces = 3;
      constexpr double       max_turn  = 15 * M_PI / 180;

      std::uint64_t
      key(const unsigned int a, const unsigned int b)
      {
        return (std::uint64_t(a) << 32) | b;
      }

      Tensor<1, 2>
      turned(const Tensor<1, 2> &x, const double angle)
      {
        const double c = std::cos(angle), s = std::sin(angle);
        Tensor<1, 2> y;
        y[0] = c * x[0] - s * x[1];
        y[1] = s * x[0] + c * x[1];
        return y;
      }

      /// Signed angle from a to b, radians.
      double
      angle_from(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
      {
        return std::atan2(a[0] * b[1] - a[1] * b[0], a * b);
      }

      double
      twice_area(const Point<2> &a, const Point<2> &b, const Point<2> &c)
      {
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      }

      /// Smallest angle of a triangle (radians); 0 if it is flat.
      double
      smallest_angle(const Point<2> &a, const Point<2> &b, const Point<2> &c)
      {
        const std::array<Point<2>, 3> p        = {{a, b, c}};
        double                        smallest = M_PI;
        for (unsigned int k = 0; k < 3; ++k)
          {
            const Tensor<1, 2> u = p[(k + 1) % 3] - p[k];
            const Tensor<1, 2> v = p[(k + 2) % 3] - p[k];
            const double       n = u.norm() * v.norm();
            if (n == 0.)
              return 0.;
            smallest = std::min(smallest, std::abs(angle_from(u, v)));
          }
        return smallest;
      }

      /// The directed sides of the triangles, sorted, and per vertex the
      /// cells around it (compressed rows).
      struct Adjacency
      {
        std::vector<std::uint64_t> sides;
        std::vector<unsigned int>  offsets, cells;

        explicit Adjacency(const geometry::BlockMesh &mesh)
        {
          const unsigned int n_vertices = mesh.vertices.size();
          sides.reserve(3 * mesh.triangles.size());
          offsets.assign(n_vertices + 1, 0);
          for (const auto &t : mesh.triangles)
            for (unsigned int j = 0; j < 3; ++j)
              {
                sides.push_back(key(t[j], t[(j + 1) % 3]));
                ++offsets[t[j] + 1];
              }
          std::sort(sides.begin(), sides.end());
          for (unsigned int v = 0; v < n_vertices; ++v)
            offsets[v + 1] += offsets[v];
          cells.resize(offsets.back());
          std::vector<unsigned int> fill(offsets.begin(), offsets.end() - 1);
          for (unsigned int c = 0; c < mesh.triangles.size(); ++c)
            for (const unsigned int v : mesh.triangles[c])
              cells[fill[v]++] = c;
        }

        bool
        has_side(const unsigned int a, const unsigned int b) const
        {
          return std::binary_search(sides.begin(), sides.end(), key(a, b));
        }

        /// Whether every side at @p v has a twin: v is inside its block.
        bool
        is_interior(const geometry::BlockMesh &mesh, const unsigned int v) const
        {
          for (unsigned int i = offsets[v]; i < offsets[v + 1]; ++i)
            {
              const auto &t = mesh.triangles[cells[i]];
              for (unsigned int j = 0; j < 3; ++j)
                if (t[j] == v && (!has_side(t[(j + 1) % 3], v) ||
                                  !has_side(v, t[(j + 2) % 3])))
                  return false;
            }
          return true;
        }
      };
    } // namespace



    std::vector<CrackTip>
    find_crack_tips(const CrackableMesh &mesh)
    {
      return find_crack_tips(mesh.get_block_mesh(),
                             mesh.get_initial_vertices());
    }



    std::vector<CrackTip>
    find_crack_tips(const geometry::BlockMesh   &block_mesh,
                    const std::vector<Point<2>> &initial_vertices)
    {
      const unsigned int n_vertices = block_mesh.vertices.size();
      // The crack faces, as undirected sorted keys.
      std::vector<std::uint64_t> crack_keys;
      crack_keys.reserve(block_mesh.crack_edges.size());
      for (const auto &e : block_mesh.crack_edges)
        crack_keys.push_back(key(std::min(e[0], e[1]), std::max(e[0], e[1])));
      std::sort(crack_keys.begin(), crack_keys.end());
      const auto is_cracked = [&](const unsigned int a, const unsigned int b) {
        return std::binary_search(crack_keys.begin(),
                                  crack_keys.end(),
                                  key(std::min(a, b), std::max(a, b)));
      };
      const Adjacency adjacency(block_mesh);
      // Per vertex: boundary sides at it, and the crack face running into
      // it and out of it.
      constexpr unsigned int    none = dealii::numbers::invalid_unsigned_int;
      std::vector<unsigned int> n_boundary(n_vertices, 0);
      std::vector<unsigned int> into(n_vertices, none), out(n_vertices, none);
      for (const auto &t : block_mesh.triangles)
        for (unsigned int j = 0; j < 3; ++j)
          {
            const unsigned int a = t[j], b = t[(j + 1) % 3];
            if (adjacency.has_side(b, a))
              continue;
            ++n_boundary[a];
            ++n_boundary[b];
            if (is_cracked(a, b))
              {
                into[b] = a;
                out[a]  = b;
              }
          }
      std::vector<CrackTip> tips;
      for (unsigned int v = 0; v < n_vertices; ++v)
        // The far ends are two copies of one vertex (same initial
        // position); a node of a crack face has faces to two different
        // nodes on its side instead.
        if (n_boundary[v] == 2 && into[v] != none && out[v] != none &&
            into[v] != out[v] &&
            initial_vertices[into[v]] == initial_vertices[out[v]])
          {
            // A cell lies on the left of each side: the face running into
            // the tip has its cell on +y', the one running out on -y'.
            CrackTip tip;
            tip.vertex = v;
            tip.behind = {{into[v], out[v]}};
            // Back along the crack while it runs straight (within
            // max_turn of the last faces), up to max_faces faces: the jump
            // further from the tip is read with less of the error of the
            // last elements (doc/fracture.md).
            for (unsigned int d = 1; d < max_faces; ++d)
              {
                const unsigned int u = tip.behind[0], l = tip.behind[1];
                if (n_boundary[u] != 2 || n_boundary[l] != 2 ||
                    into[u] == none || out[l] == none || into[u] == out[l] ||
                    !(initial_vertices[into[u]] == initial_vertices[out[l]]))
                  break;
                const auto        &y = block_mesh.vertices;
                const Tensor<1, 2> last =
                  y[v] - 0.5 * (y[tip.behind[0]] + y[tip.behind[1]]);
                const Tensor<1, 2> next =
                  0.5 * (y[u] + y[l]) - 0.5 * (y[into[u]] + y[out[l]]);
                if (std::abs(angle_from(last, next)) > max_turn)
                  break;
                tip.behind = {{into[u], out[l]}};
              }
            const auto &x       = block_mesh.vertices;
            tip.outward         = x[v] - 0.5 * (x[into[v]] + x[out[v]]);
            const double length = tip.outward.norm();
            if (length == 0.)
              continue;
            tip.outward /= length;
            tips.push_back(tip);
          }
      return tips;
    }



    std::array<double, 2>
    stress_intensity_ratio(const CrackTip                      &tip,
                           const std::vector<dealii::Point<2>> &vertices,
                           const std::vector<dealii::Point<2>> &initial)
    {
      const auto        &b = tip.behind;
      const Tensor<1, 2> jump =
        (vertices[b[0]] - vertices[b[1]]) - (initial[b[0]] - initial[b[1]]);
      const Tensor<1, 2> normal = turned(tip.outward, M_PI / 2);
      return {{jump * normal, jump * tip.outward}};
    }



    double
    maximum_tangential_stress_angle(double k_I, const double k_II)
    {
      k_I            = std::max(k_I, 0.);
      const double s = std::sqrt(k_I * k_I + 8 * k_II * k_II);
      return s == 0. ? 0. : -2 * std::atan(2 * k_II / (k_I + s));
    }



    AdvancePlan
    plan_crack_advance(const CrackableMesh                            &mesh,
                       const std::vector<std::array<unsigned int, 2>> &failing,
                       const std::vector<dealii::Point<2>> &trial_vertices,
                       const double                         zone_radius,
                       const std::vector<InteriorEdge>     &crackable,
                       const std::vector<bool>             &fixed)
    {
      std::vector<std::uint64_t> may_crack;
      may_crack.reserve(crackable.size());
      for (const auto &edge : crackable)
        may_crack.push_back(key(std::min(edge.vertices[0], edge.vertices[1]),
                                std::max(edge.vertices[0], edge.vertices[1])));
      std::sort(may_crack.begin(), may_crack.end());
      const auto crackable_edge = [&](const unsigned int a,
                                      const unsigned int b) {
        return std::binary_search(may_crack.begin(),
                                  may_crack.end(),
                                  key(std::min(a, b), std::max(a, b)));
      };
      const auto &block_mesh = mesh.get_block_mesh();
      const auto &initial    = mesh.get_initial_vertices();
      // Positions as moves of this plan leave them.
      std::vector<Point<2>>       x = block_mesh.vertices;
      const Adjacency             adjacency(block_mesh);
      const std::vector<CrackTip> tips = find_crack_tips(mesh);

      const auto cells_at = [&](const unsigned int v) {
        return std::vector<unsigned int>(adjacency.cells.begin() +
                                           adjacency.offsets[v],
                                         adjacency.cells.begin() +
                                           adjacency.offsets[v + 1]);
      };
      // The vertices joined to v by an edge.
      const auto neighbours = [&](const unsigned int v) {
        std::vector<unsigned int> n;
        for (const unsigned int c : cells_at(v))
          for (const unsigned int w : block_mesh.triangles[c])
            if (w != v)
              n.push_back(w);
        std::sort(n.begin(), n.end());
        n.erase(std::unique(n.begin(), n.end()), n.end());
        return n;
      };

      // Each failing edge goes to the nearest tip of its block whose zone
      // holds its midpoint, or is cracked as it is. (Blocks share no
      // vertices: a vertex's block is that of any cell at it.)
      const auto block_of = [&](const unsigned int v) {
        return block_mesh.cell_block[adjacency.cells[adjacency.offsets[v]]];
      };
      std::vector<double> zone(tips.size());
      for (unsigned int k = 0; k < tips.size(); ++k)
        {
          const unsigned int t      = tips[k].vertex;
          const auto         around = neighbours(t);
          double             sum    = 0;
          for (const unsigned int w : around)
            sum += x[t].distance(x[w]);
          zone[k] = std::max(zone_radius, 2 * sum / around.size());
        }
      AdvancePlan                                           plan;
      std::vector<std::vector<std::array<unsigned int, 2>>> assigned(
        tips.size());
      for (const auto &edge : failing)
        {
          const Point<2> m(0.5 * (x[edge[0]] + x[edge[1]]));
          unsigned int   nearest = dealii::numbers::invalid_unsigned_int;
          double         best    = std::numeric_limits<double>::max();
          for (unsigned int k = 0; k < tips.size(); ++k)
            {
              const double r = m.distance(x[tips[k].vertex]);
              if (r <= zone[k] && r < best &&
                  block_of(tips[k].vertex) == block_of(edge[0]))
                {
                  best    = r;
                  nearest = k;
                }
            }
          if (nearest == dealii::numbers::invalid_unsigned_int)
            plan.edges.push_back(edge);
          else
            assigned[nearest].push_back(edge);
        }

      std::vector<bool> moved(x.size(), false);
      for (unsigned int k = 0; k < tips.size(); ++k)
        if (!assigned[k].empty())
          {
            const CrackTip    &tip = tips[k];
            const unsigned int t   = tip.vertex;
            TipAdvance         advance;
            advance.tip          = t;
            advance.tip_position = x[t];
            advance.initial_tip  = initial[t];
            advance.k = stress_intensity_ratio(tip, trial_vertices, initial);
            advance.mts_angle =
              maximum_tangential_stress_angle(advance.k[0], advance.k[1]);
            const Tensor<1, 2> direction =
              turned(tip.outward, advance.mts_angle);

            // Uncracked interior edges from the tip, nearest to the
            // direction first.
            std::vector<std::pair<double, unsigned int>> candidates;
            for (const unsigned int w : neighbours(t))
              if (adjacency.has_side(t, w) && adjacency.has_side(w, t) &&
                  !mesh.is_cracked(t, w) && crackable_edge(t, w))
                candidates.emplace_back(
                  std::abs(angle_from(direction, x[w] - x[t])), w);
            if (candidates.empty())
              {
                plan.edges.insert(plan.edges.end(),
                                  assigned[k].begin(),
                                  assigned[k].end());
                continue;
              }
            std::sort(candidates.begin(), candidates.end());

            unsigned int     target  = candidates.front().second;
            Point<2>         to      = x[target];
            bool             move    = false;
            constexpr double aligned = 0.5 * M_PI / 180;
            for (const auto &[off, w] : candidates)
              {
                if (candidates.front().first <= aligned || off > M_PI / 3)
                  break;
                if (moved[w] || (!fixed.empty() && fixed[w]) ||
                    !adjacency.is_interior(block_mesh, w))
                  continue;
                const auto star = cells_at(w);
                if (std::any_of(star.begin(),
                                star.end(),
                                [&](const unsigned c) {
                                  return block_mesh.cell_material[c] !=
                                         block_mesh.cell_material[star.front()];
                                }))
                  continue;
                double old_worst = M_PI;
                for (const unsigned int c : star)
                  {
                    const auto &tri = block_mesh.triangles[c];
                    old_worst =
                      std::min(old_worst,
                               smallest_angle(x[tri[0]], x[tri[1]], x[tri[2]]));
                  }
                const double bound = std::min(15 * M_PI / 180, old_worst);
                const double r     = x[w].distance(x[t]);
                for (const double s : {1., 0.8, 1.2, 0.6, 1.4, 0.5})
                  {
                    const Point<2> p  = x[t] + s * r * direction;
                    bool           ok = true;
                    for (const unsigned int c : star)
                      {
                        std::array<Point<2>, 3> q;
                        for (unsigned int j = 0; j < 3; ++j)
                          {
                            const unsigned int u = block_mesh.triangles[c][j];
                            q[j]                 = u == w ? p : x[u];
                          }
                        if (twice_area(q[0], q[1], q[2]) <= 0. ||
                            smallest_angle(q[0], q[1], q[2]) < bound)
                          {
                            ok = false;
                            break;
                          }
                      }
                    if (ok)
                      {
                        target = w;
                        to     = p;
                        move   = true;
                        break;
                      }
                  }
                if (move)
                  break;
              }

            advance.target              = target;
            advance.target_from         = x[target];
            advance.initial_target_from = initial[target];
            advance.target_to           = to;
            advance.initial_target_to   = initial[target];
            advance.moved               = move;
            if (move)
              {
                // The initial position, linear in the triangle around the
                // target that holds the new position (before the move).
                double best = -std::numeric_limits<double>::max();
                for (const unsigned int c : cells_at(target))
                  {
                    const auto  &tri = block_mesh.triangles[c];
                    const double a =
                      twice_area(x[tri[0]], x[tri[1]], x[tri[2]]);
                    std::array<double, 3> l;
                    for (unsigned int j = 0; j < 3; ++j)
                      l[j] = twice_area(to,
                                        x[tri[(j + 1) % 3]],
                                        x[tri[(j + 2) % 3]]) /
                             a;
                    const double worst = std::min({l[0], l[1], l[2]});
                    if (worst > best)
                      {
                        best                      = worst;
                        advance.initial_target_to = Point<2>(
                          l[0] * initial[tri[0]] + l[1] * initial[tri[1]] +
                          l[2] * initial[tri[2]]);
                      }
                  }
                x[target] = to;
                plan.moved.push_back(target);
                plan.position.push_back(to);
                plan.initial_position.push_back(advance.initial_target_to);
              }
            // A target is not moved again in this event (nor first
            // aligned for one tip, then moved for another).
            moved[target]      = true;
            advance.edge_angle = angle_from(tip.outward, to - x[t]);
            plan.edges.push_back({{t, target}});
            plan.advances.push_back(advance);
          }
      return plan;
    }
  } // namespace fracture
} // namespace ndda
