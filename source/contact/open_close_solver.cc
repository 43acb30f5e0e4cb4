// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/contact/open_close_solver.h>

#include <algorithm>

namespace ndda
{
  namespace contact
  {
    bool
    OpenCloseSolver::solve(LinearSystem         &system,
                           ContactHandler       *contacts,
                           const Vector<double> &rhs,
                           const Vector<double> &prescribed,
                           const Constraints    &constraints,
                           Vector<double>       &d,
                           Vector<double>       &inertia_correction)
    {
      d.reinit(rhs.size());
      const unsigned int max_iterations =
        contacts != nullptr ? settings.max_iterations : 1;
      const LinearSystem::SpringAssembler springs =
        [contacts](const LinearSystem::BlockAdder &add, Vector<double> &b) {
          contacts->assemble(add, b);
        };
      const unsigned int one_way_limit =
        contacts != nullptr ? settings.max_one_way_iterations : 1;
      // Solves repeated in the same states because a force lagged behind
      // its solve (lagged friction), before the contacts are classified:
      // they are not state changes and do not count towards the limits
      // on those. At most max_iterations of them in a step attempt; after
      // that the forces lag one solve behind, as in Shi's DDA.
      unsigned int lag_solves = 0;
      for (unsigned int solves = 0;; ++solves)
        {
          const unsigned int iteration = solves - lag_solves;
          b                            = rhs;
          // Newmark averages the forces at the step's start and end. A
          // contact that opens in this step would keep half of its start
          // force for the whole step and hand the body the energy
          // F0 g1 / 2 (g1 the gap it opens): only contacts closed at both
          // ends enter the average (doc/contact.md).
          inertia_correction.reinit(rhs.size());
          if (contacts != nullptr && settings.contact_start_weight > 0.)
            {
              contacts->newmark_correction(inertia_correction);
              const double w = settings.contact_start_weight;
              b.add(w / (1. - w), inertia_correction);
            }
          const bool with_springs =
            contacts != nullptr && contacts->has_springs();
          solver_iterations =
            system.solve(with_springs ? springs :
                                        LinearSystem::SpringAssembler(),
                         b,
                         prescribed,
                         constraints,
                         contacts != nullptr ? settings.reuse_iterations : 0,
                         d);
          if (contacts == nullptr)
            return true;
          contacts->count_iteration();
          if (lag_solves < max_iterations && contacts->settle_lagging_forces(d))
            {
              ++lag_solves;
              continue;
            }
          if (!contacts->update_states(d))
            return true;
          // Past the limit, the iteration goes on only while its changes
          // are one-way (it cannot cycle), up to its own limit.
          if (iteration + 1 >= max_iterations &&
              (!contacts->last_changes_one_way() ||
               iteration + 1 >= std::max(max_iterations, one_way_limit)))
            return false;
        }
    }
  } // namespace contact
} // namespace ndda
