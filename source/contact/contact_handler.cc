// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <deal.II/lac/full_matrix.h>

#include <ndda/contact/contact_handler.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace ndda
{
  namespace contact
  {
    namespace
    {
      /** Vertices of the reference triangle (deal.II's numbering). */
      const Point<2> unit_vertex[3] = {Point<2>(0, 0),
                                       Point<2>(1, 0),
                                       Point<2>(0, 1)};

      /** Cosine of the largest angle between two edges taken as parallel. */
      constexpr double parallel_cosine = 0.99985; // 1 degree

      /** Cosine of the largest kink at a vertex that a contact slides
       * over keeping its state. */
      constexpr double straight_cosine = 0.985; // 10 degrees

      double
      cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
      {
        return a[0] * b[1] - a[1] * b[0];
      }
    } // namespace



    void
    ContactHandler::initialize(const std::vector<BoundaryEdge> &edges_in,
                               const std::vector<double>       &friction_in,
                               const DofAccess                 &dofs_in,
                               const ContactSettings           &settings_in)
    {
      AssertDimension(edges_in.size(), friction_in.size());
      edges         = edges_in;
      edge_friction = friction_in;
      dofs          = dofs_in;
      settings      = settings_in;
      if (!settings.law)
        settings.law = create_contact_law(default_contact_law);

      const unsigned int n_vertices = dofs.vertex_dofs->size();
      edges_at_vertex.assign(n_vertices, {});
      vertex_friction.assign(n_vertices, std::numeric_limits<double>::max());
      for (unsigned int e = 0; e < edges.size(); ++e)
        for (const unsigned int v : {edges[e].v0, edges[e].v1})
          {
            edges_at_vertex[v].push_back(e);
            vertex_friction[v] = std::min(vertex_friction[v], edge_friction[e]);
          }
      block_edge_length.clear();
      contacts.clear();
      couplings.clear();
      memory.clear();
      open_last_step.clear();
      statistics = ContactStatistics();
    }



    void
    ContactHandler::carry_memory_from(const ContactHandler &old)
    {
      memory                  = old.memory;
      open_last_step          = old.open_last_step;
      first_step              = old.first_step;
      settings                = old.settings;
      statistics.contact_work = old.statistics.contact_work;
      statistics.dissipation  = old.statistics.dissipation;
    }



    void
    ContactHandler::set_normal_stiffness(const double k)
    {
      settings.normal_stiffness = k;
    }



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
      o.vertex                   = vertex;
      o.edge                     = edge;
      const Tensor<1, 2> t       = b - a;
      o.length                   = t.norm();
      o.tangent                  = t / o.length;
      o.normal[0]                = o.tangent[1];
      o.normal[1]                = -o.tangent[0];
      o.ratio                    = ((p - a) * t) / (o.length * o.length);
      o.gap                      = (p - a) * o.normal;
      const double       clamped = std::clamp(o.ratio, 0., 1.);
      const unsigned int k0      = e.local_vertex;
      const unsigned int k1      = (k0 + 1) % 3;
      const Point<2>     xi =
        unit_vertex[k0] + clamped * (unit_vertex[k1] - unit_vertex[k0]);
      const unsigned int n_cell_dofs = dofs.fe->n_dofs_per_cell();

      o.dofs.resize(2 + n_cell_dofs);
      o.wn.resize(2 + n_cell_dofs);
      o.wt.resize(2 + n_cell_dofs);
      for (unsigned int c = 0; c < 2; ++c)
        {
          o.dofs[c] = (*dofs.vertex_dofs)[vertex][c];
          o.wn[c]   = o.normal[c];
          o.wt[c]   = o.tangent[c];
        }
      const global_dof_index *cell_dofs =
        dofs.cell_dofs->data() + std::size_t(e.cell) * n_cell_dofs;
      for (unsigned int i = 0; i < n_cell_dofs; ++i)
        {
          const double       N = dofs.fe->shape_value(i, xi);
          const unsigned int c = (*dofs.component)[i];
          o.dofs[2 + i]        = cell_dofs[i];
          o.wn[2 + i]          = -N * o.normal[c];
          o.wt[2 + i]          = -N * o.tangent[c];
        }
      return o;
    }



    unsigned int
    ContactHandler::straight_neighbour_in_memory(
      const std::vector<Point<2>> &vertices,
      const unsigned int           vertex,
      const unsigned int           edge) const
    {
      // Only across a (nearly) straight vertex: round a corner the contact
      // direction changes, and so does the state.
      const Tensor<1, 2> t =
        vertices[edges[edge].v1] - vertices[edges[edge].v0];
      unsigned int found = invalid;
      for (const unsigned int w : {edges[edge].v0, edges[edge].v1})
        for (const unsigned int other : edges_at_vertex[w])
          if (other != edge && memory.count(key(vertex, other)) > 0)
            {
              const Tensor<1, 2> u =
                vertices[edges[other].v1] - vertices[edges[other].v0];
              if (u * t >= straight_cosine * u.norm() * t.norm())
                found = other; // the last one found, should there be two
            }
      return found;
    }



    void
    ContactHandler::transfer(Contact                     &c,
                             const std::vector<Point<2>> &vertices) const
    {
      c.state  = State::open;
      c.sign   = 0;
      c.chosen = invalid;
      if (c.vertex_a == invalid)
        {
          // A vertex-edge contact: its own memory, or that of the same
          // vertex on a neighbouring edge it has slid over from.
          const Option &o  = c.options[0];
          c.chosen         = 0;
          const auto found = memory.find(key(o.vertex, o.edge));
          if (found != memory.end())
            {
              c.state  = found->second.state;
              c.anchor = found->second.anchor;
              c.sign   = found->second.sign;
              c.offset = found->second.offset;
              c.bonded = found->second.bonded;
            }
          else if (const unsigned int other =
                     straight_neighbour_in_memory(vertices, o.vertex, o.edge);
                   other != invalid)
            {
              const Memory &near = memory.at(key(o.vertex, other));
              c.state            = near.state;
              c.sign             = near.sign;
              c.offset           = near.offset;
              // The old anchor point, projected on this edge.
              const Point<2> &a0 = vertices[edges[other].v0];
              const Point<2> &b0 = vertices[edges[other].v1];
              const Point<2>  x  = a0 + near.anchor * (b0 - a0);
              const Point<2> &a  = vertices[edges[o.edge].v0];
              c.anchor = ((x - a) * o.tangent) / o.length; // ratio on this edge
            }
        }
      else
        {
          for (unsigned int i = 0; i < c.options.size(); ++i)
            {
              const auto found =
                memory.find(key(c.options[i].vertex, c.options[i].edge));
              if (found != memory.end())
                {
                  c.chosen = i;
                  c.state  = found->second.state;
                  c.anchor = found->second.anchor;
                  c.sign   = found->second.sign;
                  c.offset = found->second.offset;
                  c.bonded = found->second.bonded;
                  break;
                }
            }
          if (c.chosen == invalid &&
              memory.count({c.vertex_a, c.vertex_b, invalid}) > 0)
            c.state = State::vertex_spring;
        }
      // An open contact starts without offset; a contact that is new and
      // already penetrates keeps its present penetration as its offset.
      if (c.state == State::open)
        c.offset =
          c.chosen != invalid ?
            std::min(0., c.options[c.chosen].gap + settings.state_tolerance) :
            0.;
      if (c.chosen != invalid)
        c.options[c.chosen].gap -= c.offset;
      // A contact closed at the last step's end that starts this step with
      // a gap (the geometry has moved on) starts open.
      if (c.state != State::open && c.chosen != invalid &&
          c.state != State::vertex_spring && !c.bonded &&
          c.options[c.chosen].gap > settings.state_tolerance)
        {
          c.state = State::open;
          c.sign  = 0;
          c.options[c.chosen].gap += c.offset;
          c.offset = 0;
        }
      // A new contact that already touches (no gap) starts closed: left
      // open, its vertex would first move freely through the whole step
      // and then hit the spring, an impact that an undamped integrator
      // keeps ringing. One that was open at the last step's end stays
      // open (faces that touch without force, such as the head joints of
      // a wall, would otherwise be closed and pulled open again in every
      // step, one open-close iteration each). A pair whose edge is not
      // chosen yet stays open.
      if (c.state == State::open && c.chosen != invalid &&
          c.options[c.chosen].gap <= settings.state_tolerance &&
          (c.vertex_a != invalid ||
           open_last_step.count(
             key(c.options[c.chosen].vertex, c.options[c.chosen].edge)) == 0))
        {
          c.state  = State::locked;
          c.anchor = c.options[c.chosen].ratio;
          // Faces that touch when the run starts are joints: the contact
          // law may bond them (cohesion and tension) until they break.
          c.bonded = first_step &&
                     settings.law->bonds_initial_contacts(settings) &&
                     c.vertex_a == invalid &&
                     bonding_side(c.options[0].vertex, c.options[0].edge);
        }
      // Open and sliding contacts anchor the shear spring at the vertex's
      // present projection, should they lock within this step.
      if (c.chosen != invalid && c.state != State::locked)
        c.anchor = c.options[c.chosen].ratio;
    }



    void
    ContactHandler::begin_step(const std::vector<Point<2>> &vertices,
                               const double                 threshold)
    {
      statistics.n_iterations = 0;
      contacts.clear();
      couplings.clear();
      if (block_edge_length.empty())
        {
          // On the first step's geometry: which side ties bonded joints.
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

      const std::vector<Candidate> candidates =
        detect(vertices, edges, threshold);
      statistics.n_candidates = candidates.size();

      const unsigned int n_cell_dofs = dofs.fe->n_dofs_per_cell();
      // Is the vertex one of the nodes of the edge's cell (the third vertex
      // of a thin triangle, or a mesh neighbour)?
      const auto in_cell = [&](const unsigned int v, const unsigned int e) {
        const global_dof_index  dof = (*dofs.vertex_dofs)[v][0];
        const global_dof_index *cd =
          dofs.cell_dofs->data() + std::size_t(edges[e].cell) * n_cell_dofs;
        return std::find(cd, cd + n_cell_dofs, dof) != cd + n_cell_dofs;
      };
      // Is there a state to carry over (see transfer()): the pair's own, or
      // that of the vertex on a neighbouring edge across a straight vertex?
      const auto remembered = [&](const unsigned int v, const unsigned int e) {
        return memory.count(key(v, e)) > 0 ||
               straight_neighbour_in_memory(vertices, v, e) != invalid;
      };
      const auto c_friction = [&](const unsigned int a, const unsigned int b) {
        return std::min(vertex_friction[a], vertex_friction[b]);
      };
      const auto other_end = [&](const unsigned int e, const unsigned int v) {
        return edges[e].v0 == v ? edges[e].v1 : edges[e].v0;
      };
      // A vertex can touch an edge only if they face each other: the
      // outward normal at the vertex (the mean of its edges' normals) and
      // the edge's normal point against each other. This rules out the
      // other vertices of the same straight side, every vertex of a
      // convex block against its own edges, and the far face of a thin
      // block.
      const auto outward = [&](const unsigned int e) {
        const Tensor<1, 2> t = vertices[edges[e].v1] - vertices[edges[e].v0];
        return Tensor<1, 2>({t[1], -t[0]}) / t.norm();
      };
      const auto facing = [&](const unsigned int v, const unsigned int e) {
        Tensor<1, 2> n;
        for (const unsigned int f : edges_at_vertex[v])
          n += outward(f);
        return n * outward(e) < -1e-3 * n.norm();
      };

      // 1. Vertex-edge candidates. A vertex near a convex (or straight)
      // corner of a boundary may project into both edges there; it then
      // touches one of them: the remembered one, else the one it is
      // farthest outside of. New candidates that start deep inside the
      // other body (the far face of a thin block) are not contacts.
      std::vector<std::pair<unsigned int, unsigned int>> vertex_edge;
      for (std::size_t i = 0; i < candidates.size();)
        {
          std::size_t j = i;
          while (j < candidates.size() &&
                 candidates[j].vertex == candidates[i].vertex)
            ++j;
          std::vector<const Candidate *> list;
          for (std::size_t k = i; k < j; ++k)
            {
              const Candidate &c = candidates[k];
              if (c.type != CandidateType::vertex_edge ||
                  in_cell(c.vertex, c.edge) || !facing(c.vertex, c.edge))
                continue;
              if (c.distance < -settings.ignore_depth &&
                  !remembered(c.vertex, c.edge))
                continue;
              list.push_back(&c);
            }
          std::vector<bool> dropped(list.size(), false);
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
                const Tensor<1, 2> t_in = vertices[in->v1] - vertices[in->v0];
                const Tensor<1, 2> t_out =
                  vertices[out->v1] - vertices[out->v0];
                if (cross(t_in, t_out) < -1e-12 * t_in.norm() * t_out.norm())
                  continue; // concave corner: both faces may touch
                const bool ra = remembered(list[a]->vertex, list[a]->edge);
                const bool rb = remembered(list[b]->vertex, list[b]->edge);
                const bool drop_a =
                  (ra != rb) ? rb : list[a]->distance < list[b]->distance;
                dropped[drop_a ? a : b] = true;
              }
          for (unsigned int a = 0; a < list.size(); ++a)
            if (!dropped[a])
              vertex_edge.emplace_back(list[a]->vertex, list[a]->edge);
          i = j;
        }
      // vertex_edge is sorted by vertex, then edge (the candidates are).
      const auto has_vertex_edge_at = [&](const unsigned int v,
                                          const unsigned int corner) {
        auto range = std::equal_range(vertex_edge.begin(),
                                      vertex_edge.end(),
                                      std::make_pair(v, 0u),
                                      [](const auto &x, const auto &y) {
                                        return x.first < y.first;
                                      });
        for (auto it = range.first; it != range.second; ++it)
          if (edges[it->second].v0 == corner || edges[it->second].v1 == corner)
            return true;
        return false;
      };

      for (const auto &[v, e] : vertex_edge)
        {
          Contact c;
          c.options.push_back(make_option(vertices, v, e));
          c.friction = std::min(edge_friction[e], vertex_friction[v]);
          contacts.push_back(std::move(c));
        }

      // 2. Vertex-vertex pairs: a vertex whose closest point on an edge is
      // that edge's end vertex, unless one of the two already touches an
      // edge at the other (then that vertex-edge contact holds the pair).
      std::set<std::pair<unsigned int, unsigned int>> pairs;
      for (const Candidate &c : candidates)
        if (c.type == CandidateType::vertex_vertex)
          {
            const unsigned int corner =
              c.edge_ratio < 0.5 ? edges[c.edge].v0 : edges[c.edge].v1;
            if (in_cell(c.vertex, c.edge) ||
                has_vertex_edge_at(c.vertex, corner))
              continue;
            pairs.insert(std::minmax(c.vertex, corner));
          }
      for (const auto &[a, b] : pairs)
        {
          if (has_vertex_edge_at(b, a))
            continue;
          bool neighbours = false;
          for (const unsigned int e : edges_at_vertex[a])
            neighbours = neighbours || other_end(e, a) == b;
          if (neighbours)
            continue;

          // Edge-edge: an edge e at b and an edge f at a leave the pair in
          // the same direction and overlap. Then nothing is indeterminate:
          // a touches e and b touches f, each at the end point of the
          // edge. Both contacts are kept, so that when the corners move
          // apart the one whose vertex slides onto the other's edge goes
          // on with its state, and no contact appears already compressed.
          unsigned int face_e = invalid, face_f = invalid;
          for (const unsigned int e : edges_at_vertex[b])
            for (const unsigned int f : edges_at_vertex[a])
              {
                Tensor<1, 2> we = vertices[other_end(e, b)] - vertices[b];
                Tensor<1, 2> wf = vertices[other_end(f, a)] - vertices[a];
                if (we * wf > parallel_cosine * we.norm() * wf.norm() &&
                    facing(a, e) && facing(b, f))
                  face_e = e, face_f = f;
              }
          Contact c;
          if (face_e != invalid)
            {
              for (const auto &[v, e] :
                   {std::make_pair(a, face_e), std::make_pair(b, face_f)})
                {
                  // Already a vertex-edge contact (the pair was found from
                  // the other vertex's side): not twice.
                  if (std::binary_search(vertex_edge.begin(),
                                         vertex_edge.end(),
                                         std::make_pair(v, e)))
                    continue;
                  Contact face;
                  face.options.push_back(make_option(vertices, v, e));
                  const Option &o = face.options[0];
                  if (o.ratio < -1e-6 || o.ratio > 1. + 1e-6)
                    continue; // v is beyond the edge: no overlap
                  if (o.gap < -settings.ignore_depth && !remembered(v, e))
                    continue; // the other side of a thin body
                  face.friction = c_friction(a, b);
                  contacts.push_back(std::move(face));
                }
              continue;
            }
          else
            {
              c.vertex_a = a;
              c.vertex_b = b;
              for (const unsigned int e : edges_at_vertex[b])
                if (facing(a, e))
                  c.options.push_back(make_option(vertices, a, e));
              for (const unsigned int f : edges_at_vertex[a])
                if (facing(b, f))
                  c.options.push_back(make_option(vertices, b, f));
              if (c.options.empty())
                continue;
              // A new pair whose vertex starts deep inside the other's
              // corner (behind both of its edges) is not a contact: the
              // two vertices lie on opposite sides of a thin body.
              bool known = false;
              for (const Option &o : c.options)
                known = known || remembered(o.vertex, o.edge);
              known =
                known || memory.count({c.vertex_a, c.vertex_b, invalid}) > 0;
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
                continue;
            }
          c.friction = c_friction(a, b);
          contacts.push_back(std::move(c));
        }

      for (Contact &c : contacts)
        transfer(c, vertices);
      // A bonded joint is tied from one side: contacts from the other side
      // on an edge whose end vertex is bonded to the contact vertex's
      // block stay open.
      std::set<std::pair<unsigned int, unsigned int>> bonded_to;
      for (const Contact &c : contacts)
        if (c.bonded)
          bonded_to.emplace(c.options[c.chosen].vertex,
                            edges[c.options[c.chosen].edge].block);
      for (Contact &c : contacts)
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
      for (Contact &c : contacts)
        {
          if (c.bonded)
            c.bond_length = bond_length(vertices,
                                        c.options[c.chosen].vertex,
                                        c.options[c.chosen].edge);
          c.start        = c;
          c.start_chosen = c.chosen;
          c.start_bonded = c.bonded;
          for (const Option &o : c.options)
            couplings.emplace_back(o.vertex, edges[o.edge].cell);
        }
      std::sort(couplings.begin(), couplings.end());
      couplings.erase(std::unique(couplings.begin(), couplings.end()),
                      couplings.end());
      statistics.n_contacts = contacts.size();
    }



    void
    ContactHandler::restart_step()
    {
      statistics.n_iterations = 0;
      for (Contact &c : contacts)
        {
          c.flips                        = 0;
          c.scale                        = 1;
          static_cast<ContactState &>(c) = c.start;
          c.chosen                       = c.start_chosen;
          c.bonded                       = c.start_bonded;
        }
    }



    bool
    ContactHandler::has_springs() const
    {
      for (const Contact &c : contacts)
        if (c.state != State::open)
          return true;
      return false;
    }



    void
    ContactHandler::assemble(dealii::SparseMatrix<double> &matrix,
                             dealii::Vector<double>       &rhs) const
    {
      const double kn = settings.normal_stiffness;
      for (const Contact &c : contacts)
        {
          if (c.state == State::vertex_spring)
            {
              // Thesis 6.5-6.12: a spring on the relative displacement of
              // the two vertices in this step, a hinge between them.
              const auto &da = (*dofs.vertex_dofs)[c.vertex_a];
              const auto &db = (*dofs.vertex_dofs)[c.vertex_b];
              for (unsigned int i = 0; i < 2; ++i)
                {
                  matrix.add(da[i], da[i], kn);
                  matrix.add(db[i], db[i], kn);
                  matrix.add(da[i], db[i], -kn);
                  matrix.add(db[i], da[i], -kn);
                }
              continue;
            }
          if (c.state == State::open || c.chosen == invalid)
            continue;
          add_springs(c.options[c.chosen], c, c.scale, &matrix, rhs);
        }
    }



    void
    ContactHandler::add_springs(const Option                 &o,
                                const ContactState           &contact,
                                const double                  scale,
                                dealii::SparseMatrix<double> *matrix,
                                dealii::Vector<double>       &rhs) const
    {
      if (matrix == nullptr)
        {
          settings.law->add_springs(o, contact, scale, settings, nullptr, rhs);
          return;
        }
      // The springs' stiffness as one dense n x n block, added to the
      // sparse matrix row by row (one search per row, not per entry).
      const unsigned int         n = o.dofs.size();
      dealii::FullMatrix<double> k(n, n);
      settings.law->add_springs(o, contact, scale, settings, &k, rhs);
      for (unsigned int i = 0; i < n; ++i)
        matrix->add(o.dofs[i], n, o.dofs.data(), &k(i, 0), false, false);
    }



    void
    ContactHandler::start_forces(dealii::Vector<double> &force) const
    {
      // The contacts closed at both ends of the step with their full start
      // force; those that open within the step with the fraction of it
      // that makes their work equal to the spring energy they release
      // (scale, see update_states()).
      force = 0;
      for (const Contact &c : contacts)
        {
          const bool closed_at_start =
            c.start_chosen != invalid &&
            (c.start.state == State::locked || c.start.state == State::sliding);
          if (!closed_at_start)
            continue;
          double scale = 0;
          if (c.state == State::locked || c.state == State::sliding)
            scale = c.chosen == c.start_chosen ? 1. : 0.;
          else if (c.state == State::open)
            scale = c.scale;
          if (scale > 0.)
            add_springs(
              c.options[c.start_chosen], c.start, scale, nullptr, force);
        }
    }



    void
    ContactHandler::newmark_correction(dealii::Vector<double> &force) const
    {
      // The contact forces the inertia force holds from the last step's
      // end are replaced by the start forces of the contacts that are
      // closed at both ends of this step.
      start_forces(force);
      if (end_force.size() == force.size())
        force -= end_force;
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



    unsigned int
    ContactHandler::entrance_option(const Contact                   &c,
                                    const std::vector<unsigned int> &inside,
                                    const dealii::Vector<double>    &d) const
    {
      unsigned int shortest = inside[0];
      for (const unsigned int i : inside)
        if (c.options[i].normal_gap(d) > c.options[shortest].normal_gap(d))
          shortest = i;
      if (settings.vertex_vertex_method ==
          parameters::VertexVertexMethod::shortest_path)
        return shortest;

      // Thesis 6.3: the vertex entered through the edge whose segment (not
      // its extension, 6.18) its straight trajectory crossed first.
      unsigned int best   = invalid;
      double       best_t = std::numeric_limits<double>::max();
      bool         tie    = false;
      for (const unsigned int i : inside)
        {
          const Option &o  = c.options[i];
          const double  g0 = o.gap, g1 = o.normal_gap(d);
          if (g0 < 0. || g1 >= 0.)
            continue;
          const double t = g0 / (g0 - g1);
          const double r = o.ratio + t * o.tangential_increment(d) / o.length;
          if (r < -1e-9 || r > 1. + 1e-9)
            continue;
          if (t < best_t - 1e-9)
            {
              best   = i;
              best_t = t;
              tie    = false;
            }
          else if (t <= best_t + 1e-9)
            tie = true;
        }
      if (best == invalid)
        return shortest; // penetrating from the start: no trajectory
      return tie ? invalid : best;
    }



    unsigned int
    ContactHandler::sliding_option(const Contact                &c,
                                   const dealii::Vector<double> &d) const
    {
      // Thesis 6.2: after a solve with the temporary spring, the vertex
      // slides onto the edge most aligned with its motion relative to the
      // other vertex. (The thesis compares sin of the angles; ndda compares
      // the angles themselves, so that an edge pointing against the motion
      // is never chosen.)
      unsigned int best     = invalid;
      double       best_cos = -2, second_cos = -2;
      for (unsigned int i = 0; i < c.options.size(); ++i)
        {
          const Option      &o = c.options[i];
          const unsigned int corner =
            o.vertex == c.vertex_a ? c.vertex_b : c.vertex_a;
          Tensor<1, 2> u;
          for (unsigned int k = 0; k < 2; ++k)
            u[k] = d[(*dofs.vertex_dofs)[o.vertex][k]] -
                   d[(*dofs.vertex_dofs)[corner][k]];
          if (u.norm() == 0.)
            return invalid;
          const Tensor<1, 2> r =
            edges[o.edge].v0 == corner ? o.tangent : -o.tangent;
          const double cosine = (r * u) / u.norm();
          if (cosine > best_cos)
            {
              second_cos = best_cos;
              best_cos   = cosine;
              best       = i;
            }
          else if (cosine > second_cos)
            second_cos = cosine;
        }
      return (best_cos - second_cos < 1e-9) ? invalid : best;
    }



    bool
    ContactHandler::update_scale(Contact &c, const dealii::Vector<double> &d)
    {
      // A spring that engages or lets go within the step acts for part of
      // it only. With the average of start and end forces (Newmark), the
      // energy-consistent force of the one-sided spring
      // Phi(g) = kn/2 min(g, 0)^2 is -(Phi(g1) - Phi(g0)) / (g1 - g0)
      // (a discrete gradient): for a contact that closes from the gap
      // g0 > 0 to g1 < 0 it is the end force times g1 / (g1 - g0), for one
      // that opens from g0 < 0 to g1 > 0 the start force times
      // g0 / (g0 - g1). Without it, every impact would lose kn g0 g1 / 2.
      const bool closed_at_start =
        c.start_chosen != invalid &&
        (c.start.state == State::locked || c.start.state == State::sliding);
      const bool closed_now =
        c.state == State::locked || c.state == State::sliding;
      double scale = 1;
      if (closed_now && !closed_at_start)
        {
          const Option &o  = c.options[c.chosen];
          const double  g0 = o.gap, g1 = o.normal_gap(d);
          if (g0 > 0. && g1 < 0.)
            scale = g1 / (g1 - g0);
        }
      else if (!closed_now && closed_at_start)
        {
          const Option &o  = c.options[c.start_chosen];
          const double  g0 = o.gap, g1 = o.normal_gap(d);
          scale = (g0 < 0. && g1 > 0.) ? g0 / (g0 - g1) : 0.;
        }
      const bool changed =
        std::abs(scale - c.scale) > 1e-3 * std::max(scale, c.scale);
      c.scale = scale;
      return changed;
    }



    bool
    ContactHandler::update_states(const dealii::Vector<double> &d)
    {
      bool changed = false;
      for (Contact &c : contacts)
        {
          if (c.chosen == invalid)
            {
              // An unresolved vertex-vertex pair.
              unsigned int option = invalid;
              if (c.state == State::vertex_spring)
                {
                  option = sliding_option(c, d);
                  if (option == invalid)
                    continue; // symmetric: the spring stays
                }
              else
                {
                  // A vertex has entered the other's corner if it ends
                  // behind the lines of both edges there, within their
                  // lengths.
                  std::vector<unsigned int> inside;
                  for (const unsigned int v : {c.vertex_a, c.vertex_b})
                    {
                      std::vector<unsigned int> mine;
                      bool                      all = true;
                      for (unsigned int i = 0; i < c.options.size(); ++i)
                        if (c.options[i].vertex == v)
                          {
                            const Option &o = c.options[i];
                            const double  r =
                              o.ratio + o.tangential_increment(d) / o.length;
                            all = all &&
                                  o.normal_gap(d) < -settings.state_tolerance &&
                                  r > -1e-9 && r < 1. + 1e-9;
                            mine.push_back(i);
                          }
                      if (all)
                        inside.insert(inside.end(), mine.begin(), mine.end());
                    }
                  if (inside.empty())
                    continue;
                  option = entrance_option(c, inside, d);
                  if (option == invalid)
                    {
                      c.state = State::vertex_spring;
                      changed = true;
                      continue;
                    }
                }
              const Option &o = c.options[option];
              c.chosen        = option;
              c.anchor        = o.ratio;
              c.state         = State::open;
              int sign;
              c.state =
                settings.law->classify(o, c, Trial(o, d), settings, sign);
              c.sign = sign;
              if (c.state == State::open)
                c.chosen = invalid;
              if (settings.average_start_and_end)
                update_scale(c, d);
              changed = true;
              continue;
            }

          if (c.shadowed)
            continue;
          const ContactLaw &law = *settings.law;
          const Option     &o   = c.options[c.chosen];
          const Trial       trial(o, d);
          int               sign;
          State             state = State::locked;
          if (c.bonded && law.bond_holds(o, c, trial, settings))
            sign = 0;
          else
            {
              c.bonded = false; // broken for good
              state    = law.classify(o, c, trial, settings, sign);
            }
          // Contacts that carry almost no force can make the iteration
          // cycle (closing one opens another). A contact that has changed
          // between open and closed three times in this step may still
          // close but no longer open in this step: it holds a little
          // tension rather than letting its vertex through.
          if ((state == State::open) != (c.state == State::open))
            {
              if (c.flips >= 3 && state == State::open)
                state = c.state, sign = c.sign;
              else
                ++c.flips;
            }
          if (state != c.state || sign != c.sign)
            changed = true;
          if (state == State::locked && c.state != State::locked)
            c.anchor = law.anchor_on_locking(o, c, trial, settings);
          c.state = state;
          c.sign  = sign;
          if (state == State::open && c.vertex_a != invalid)
            c.chosen = invalid; // a pair that separates is open again
          // The scale depends on the solution it enters: a few
          // iterations make it consistent; after that it is accepted as it
          // is rather than cutting the step.
          if (settings.average_start_and_end && update_scale(c, d) &&
              statistics.n_iterations < 4)
            changed = true;
        }
      return changed;
    }



    double
    ContactHandler::max_penetration(const dealii::Vector<double> &d) const
    {
      double p = 0;
      for (const Contact &c : contacts)
        if (c.chosen != invalid &&
            (c.state == State::locked || c.state == State::sliding))
          p = std::max(p, -c.options[c.chosen].normal_gap(d) - c.offset);
      return p;
    }



    void
    ContactHandler::end_step(const dealii::Vector<double> &d)
    {
      const double kn = settings.normal_stiffness;
      memory.clear();
      open_last_step.clear();
      statistics.n_closed         = 0;
      statistics.n_sliding        = 0;
      statistics.n_vertex_springs = 0;
      statistics.n_vertex_vertex  = 0;
      statistics.spring_energy    = 0;
      statistics.max_penetration  = max_penetration(d);
      statistics.n_bonded         = 0;
      statistics.bonded_length    = 0;
      first_step                  = false;
      // The forces the integrator applied over the step: at its end (DDA)
      // or the mean of start and end (Newmark).
      dealii::Vector<double> applied(d.size());
      if (settings.average_start_and_end)
        {
          start_forces(applied);
          applied *= 0.5;
        }
      end_force.reinit(d.size());
      for (const Contact &c : contacts)
        {
          if (c.vertex_a != invalid)
            ++statistics.n_vertex_vertex;
          if (c.state == State::vertex_spring)
            {
              ++statistics.n_vertex_springs;
              memory[{c.vertex_a, c.vertex_b, invalid}] = {
                c.state, 0., 0, 0., false};
              Tensor<1, 2> u;
              for (unsigned int k = 0; k < 2; ++k)
                u[k] = d[(*dofs.vertex_dofs)[c.vertex_a][k]] -
                       d[(*dofs.vertex_dofs)[c.vertex_b][k]];
              statistics.spring_energy += 0.5 * kn * u.norm_square();
              for (unsigned int k = 0; k < 2; ++k)
                {
                  end_force[(*dofs.vertex_dofs)[c.vertex_a][k]] -= kn * u[k];
                  end_force[(*dofs.vertex_dofs)[c.vertex_b][k]] += kn * u[k];
                }
              continue;
            }
          if (c.state == State::open && c.vertex_a == invalid)
            open_last_step.insert(
              key(c.options[c.chosen].vertex, c.options[c.chosen].edge));
          if (c.state == State::open || c.chosen == invalid)
            continue;
          ++statistics.n_closed;
          const Option &o = c.options[c.chosen];
          const Trial   trial(o, d);
          statistics.spring_energy +=
            settings.law->energy(o, c, trial, settings);
          // The force at the step's end: the springs' forces at d = 0 on
          // the geometry of the step's end (the solution's gap and, for a
          // locked contact, its shear displacement).
          {
            Option at_end             = o;
            at_end.gap                = trial.gap;
            ContactState state_at_end = c;
            if (c.state == State::locked)
              state_at_end.anchor -= trial.increment / o.length;
            add_springs(at_end, state_at_end, c.scale, nullptr, end_force);
          }
          double anchor = c.anchor;
          if (c.state != State::locked)
            {
              ++statistics.n_sliding;
              anchor = o.ratio + trial.increment / o.length;
            }
          if (c.bonded)
            {
              ++statistics.n_bonded;
              statistics.bonded_length += c.bond_length;
            }
          memory[key(o.vertex, o.edge)] = {
            c.state, anchor, c.sign, c.offset, c.bonded};
        }
      applied.add(settings.average_start_and_end ? 0.5 : 1., end_force);
      statistics.contact_work += applied * d;
      statistics.dissipation =
        -statistics.contact_work - statistics.spring_energy;
    }
  } // namespace contact
} // namespace ndda
