// SPDX-License-Identifier: GPL-3.0-or-later
//
// The resolution of vertex-vertex contacts in the open-close iteration,
// thesis chapter 6 (doc/contact.md, "The open-close iteration"): which of
// its potential reference edges a pair of vertices touches. This is
// geometry; once the edge is chosen, the contact law classifies the
// contact like any vertex-edge contact.

#include <ndda/contact/contact_handler.h>

#include <limits>

namespace ndda
{
  namespace contact
  {
    std::vector<unsigned int>
    ContactHandler::entered_options(const ContactPair            &c,
                                    const dealii::Vector<double> &d) const
    {
      std::vector<unsigned int> inside;
      for (const unsigned int v : {c.vertex_a, c.vertex_b})
        {
          std::vector<unsigned int> mine;
          bool                      all = true;
          for (unsigned int i = 0; i < c.options.size(); ++i)
            if (c.options[i].vertex == v)
              {
                const Option &o = c.options[i];
                const double r = o.ratio + o.tangential_increment(d) / o.length;
                all = all && o.normal_gap(d) < -settings.state_tolerance &&
                      r > -1e-9 && r < 1. + 1e-9;
                mine.push_back(i);
              }
          if (all)
            inside.insert(inside.end(), mine.begin(), mine.end());
        }
      return inside;
    }



    unsigned int
    ContactHandler::entrance_option(const ContactPair               &c,
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
    ContactHandler::sliding_option(const ContactPair            &c,
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
            u[k] = d[dofs->vertex_dofs[o.vertex][k]] -
                   d[dofs->vertex_dofs[corner][k]];
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
    ContactHandler::resolve_pair(ContactPair                  &c,
                                 const dealii::Vector<double> &d)
    {
      unsigned int option = invalid;
      if (c.state == State::vertex_spring)
        {
          option = sliding_option(c, d);
          if (option == invalid)
            return false; // symmetric: the spring stays
        }
      else
        {
          // A vertex has entered the other's corner if it ends behind the
          // lines of both edges there, within their lengths.
          const std::vector<unsigned int> inside = entered_options(c, d);
          if (inside.empty())
            return false;
          option = entrance_option(c, inside, d);
          if (option == invalid)
            {
              c.state = State::vertex_spring;
              return true;
            }
        }
      // The pair is a vertex-edge contact on the chosen option now, open
      // until the contact law says otherwise.
      const Option &o = c.options[option];
      c.chosen        = option;
      c.anchor        = o.ratio;
      c.state         = State::open;
      int sign;
      c.state = settings.law->classify(o, c, Trial(o, d), settings, sign);
      // The gap of this solve is no normal force: the pair was not closed.
      c.solved_gap = std::numeric_limits<double>::quiet_NaN();
      c.sign       = sign;
      if (c.state == State::open)
        c.chosen = invalid;
      if (settings.start_weight > 0.)
        update_scale(c, d);
      return true;
    }
  } // namespace contact
} // namespace ndda
