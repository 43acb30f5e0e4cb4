// SPDX-License-Identifier: GPL-3.0-or-later
//
// What a contact carries from one step to the next: state, reference edge,
// anchor, offset and bond (doc/contact.md, "From candidates to contacts",
// item 4).

#include <ndda/contact/contact_handler.h>

#include <algorithm>

namespace ndda
{
  namespace contact
  {
    namespace
    {
      /** Cosine of the largest kink at a vertex that a contact slides
       * over keeping its state. */
      constexpr double straight_cosine = 0.985; // 10 degrees
    }                                           // namespace



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
          if (other != edge && memory.contains(key(vertex, other)))
            {
              const Tensor<1, 2> u =
                vertices[edges[other].v1] - vertices[edges[other].v0];
              if (u * t >= straight_cosine * u.norm() * t.norm())
                found = other; // the last one found, should there be two
            }
      return found;
    }



    void
    ContactHandler::recall(ContactPair                 &c,
                           const std::vector<Point<2>> &vertices) const
    {
      const auto restore = [&c](const Memory &m) {
        c.state  = m.state;
        c.anchor = m.anchor;
        c.sign   = m.sign;
        c.offset = m.offset;
        c.bonded = m.bonded;
      };
      if (c.vertex_a == invalid)
        {
          // A vertex-edge contact: its own memory, or that of the same
          // vertex on a neighbouring edge it has slid over from.
          const Option &o = c.options[0];
          c.chosen        = 0;
          if (const Memory *found = memory.find(key(o.vertex, o.edge)))
            restore(*found);
          else if (const unsigned int other =
                     straight_neighbour_in_memory(vertices, o.vertex, o.edge);
                   other != invalid)
            {
              const Memory &near = *memory.find(key(o.vertex, other));
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
          return;
        }
      for (unsigned int i = 0; i < c.options.size(); ++i)
        {
          if (const Memory *found =
                memory.find(key(c.options[i].vertex, c.options[i].edge)))
            {
              c.chosen = i;
              restore(*found);
              return;
            }
        }
      if (memory.contains({c.vertex_a, c.vertex_b, invalid}))
        c.state = State::vertex_spring;
    }



    void
    ContactHandler::transfer(ContactPair                 &c,
                             const std::vector<Point<2>> &vertices) const
    {
      c.state  = State::open;
      c.sign   = 0;
      c.chosen = invalid;
      recall(c, vertices);
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
           !open_last_step.contains(
             key(c.options[c.chosen].vertex, c.options[c.chosen].edge))))
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
  } // namespace contact
} // namespace ndda
