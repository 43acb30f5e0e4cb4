// SPDX-License-Identifier: GPL-3.0-or-later
//
// ContactHandler: the contacts of a step from detection to springs, the
// open-close iteration's states, and what is kept from step to step. The
// narrow phase, the transfer of states, bonded joint geometry and the
// vertex-vertex resolution have their own files beside this one; the
// springs and the classification come from the contact law.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parallel.h>

#include <deal.II/lac/full_matrix.h>

#include <ndda/contact/contact_handler.h>
#include <ndda/parallel/owned_cells.h>
#include <ndda/physics/block_rotation.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ndda
{
  namespace contact
  {
    namespace
    {
      /// Contacts a thread takes at a time in the passes over all of them.
      constexpr unsigned int grain_size = 512;

      /**
       * The largest depth of the contacts with a chosen option (@p
       * closed_only: of the closed ones) under @p d, 0 if none is deeper.
       * Each contact's depth on deal.II's threads, the largest on one (a
       * maximum is the same in any order).
       */
      template <typename Pairs>
      double
      largest_depth(const Pairs                  &contacts,
                    const dealii::Vector<double> &d,
                    const unsigned int            invalid,
                    const bool                    closed_only)
      {
        const unsigned int  n = contacts.size();
        std::vector<double> depths(n, 0.);
        dealii::parallel::apply_to_subranges(
          0u,
          n,
          [&](const unsigned int begin, const unsigned int end) {
            for (unsigned int i = begin; i < end; ++i)
              {
                const auto &c = contacts[i];
                if (c.chosen != invalid &&
                    (!closed_only || c.state == State::locked ||
                     c.state == State::sliding))
                  depths[i] = -c.options[c.chosen].normal_gap(d) - c.offset;
              }
          },
          grain_size);
        double depth = 0;
        for (const double x : depths)
          depth = std::max(depth, x);
        return depth;
      }


      /**
       * The candidates of the whole scene within @p threshold: on several
       * processes (@p owned_cells), this process's from its neighbour
       * list, joined with the others'.
       */
      std::vector<Candidate>
      detect_candidates(NeighbourList                   &neighbours,
                        const OwnedCells                *owned_cells,
                        const std::vector<Point<2>>     &vertices,
                        const std::vector<BoundaryEdge> &edges,
                        const double                     threshold,
                        const double                     min_skin)
      {
        std::vector<Candidate> candidates =
          neighbours.detect(vertices, edges, threshold, min_skin);
        if (owned_cells == nullptr)
          return candidates;
        // Each process's list is sorted by vertex, then edge, and no pair is
        // on two lists; joined and sorted, they are one process's list.
        candidates                = owned_cells->gather(candidates);
        const auto by_vertex_edge = [](const Candidate &a, const Candidate &b) {
          return std::tie(a.vertex, a.edge) < std::tie(b.vertex, b.edge);
        };
        if (!std::is_sorted(candidates.begin(),
                            candidates.end(),
                            by_vertex_edge))
          std::sort(candidates.begin(), candidates.end(), by_vertex_edge);
        return candidates;
      }
    } // namespace



    void
    ContactHandler::initialize(const std::vector<BoundaryEdge> &edges_in,
                               const std::vector<double>       &friction_in,
                               const DofMap                    &dofs_in,
                               const ContactSettings           &settings_in)
    {
      AssertDimension(edges_in.size(), friction_in.size());
      edges         = edges_in;
      edge_friction = friction_in;
      dofs          = &dofs_in;
      settings      = settings_in;
      edge_shapes.initialize(*dofs->fe);
      owned_cells = nullptr;
      neighbours.set_owned_vertices({});
      if (!settings.law)
        settings.law = create_contact_law(default_contact_law);

      const unsigned int n_vertices = dofs->vertex_dofs.size();
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
      memory                          = old.memory;
      open_last_step                  = old.open_last_step;
      first_step                      = old.first_step;
      settings                        = old.settings;
      statistics.contact_work         = old.statistics.contact_work;
      statistics.dissipation          = old.statistics.dissipation;
      statistics.friction_dissipation = old.statistics.friction_dissipation;
    }



    void
    ContactHandler::set_owned_cells(const OwnedCells *cells)
    {
      // Each process finds the candidates of the vertices it owns against
      // its own and its ghost edges (NeighbourList); detect_candidates()
      // joins them, in the order of one process. nullptr, or cells not
      // split: this process alone. initialize() goes back to that.
      Assert(dofs != nullptr, dealii::ExcNotInitialized());
      const bool split = cells != nullptr && cells->is_split();
      owned_cells      = split ? cells : nullptr;
      neighbours.set_owned_vertices(
        split ? cells->owned_vertices(dofs->cell_vertices,
                                      dofs->vertices_per_cell,
                                      dofs->vertex_dofs.size()) :
                std::vector<bool>());
    }



    void
    ContactHandler::set_normal_stiffness(const double k)
    {
      settings.normal_stiffness = k;
      assembled.clear();
    }



    void
    ContactHandler::set_reduced_blocks(const std::vector<bool> &reduced)
    {
      reduced_block = reduced;
    }



    void
    ContactHandler::begin_step(const std::vector<Point<2>> &vertices,
                               const double                 threshold,
                               const double                 min_skin)
    {
      statistics.n_iterations = 0;
      contacts.clear();
      assembled.clear();
      couplings.clear();
      if (block_edge_length.empty())
        measure_block_edges(vertices); // on the first step's geometry

      const std::vector<Candidate> candidates = detect_candidates(
        neighbours, owned_cells, vertices, edges, threshold, min_skin);
      statistics.n_candidates = candidates.size();
      index_by_vertex(
        vertices.size(),
        candidates,
        [](const Candidate &c) { return c.vertex; },
        candidate_start);

      // The narrow phase, one contact type after the other.
      compute_normals(vertices);
      const std::vector<VertexEdge> vertex_edge =
        vertex_edge_pairs(vertices, candidates);
      index_by_vertex(
        vertices.size(),
        vertex_edge,
        [](const VertexEdge &p) { return p.first; },
        vertex_edge_start);
      add_vertex_edge_contacts(vertices, vertex_edge);
      add_vertex_vertex_contacts(vertices, candidates, vertex_edge);

      for (ContactPair &c : contacts)
        transfer(c, vertices);
      shadow_bonded_joints();
      for (ContactPair &c : contacts)
        {
          if (c.bonded)
            c.bond_length = bond_length(vertices,
                                        c.options[c.chosen].vertex,
                                        c.options[c.chosen].edge);
          c.solved_gap   = std::numeric_limits<double>::quiet_NaN();
          c.start        = c;
          c.start_chosen = c.chosen;
          c.start_bonded = c.bonded;
          c.visit();
          for (const Option &o : c.options)
            couplings.emplace_back(o.vertex, edges[o.edge].cell);
        }
      std::sort(couplings.begin(), couplings.end());
      couplings.erase(std::unique(couplings.begin(), couplings.end()),
                      couplings.end());
      statistics.n_contacts = contacts.size();
    }



    bool
    ContactHandler::finds_more(const std::vector<Point<2>> &vertices,
                               const double                 threshold,
                               const double                 min_skin)
    {
      return detect_candidates(
               neighbours, owned_cells, vertices, edges, threshold, min_skin)
               .size() > statistics.n_candidates;
    }



    void
    ContactHandler::restart_step()
    {
      statistics.n_iterations = 0;
      assembled.clear();
      for (ContactPair &c : contacts)
        {
          c.flips                        = 0;
          c.shear_flips                  = 0;
          c.scale                        = 1;
          static_cast<ContactState &>(c) = c.start;
          c.chosen                       = c.start_chosen;
          c.bonded                       = c.start_bonded;
          c.visited                      = 0;
          c.visit();
        }
    }



    bool
    ContactHandler::has_springs() const
    {
      for (const ContactPair &c : contacts)
        if (c.state != State::open)
          return true;
      return false;
    }



    void
    ContactHandler::assemble(
      const std::function<
        bool(const unsigned int,
             const dealii::ArrayView<const dealii::types::global_dof_index> &,
             const dealii::FullMatrix<double> *)> &add,
      dealii::Vector<double>                      &rhs) const
    {
      const double kn = settings.normal_stiffness;
      // The springs' stiffness of one contact as a dense block; one block
      // for all contacts, so that it is allocated once.
      dealii::FullMatrix<double> k;
      const bool                 turned = frames != nullptr && frames->turned();
      std::vector<dealii::types::global_dof_index> ab(4);
      if (assembled.size() != contacts.size())
        assembled.assign(contacts.size(), Assembled());
      for (unsigned int i = 0; i < contacts.size(); ++i)
        {
          const ContactPair &c    = contacts[i];
          Assembled         &last = assembled[i];
          // The block depends on the contact's state, option and scale
          // only (the options and the frames stay within a step).
          const bool same = last.valid && last.state.state == c.state &&
                            last.state.anchor == c.anchor &&
                            last.state.sign == c.sign &&
                            last.state.friction == c.friction &&
                            last.state.bond_length == c.bond_length &&
                            last.chosen == c.chosen && last.scale == c.scale &&
                            last.bonded == c.bonded;
          if (c.state == State::vertex_spring)
            {
              // Thesis 6.5-6.12: a spring on the relative displacement of
              // the two vertices in this step, a hinge between them.
              const auto &da = dofs->vertex_dofs[c.vertex_a];
              const auto &db = dofs->vertex_dofs[c.vertex_b];
              ab             = {da[0], da[1], db[0], db[1]};
              if (same && add(i, ab, nullptr))
                continue;
              k.reinit(4, 4);
              for (unsigned int j = 0; j < 4; ++j)
                {
                  k(j, j)           = kn;
                  k(j, (j + 2) % 4) = -kn;
                }
              if (turned)
                frames->turn(ab, k);
              add(i, ab, &k);
            }
          else
            {
              if (c.state == State::open || c.chosen == invalid)
                continue;
              const Option      &o = c.options[c.chosen];
              const unsigned int n = o.dofs.size();
              const dealii::ArrayView<const dealii::types::global_dof_index>
                option_dofs(o.dofs.data(), n);
              if (same && add(i, option_dofs, nullptr))
                {
                  settings.law->add_springs(
                    o, c, c.scale, settings, nullptr, rhs);
                  continue;
                }
              k.reinit(n, n);
              settings.law->add_springs(o, c, c.scale, settings, &k, rhs);
              if (turned)
                frames->turn(option_dofs, k);
              add(i, option_dofs, &k);
            }
          last = {true, c, c.chosen, c.scale, c.bonded};
        }
    }



    void
    ContactHandler::start_forces(dealii::Vector<double> &force) const
    {
      // The contacts closed at both ends of the step with their full start
      // force; those that open within the step with the fraction of it
      // that makes their work equal to the spring energy they release
      // (scale, see update_states()).
      force = 0;
      for (const ContactPair &c : contacts)
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
            settings.law->add_springs(c.options[c.start_chosen],
                                      c.start,
                                      scale,
                                      settings,
                                      nullptr,
                                      force);
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
    ContactHandler::update_scale(ContactPair                  &c,
                                 const dealii::Vector<double> &d)
    {
      // A spring that engages or lets go within the step acts for part of
      // it only. With the average of start and end forces (Newmark), the
      // energy-consistent force of the one-sided spring
      // Phi(g) = kn/2 min(g, 0)^2 is -(Phi(g1) - Phi(g0)) / (g1 - g0)
      // (a discrete gradient): for a contact that closes from the gap
      // g0 > 0 to g1 < 0 it is the end force times g1 / (g1 - g0), for one
      // that opens from g0 < 0 to g1 > 0 the start force times
      // g0 / (g0 - g1). Without it, every impact would lose kn g0 g1 / 2.
      // Generalized-α (start forces weighted alpha_f) takes the same
      // scales: doc/theory.md, "Generalized-α", says why.
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
      // Each contact on deal.II's threads: its update reads d and the
      // settings and writes that contact alone, and the contact law's
      // functions may be called for several contacts at once
      // (doc/contact.md, "Contact laws"). What the iteration learns of all
      // of them is an or (changed) and an and (one way), the same in any
      // order.
      const unsigned int n = contacts.size();
      std::vector<char>  flags(n, 0);
      dealii::parallel::apply_to_subranges(
        0u,
        n,
        [&](const unsigned int begin, const unsigned int end) {
          for (unsigned int i = begin; i < end; ++i)
            {
              ContactPair &c      = contacts[i];
              const bool   change = c.chosen == invalid ?
                                      resolve_pair(c, d) :
                                      !c.shadowed && update_state(c, d);
              if (change)
                flags[i] = c.visit() ? 2 : 1;
            }
        },
        grain_size);
      bool changed = false;
      one_way      = true;
      for (const char f : flags)
        {
          changed = changed || f != 0;
          one_way = one_way && f != 2;
        }
      return changed;
    }



    bool
    ContactHandler::settle_lagging_forces(const dealii::Vector<double> &d)
    {
      const ContactLaw &law = *settings.law;
      if (!law.forces_may_lag())
        return false;
      bool lags = false;
      for (const ContactPair &c : contacts)
        if (c.chosen != invalid && !c.shadowed &&
            law.force_lags(
              c.options[c.chosen], c, Trial(c.options[c.chosen], d), settings))
          {
            lags = true;
            break;
          }
      if (!lags)
        return false;
      for (ContactPair &c : contacts)
        if (c.chosen != invalid && !c.shadowed &&
            (c.state == State::locked || c.state == State::sliding))
          c.solved_gap = c.options[c.chosen].normal_gap(d);
      return true;
    }



    bool
    ContactHandler::update_state(ContactPair                  &c,
                                 const dealii::Vector<double> &d)
    {
      const ContactLaw &law = *settings.law;
      const Option     &o   = c.options[c.chosen];
      const Trial       trial(o, d);
      int               sign;
      State             state = State::locked;
      // The gap of a solve in which the contact was open is no normal
      // force: a contact that closes takes the step start's gap next.
      c.solved_gap = c.state == State::locked || c.state == State::sliding ?
                       trial.gap :
                       std::numeric_limits<double>::quiet_NaN();
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
      // The same for the shear state of a closed contact: one whose
      // shear force sits at the friction limit can change between locked
      // and sliding, or between the two sliding directions, at every
      // solve, whatever the step size (a fresh crack face in a dynamic
      // run). After three such changes in this step it stays locked: its
      // shear spring holds a force a little beyond the limit rather than
      // the iteration cycling.
      else if ((state == State::locked || state == State::sliding) &&
               (c.state == State::locked || c.state == State::sliding) &&
               (state != c.state || sign != c.sign))
        {
          if (c.shear_flips >= 3)
            state = State::locked, sign = 0;
          else
            ++c.shear_flips;
        }
      bool changed = state != c.state || sign != c.sign;
      if (state == State::locked && c.state != State::locked)
        c.anchor = law.anchor_on_locking(o, c, trial, settings);
      c.state = state;
      c.sign  = sign;
      if (state == State::open && c.vertex_a != invalid)
        c.chosen = invalid; // a pair that separates is open again
      // The scale depends on the solution it enters: a few
      // iterations make it consistent; after that it is accepted as it
      // is rather than cutting the step.
      if (settings.start_weight > 0. && update_scale(c, d) &&
          statistics.n_iterations < 4)
        changed = true;
      return changed;
    }



    double
    ContactHandler::max_penetration(const dealii::Vector<double> &d) const
    {
      return largest_depth(contacts, d, invalid, true);
    }



    double
    ContactHandler::max_depth(const dealii::Vector<double> &d) const
    {
      return largest_depth(contacts, d, invalid, false);
    }



    void
    ContactHandler::end_step(const dealii::Vector<double> &d)
    {
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
      // The forces the integrator applied over the step: at its end (DDA),
      // the mean of start and end (Newmark), or start and end weighted
      // alpha_f and 1 - alpha_f (generalized-α).
      applied.reinit(d.size());
      if (settings.start_weight > 0.)
        {
          start_forces(applied);
          applied *= settings.start_weight;
        }
      end_force.reinit(d.size());
      for (const ContactPair &c : contacts)
        {
          if (c.vertex_a != invalid)
            ++statistics.n_vertex_vertex;
          if (c.state == State::vertex_spring)
            end_vertex_spring(c, d);
          else if (c.state == State::open && c.vertex_a == invalid)
            open_last_step.add(key(c.options[c.chosen].vertex,
                                   c.options[c.chosen].edge),
                               true);
          else if (c.state != State::open && c.chosen != invalid)
            end_closed_contact(c, d);
        }
      memory.finish();
      open_last_step.finish();
      applied.add(1. - settings.start_weight, end_force);
      statistics.contact_work += applied * d;
      statistics.dissipation =
        -statistics.contact_work - statistics.spring_energy;
    }



    void
    ContactHandler::end_vertex_spring(const ContactPair            &c,
                                      const dealii::Vector<double> &d)
    {
      const double kn = settings.normal_stiffness;
      ++statistics.n_vertex_springs;
      memory.add({c.vertex_a, c.vertex_b, invalid},
                 {c.state, 0., 0, 0., false});
      Tensor<1, 2> u;
      for (unsigned int k = 0; k < 2; ++k)
        u[k] = d[dofs->vertex_dofs[c.vertex_a][k]] -
               d[dofs->vertex_dofs[c.vertex_b][k]];
      statistics.spring_energy += 0.5 * kn * u.norm_square();
      add_end_force(c, d, end_force);
    }



    void
    ContactHandler::add_end_force(const ContactPair            &c,
                                  const dealii::Vector<double> &d,
                                  dealii::Vector<double>       &force) const
    {
      if (c.state == State::vertex_spring)
        {
          const double kn = settings.normal_stiffness;
          for (unsigned int k = 0; k < 2; ++k)
            {
              const double u = d[dofs->vertex_dofs[c.vertex_a][k]] -
                               d[dofs->vertex_dofs[c.vertex_b][k]];
              force[dofs->vertex_dofs[c.vertex_a][k]] -= kn * u;
              force[dofs->vertex_dofs[c.vertex_b][k]] += kn * u;
            }
          return;
        }
      if (c.state == State::open || c.chosen == invalid)
        return;
      // The springs' forces at d = 0 on the geometry of the step's end
      // (the gap and, for a locked contact, the shear displacement of the
      // solution).
      const Option &o = c.options[c.chosen];
      const Trial   trial(o, d);
      Option        at_end      = o;
      at_end.gap                = trial.gap;
      ContactState state_at_end = c;
      if (c.state == State::locked)
        state_at_end.anchor -= trial.increment / o.length;
      settings.law->add_springs(
        at_end, state_at_end, c.scale, settings, nullptr, force);
    }



    void
    ContactHandler::trial_end_forces(const dealii::Vector<double> &d,
                                     dealii::Vector<double>       &force) const
    {
      force.reinit(d.size());
      for (const ContactPair &c : contacts)
        add_end_force(c, d, force);
    }



    void
    ContactHandler::end_closed_contact(const ContactPair            &c,
                                       const dealii::Vector<double> &d)
    {
      ++statistics.n_closed;
      const Option &o = c.options[c.chosen];
      const Trial   trial(o, d);
      // A contact that is not bonded and ends the step with a gap starts
      // the next one open (transfer()): its springs hold nothing. (An
      // exact rotation can move a vertex off the edge that the linearised
      // rotation of the solve had it touching; counting kn g^2 / 2 there
      // showed as an energy gain proportional to the penalty.)
      if (c.bonded || trial.gap <= settings.state_tolerance)
        statistics.spring_energy += settings.law->energy(o, c, trial, settings);
      add_end_force(c, d, end_force);
      double anchor = c.anchor;
      if (c.state != State::locked)
        {
          ++statistics.n_sliding;
          anchor = o.ratio + trial.increment / o.length;
          statistics.friction_dissipation +=
            settings.law->friction_dissipation(o, c, trial, settings);
        }
      if (c.bonded)
        {
          ++statistics.n_bonded;
          statistics.bonded_length += c.bond_length;
        }
      memory.add(key(o.vertex, o.edge),
                 {c.state, anchor, c.sign, c.offset, c.bonded});
    }
  } // namespace contact
} // namespace ndda
