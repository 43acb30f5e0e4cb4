// SPDX-License-Identifier: GPL-3.0-or-later
//
// The geometry of bonded joints: which side ties a joint, the length of
// joint each bonded contact stands for, and the shadowed contacts of the
// other side (doc/contact.md, "Bonded joints"). Whether a joint is bonded
// and whether a bond holds is the contact law's (ContactLaw).

#include <deal.II/base/numbers.h>

#include <ndda/contact/contact_handler.h>

#include <algorithm>
#include <cmath>

namespace ndda
{
  namespace contact
  {
    void
    ContactHandler::measure_block_edges(const std::vector<Point<2>> &vertices)
    {
      std::vector<unsigned int> n(edges.size() > 0 ? 1 : 0, 0);
      for (const BoundaryEdge &e : edges)
        {
          if (e.block >= block_edge_length.size())
            {
              block_edge_length.resize(e.block + 1, 0.);
              n.resize(e.block + 1, 0);
            }
          block_edge_length[e.block] +=
            (vertices[e.v1] - vertices[e.v0]).norm();
          ++n[e.block];
        }
      for (unsigned int b = 0; b < n.size(); ++b)
        if (n[b] > 0)
          block_edge_length[b] /= n[b];
    }



    bool
    ContactHandler::bonding_side(const unsigned int vertex,
                                 const unsigned int edge) const
    {
      const unsigned int own   = edges[edges_at_vertex[vertex][0]].block;
      const unsigned int other = edges[edge].block;
      if (own == other)
        return vertex < std::min(edges[edge].v0, edges[edge].v1);
      const double a = block_edge_length[own], b = block_edge_length[other];
      if (std::abs(a - b) > 1e-9 * std::max(a, b))
        return a < b;
      return own < other;
    }



    double
    ContactHandler::bond_length(const std::vector<Point<2>> &vertices,
                                const unsigned int           vertex,
                                const unsigned int           edge) const
    {
      const double parallel = std::cos(10. * dealii::numbers::PI / 180.);
      // The interval of boundary edge e (as distances from its first
      // vertex) that lies on edge f, if the two run against each other.
      const auto overlap = [&](const unsigned int e, const unsigned int f) {
        const Point<2> &p      = vertices[edges[e].v0];
        Tensor<1, 2>    t      = vertices[edges[e].v1] - p;
        const double    length = t.norm();
        t /= length;
        const Point<2> &a  = vertices[edges[f].v0];
        const Point<2> &b  = vertices[edges[f].v1];
        const double    ra = (a - p) * t, rb = (b - p) * t;
        if (ra - rb < parallel * (b - a).norm()) // not antiparallel
          return std::make_pair(0., 0.);
        return std::make_pair(std::max(rb, 0.), std::min(ra, length));
      };
      double sum = 0;
      for (const unsigned int e : edges_at_vertex[vertex])
        {
          auto [lo, hi] = overlap(e, edge);
          if (hi <= lo)
            continue;
          // Along the other side's boundary beyond either end of the edge,
          // as long as it stays on e.
          for (const unsigned int start : {edges[edge].v0, edges[edge].v1})
            {
              unsigned int at = start, current = edge;
              for (unsigned int n = 0; n < 1000; ++n)
                {
                  unsigned int next = invalid;
                  for (const unsigned int f : edges_at_vertex[at])
                    if (f != current)
                      next = f;
                  if (next == invalid)
                    break;
                  const auto [l, h] = overlap(e, next);
                  if (h <= l || l > hi + 1e-12 * h || h < lo - 1e-12 * h)
                    break;
                  lo      = std::min(lo, l);
                  hi      = std::max(hi, h);
                  current = next;
                  at = edges[next].v0 == at ? edges[next].v1 : edges[next].v0;
                }
            }
          const double length =
            (vertices[edges[e].v1] - vertices[edges[e].v0]).norm();
          // Does the joint reach the edge's other end?
          const bool other_end_on_joint = edges[e].v0 == vertex ?
                                            hi > length * (1. - 1e-9) :
                                            lo < length * 1e-9;
          sum += (other_end_on_joint ? 0.5 : 1.) * (hi - lo);
        }
      return sum;
    }



    void
    ContactHandler::shadow_bonded_joints()
    {
      // The (vertex, block) pairs that bonded contacts tie together.
      std::set<std::pair<unsigned int, unsigned int>> bonded_to;
      for (const ContactPair &c : contacts)
        if (c.bonded)
          bonded_to.emplace(c.options[c.chosen].vertex,
                            edges[c.options[c.chosen].edge].block);
      for (ContactPair &c : contacts)
        {
          c.shadowed = false;
          if (!bonded_to.empty() && !c.bonded && c.vertex_a == invalid)
            {
              const Option      &o = c.options[0];
              const unsigned int block =
                edges[edges_at_vertex[o.vertex][0]].block;
              c.shadowed = bonded_to.count({edges[o.edge].v0, block}) > 0 ||
                           bonded_to.count({edges[o.edge].v1, block}) > 0;
              if (c.shadowed)
                {
                  c.state = State::open;
                  c.sign  = 0;
                }
            }
        }
    }
  } // namespace contact
} // namespace ndda
