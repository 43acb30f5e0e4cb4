// SPDX-License-Identifier: GPL-3.0-or-later
//
// The narrow phase of ContactHandler::begin_step(): from the candidates of
// detect() to the contacts of a step, one function per contact type
// (vertex-edge, vertex-vertex, edge-edge as two vertex-edge);
// doc/contact.md, "From candidates to contacts".

#include <ndda/contact/contact_handler.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ndda
{
  namespace contact
  {
    namespace
    {
      /** Cosine of the largest angle between two edges taken as parallel. */
      constexpr double parallel_cosine = 0.99985; // 1 degree

      /** Cosine of the largest kink at a straight vertex. */
      constexpr double straight_cosine = 0.985; // 10 degrees

      double
      cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
      {
        return a[0] * b[1] - a[1] * b[0];
      }

      /** Outward unit normal of boundary edge @p e. */
      Tensor<1, 2>
      outward(const std::vector<Point<2>>     &vertices,
              const std::vector<BoundaryEdge> &edges,
              const unsigned int               e)
      {
        const Tensor<1, 2> t = vertices[edges[e].v1] - vertices[edges[e].v0];
        return Tensor<1, 2>({t[1], -t[0]}) / t.norm();
      }

      /**
       * Is @p vertex a straight vertex (two edges, kink below 10°), by the
       * edges' outward unit @p normal?
       */
      bool
      straight_vertex(const std::vector<Tensor<1, 2>>              &normal,
                      const std::vector<std::vector<unsigned int>> &at_vertex,
                      const unsigned int                            vertex)
      {
        const auto &at = at_vertex[vertex];
        return at.size() == 2 &&
               normal[at[0]] * normal[at[1]] >= straight_cosine;
      }

      /**
       * Is @p vertex a convex corner: two edges, the body on the left,
       * turning left by more than a straight vertex's kink and by less
       * than 180 degrees less that kink (a turn of 180 degrees, the tip of
       * a crack or of a spike, has no side)?
       */
      bool
      convex_corner(const std::vector<Point<2>>                  &vertices,
                    const std::vector<BoundaryEdge>              &edges,
                    const std::vector<std::vector<unsigned int>> &at_vertex,
                    const unsigned int                            vertex)
      {
        const auto &at = at_vertex[vertex];
        if (at.size() != 2)
          return false;
        const unsigned int  k   = edges[at[0]].v1 == vertex ? 0 : 1;
        const BoundaryEdge &in  = edges[at[k]];
        const BoundaryEdge &out = edges[at[1 - k]];
        const Tensor<1, 2>  a   = vertices[in.v1] - vertices[in.v0];
        const Tensor<1, 2>  b   = vertices[out.v1] - vertices[out.v0];
        return cross(a, b) > std::sqrt(1. - straight_cosine * straight_cosine) *
                               a.norm() * b.norm();
      }

      /**
       * Is @p vertex a straight vertex of a face that lies at a convex
       * corner (an end of @p e) where the corner touches the face (a
       * vertex-edge pair of @p vertex_edge on an edge at @p vertex more
       * than 10 degrees from lying on @p e: faces lying on each other
       * touch at all their vertices)? The corner touches the face then;
       * the face's vertex lies behind the corner's edges only within the
       * corner's penetration. A spring of it on a corner's edge acts on
       * the edge's line beyond the corner: a wall across the face that
       * stops a face sliding over the corner at each of its vertices.
       */
      bool
      face_vertex_at_corner(
        const std::vector<Point<2>>                              &vertices,
        const std::vector<BoundaryEdge>                          &edges,
        const std::vector<Tensor<1, 2>>                          &normal,
        const std::vector<std::vector<unsigned int>>             &at_vertex,
        const std::vector<std::pair<unsigned int, unsigned int>> &vertex_edge,
        const unsigned int                                        vertex,
        const unsigned int                                        e)
      {
        if (!straight_vertex(normal, at_vertex, vertex))
          return false;
        for (const unsigned int corner : {edges[e].v0, edges[e].v1})
          if (convex_corner(vertices, edges, at_vertex, corner))
            for (const unsigned int f : at_vertex[vertex])
              if (std::binary_search(vertex_edge.begin(),
                                     vertex_edge.end(),
                                     std::make_pair(corner, f)) &&
                  normal[e] * normal[f] > -straight_cosine)
                return true;
        return false;
      }

      /** The end of boundary edge @p e that is not @p v. */
      unsigned int
      other_end(const BoundaryEdge &e, const unsigned int v)
      {
        return e.v0 == v ? e.v1 : e.v0;
      }
    } // namespace



    Option
    ContactHandler::make_option(const std::vector<Point<2>> &vertices,
                                const unsigned int           vertex,
                                const unsigned int           edge) const
    {
      const BoundaryEdge &e = edges[edge];
      const Point<2>     &a = vertices[e.v0];
      const Point<2>     &b = vertices[e.v1];
      const Point<2>     &p = vertices[vertex];

      Option o;
      o.vertex             = vertex;
      o.edge               = edge;
      const Tensor<1, 2> t = b - a;
      o.length             = t.norm();
      o.tangent            = t / o.length;
      o.normal[0]          = o.tangent[1];
      o.normal[1]          = -o.tangent[0];
      o.ratio              = ((p - a) * t) / (o.length * o.length);
      o.gap                = (p - a) * o.normal;
      const double                     clamped = std::clamp(o.ratio, 0., 1.);
      const unsigned int               k       = e.local_vertex;
      const std::vector<unsigned int> &local   = edge_shapes.dofs(k);
      const unsigned int               n       = 2 + local.size();

      o.dofs.resize(n);
      o.wn.resize(n);
      o.wt.resize(n);
      for (unsigned int c = 0; c < 2; ++c)
        {
          o.dofs[c] = dofs->vertex_dofs[vertex][c];
          o.wn[c]   = o.normal[c];
          o.wt[c]   = o.tangent[c];
        }
      // The shape values go to wn first, then the entries are made.
      edge_shapes.values(k, clamped, &o.wn[2]);
      const global_dof_index *cell_dofs = dofs->dofs_of_cell(e.cell);
      for (unsigned int q = 0; q < local.size(); ++q)
        {
          const double       N = o.wn[2 + q];
          const unsigned int c = dofs->local_component[local[q]];
          o.dofs[2 + q]        = cell_dofs[local[q]];
          o.wn[2 + q]          = -N * o.normal[c];
          o.wt[2 + q]          = -N * o.tangent[c];
        }
      return o;
    }



    bool
    ContactHandler::in_cell(const unsigned int vertex,
                            const unsigned int edge) const
    {
      const unsigned int      n_cell_dofs = dofs->dofs_per_cell;
      const global_dof_index  dof         = dofs->vertex_dofs[vertex][0];
      const global_dof_index *cd = dofs->dofs_of_cell(edges[edge].cell);
      return std::find(cd, cd + n_cell_dofs, dof) != cd + n_cell_dofs;
    }



    void
    ContactHandler::compute_normals(const std::vector<Point<2>> &vertices)
    {
      edge_normal.resize(edges.size());
      for (unsigned int e = 0; e < edges.size(); ++e)
        edge_normal[e] = outward(vertices, edges, e);
      vertex_normal.resize(edges_at_vertex.size());
      for (unsigned int v = 0; v < edges_at_vertex.size(); ++v)
        {
          Tensor<1, 2> n;
          for (const unsigned int f : edges_at_vertex[v])
            n += edge_normal[f];
          vertex_normal[v] = n;
        }
      // A vertex inside a straight face of a rigid or affine block: two
      // collinear edges (to rounding: the face moves as a whole).
      passive.assign(edges_at_vertex.size(), false);
      if (reduced_block.empty() ||
          settings.law->bonds_initial_contacts(settings))
        return;
      for (unsigned int v = 0; v < edges_at_vertex.size(); ++v)
        if (const auto &at = edges_at_vertex[v];
            at.size() == 2 && edges[at[0]].block == edges[at[1]].block &&
            edges[at[0]].block < reduced_block.size() &&
            reduced_block[edges[at[0]].block])
          {
            const Tensor<1, 2> &n0 = edge_normal[at[0]];
            const Tensor<1, 2> &n1 = edge_normal[at[1]];
            passive[v] = n0 * n1 > 0 && std::abs(cross(n0, n1)) < 1e-8;
          }
    }



    bool
    ContactHandler::facing(const unsigned int vertex,
                           const unsigned int edge) const
    {
      const Tensor<1, 2> &n = vertex_normal[vertex];
      return n * edge_normal[edge] < -1e-3 * n.norm();
    }



    bool
    ContactHandler::remembered(const std::vector<Point<2>> &vertices,
                               const unsigned int           vertex,
                               const unsigned int           edge) const
    {
      return memory.contains(key(vertex, edge)) ||
             straight_neighbour_in_memory(vertices, vertex, edge) != invalid;
    }



    std::vector<ContactHandler::VertexEdge>
    ContactHandler::vertex_edge_pairs(
      const std::vector<Point<2>>  &vertices,
      const std::vector<Candidate> &candidates) const
    {
      // The candidates are sorted by vertex, then edge, and so is the
      // result.
      std::vector<VertexEdge> vertex_edge;
      for (auto first = candidates.begin(); first != candidates.end();)
        {
          auto last = first;
          while (last != candidates.end() && last->vertex == first->vertex)
            ++last;
          touched_edges(vertices, first, last, vertex_edge);
          first = last;
        }
      // A vertex of a straight face at the other block's convex corner,
      // where the corner touches that face: the corner touches the face,
      // not the face's vertex the corner's edges.
      std::vector<VertexEdge> kept;
      kept.reserve(vertex_edge.size());
      for (const VertexEdge &p : vertex_edge)
        if (!face_vertex_at_corner(vertices,
                                   edges,
                                   edge_normal,
                                   edges_at_vertex,
                                   vertex_edge,
                                   p.first,
                                   p.second))
          kept.push_back(p);
      return kept;
    }



    void
    ContactHandler::touched_edges(const std::vector<Point<2>> &vertices,
                                  std::vector<Candidate>::const_iterator first,
                                  std::vector<Candidate>::const_iterator last,
                                  std::vector<VertexEdge> &touched) const
    {
      boost::container::small_vector<const Candidate *, 8> list;
      for (auto c = first; c != last; ++c)
        {
          if (c->type != CandidateType::vertex_edge || passive[c->vertex] ||
              in_cell(c->vertex, c->edge) || !facing(c->vertex, c->edge))
            continue;
          if (c->distance < -settings.ignore_depth &&
              !remembered(vertices, c->vertex, c->edge))
            continue;
          list.push_back(&*c);
        }
      boost::container::small_vector<bool, 8> dropped(list.size(), false);
      for (unsigned int a = 0; a < list.size(); ++a)
        for (unsigned int b = a + 1; b < list.size(); ++b)
          {
            const BoundaryEdge &ea = edges[list[a]->edge];
            const BoundaryEdge &eb = edges[list[b]->edge];
            // Consecutive edges: in -> corner -> out.
            const BoundaryEdge *in = nullptr, *out = nullptr;
            if (ea.v1 == eb.v0)
              in = &ea, out = &eb;
            else if (eb.v1 == ea.v0)
              in = &eb, out = &ea;
            if (in == nullptr)
              continue;
            const Tensor<1, 2> t_in  = vertices[in->v1] - vertices[in->v0];
            const Tensor<1, 2> t_out = vertices[out->v1] - vertices[out->v0];
            if (cross(t_in, t_out) < -1e-12 * t_in.norm() * t_out.norm())
              continue; // concave corner: both faces may touch
            const bool ra =
              remembered(vertices, list[a]->vertex, list[a]->edge);
            const bool rb =
              remembered(vertices, list[b]->vertex, list[b]->edge);
            // Of two edges the vertex touches alike (it lies at their
            // corner, as a split vertex of a crack does on the other
            // face), the edge that enters the corner stays: a rule of the
            // boundary's orientation, not of the edges' numbers, which
            // follow the order of the cells.
            const double tie = 1e-9 * (t_in.norm() + t_out.norm());
            const double da = list[a]->distance, db = list[b]->distance;
            const bool   drop_a     = (ra != rb)              ? rb :
                                      std::abs(da - db) > tie ? da < db :
                                                                in != &ea;
            dropped[drop_a ? a : b] = true;
          }
      for (unsigned int a = 0; a < list.size(); ++a)
        if (!dropped[a])
          touched.emplace_back(list[a]->vertex, list[a]->edge);
    }



    void
    ContactHandler::add_vertex_edge_contacts(
      const std::vector<Point<2>>   &vertices,
      const std::vector<VertexEdge> &vertex_edge)
    {
      for (const auto &[v, e] : vertex_edge)
        {
          ContactPair &c = contacts.emplace_back();
          c.options.push_back(make_option(vertices, v, e));
          c.friction = std::min(edge_friction[e], vertex_friction[v]);
        }
    }



    bool
    ContactHandler::has_vertex_edge_at(
      const std::vector<VertexEdge> &vertex_edge,
      const unsigned int             vertex,
      const unsigned int             corner) const
    {
      AssertDimension(vertex_edge_start.back(), vertex_edge.size());
      for (unsigned int i = vertex_edge_start[vertex];
           i < vertex_edge_start[vertex + 1];
           ++i)
        if (const BoundaryEdge &e = edges[vertex_edge[i].second];
            e.v0 == corner || e.v1 == corner)
          return true;
      return false;
    }



    bool
    ContactHandler::nearer_elsewhere(const std::vector<Point<2>>  &vertices,
                                     const std::vector<Candidate> &candidates,
                                     const unsigned int            vertex,
                                     const unsigned int            other) const
    {
      const double reach =
        (1. - 1e-6) * vertices[vertex].distance(vertices[other]);
      const unsigned int block = edges[edges_at_vertex[other][0]].block;
      AssertDimension(candidate_start.back(), candidates.size());
      for (unsigned int i = candidate_start[vertex];
           i < candidate_start[vertex + 1];
           ++i)
        {
          const Candidate    *c = &candidates[i];
          const BoundaryEdge &e = edges[c->edge];
          if (e.block == block && e.v0 != other && e.v1 != other &&
              std::abs(c->distance) < reach && !in_cell(vertex, c->edge) &&
              facing(vertex, c->edge))
            return true;
        }
      return false;
    }



    std::vector<ContactHandler::VertexPair>
    ContactHandler::vertex_vertex_pairs(
      const std::vector<Point<2>>   &vertices,
      const std::vector<Candidate>  &candidates,
      const std::vector<VertexEdge> &vertex_edge) const
    {
      // The pairs of the candidates not in their edge's cell; every other
      // test is the pair's, made once for each pair.
      std::vector<std::pair<unsigned int, unsigned int>> found;
      for (const Candidate &c : candidates)
        if (c.type == CandidateType::vertex_vertex && !passive[c.vertex] &&
            !in_cell(c.vertex, c.edge))
          found.push_back(std::minmax(c.vertex,
                                      c.edge_ratio < 0.5 ? edges[c.edge].v0 :
                                                           edges[c.edge].v1));
      std::sort(found.begin(), found.end());
      found.erase(std::unique(found.begin(), found.end()), found.end());

      std::vector<VertexPair> pairs;
      for (const auto &[a, b] : found)
        {
          bool neighbours = false;
          for (const unsigned int e : edges_at_vertex[a])
            neighbours = neighbours || other_end(edges[e], a) == b;
          if (neighbours)
            continue;
          // A vertex-edge contact at the other vertex holds the pair,
          // unless faces lie on each other there and the other vertex has
          // no contact yet: it gets its own from the pair
          // (add_face_contact()).
          const bool a_at_b = has_vertex_edge_at(vertex_edge, a, b);
          const bool b_at_a = has_vertex_edge_at(vertex_edge, b, a);
          if (a_at_b && b_at_a)
            continue;
          const bool held = a_at_b || b_at_a;
          if ((held && !faces_meet(vertices, a, b)) ||
              (!passive[a] && nearer_elsewhere(vertices, candidates, a, b)) ||
              (!passive[b] && nearer_elsewhere(vertices, candidates, b, a)))
            continue;
          pairs.push_back({a, b, held || faces_meet(vertices, a, b)});
        }
      return pairs;
    }



    void
    ContactHandler::add_vertex_vertex_contacts(
      const std::vector<Point<2>>   &vertices,
      const std::vector<Candidate>  &candidates,
      const std::vector<VertexEdge> &vertex_edge)
    {
      for (const VertexPair &p :
           vertex_vertex_pairs(vertices, candidates, vertex_edge))
        if (passive[p.a] || passive[p.b])
          {
            // A vertex on a straight face of a rigid or affine block.
            const unsigned int w = passive[p.a] ? p.a : p.b;
            add_face_contact(vertices, vertex_edge, p.a + p.b - w, w);
          }
        else if (p.faces_meet)
          {
            add_face_contact(vertices, vertex_edge, p.a, p.b);
            add_face_contact(vertices, vertex_edge, p.b, p.a);
          }
        else
          add_vertex_vertex_contact(vertices, p.a, p.b);
    }



    bool
    ContactHandler::parallel_faces(const std::vector<Point<2>> &vertices,
                                   const unsigned int           a,
                                   const unsigned int           b,
                                   const unsigned int           e) const
    {
      const Tensor<1, 2> we = vertices[other_end(edges[e], b)] - vertices[b];
      for (const unsigned int f : edges_at_vertex[a])
        {
          const Tensor<1, 2> wf =
            vertices[other_end(edges[f], a)] - vertices[a];
          const double d = we * wf;
          if (d > 0 &&
              d * d > parallel_cosine * parallel_cosine * we.norm_square() *
                        wf.norm_square() &&
              facing(a, e) && facing(b, f))
            return true;
        }
      return false;
    }



    bool
    ContactHandler::faces_meet(const std::vector<Point<2>> &vertices,
                               const unsigned int           a,
                               const unsigned int           b) const
    {
      for (const unsigned int e : edges_at_vertex[b])
        if (parallel_faces(vertices, a, b, e))
          return true;
      return false;
    }



    void
    ContactHandler::add_face_contact(const std::vector<Point<2>>   &vertices,
                                     const std::vector<VertexEdge> &vertex_edge,
                                     const unsigned int             v,
                                     const unsigned int             w)
    {
      // None if v already touches an edge at w (the pair was found from
      // the other vertex's side, or v projects just inside one of w's
      // edges).
      if (has_vertex_edge_at(vertex_edge, v, w))
        return;
      // Of the faces at w that lie on a face at v (at a passive w: that v
      // faces), the one v projects farthest into (at a straight vertex w,
      // v lies just inside one of its two edges and just beyond the
      // other).
      unsigned int best   = invalid;
      double       inside = 0, ratio = 0;
      for (const unsigned int e : edges_at_vertex[w])
        if (passive[w] ? facing(v, e) : parallel_faces(vertices, v, w, e))
          {
            const Tensor<1, 2> t =
              vertices[edges[e].v1] - vertices[edges[e].v0];
            const double r =
              ((vertices[v] - vertices[edges[e].v0]) * t) / t.norm_square();
            // v at w: the two edges alike, the one that enters w stays
            // (as in touched_edges()).
            const double in = std::min(r, 1. - r);
            if (best == invalid || in > inside + 1e-9 ||
                (in > inside - 1e-9 && edges[e].v1 == w))
              best = e, inside = in, ratio = r;
          }
      if (best == invalid || ratio < -1e-3 || ratio > 1. + 1e-3)
        return; // v is beyond the faces: no overlap
      const Option o = make_option(vertices, v, best);
      if (o.ratio < -1e-6 || o.ratio > 1. + 1e-6)
        return;
      if (o.gap < -settings.ignore_depth && !remembered(vertices, v, best))
        return; // the other side of a thin body
      ContactPair &face = contacts.emplace_back();
      face.options.push_back(o);
      face.friction = std::min(vertex_friction[v], vertex_friction[w]);
    }



    void
    ContactHandler::add_vertex_vertex_contact(
      const std::vector<Point<2>> &vertices,
      const unsigned int           a,
      const unsigned int           b)
    {
      ContactPair c;
      c.vertex_a = a;
      c.vertex_b = b;
      for (const unsigned int e : edges_at_vertex[b])
        if (facing(a, e))
          c.options.push_back(make_option(vertices, a, e));
      for (const unsigned int f : edges_at_vertex[a])
        if (facing(b, f))
          c.options.push_back(make_option(vertices, b, f));
      if (c.options.empty())
        return;
      // A new pair whose vertex starts deep inside the other's corner
      // (behind both of its edges) is not a contact: the two vertices lie
      // on opposite sides of a thin body.
      bool known = memory.contains({a, b, invalid});
      for (const Option &o : c.options)
        known = known || remembered(vertices, o.vertex, o.edge);
      double depth = 0;
      for (const unsigned int v : {a, b})
        {
          double inside = std::numeric_limits<double>::max();
          for (const Option &o : c.options)
            if (o.vertex == v)
              inside = std::min(inside, -o.gap);
          if (inside < std::numeric_limits<double>::max())
            depth = std::max(depth, inside);
        }
      if (!known && depth > settings.ignore_depth)
        return;
      c.friction = std::min(vertex_friction[a], vertex_friction[b]);
      contacts.push_back(std::move(c));
    }
  } // namespace contact
} // namespace ndda
