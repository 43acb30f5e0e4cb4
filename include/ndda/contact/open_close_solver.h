// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_contact_open_close_solver_h
#define ndda_contact_open_close_solver_h

#include <deal.II/lac/vector.h>

#include <ndda/contact/contact_handler.h>
#include <ndda/physics/linear_system.h>

namespace ndda
{
  namespace contact
  {
    /**
     * The open-close iteration of one step attempt (thesis 2.3.13; DESIGN
     * decision 5): solve with the springs of the present contact states,
     * classify the contacts from the solution, and solve again until no
     * state changes, as step-41 and step-42 iterate until the active set
     * repeats. The element part of the system matrix is kept; only the
     * contact springs change between iterations.
     */
    class OpenCloseSolver
    {
    public:
      struct Settings
      {
        /// Iterations before the attempt is given up (the step is cut).
        unsigned int max_iterations = 1;
        /// Iterations before the attempt is given up if every change of
        /// the iterations past max_iterations was one-way
        /// (ContactHandler::last_changes_one_way()).
        unsigned int max_one_way_iterations = 1;
        /// GMRES iterations with the last factorization before a changed
        /// system is factorized (LinearSystem::solve()).
        unsigned int reuse_iterations = 0;
        /// The weight w of the contact forces at the step's start
        /// (TimeIntegrator::contact_start_weight(); 1/2 for Newmark). With
        /// w > 0 the start forces are corrected for the contacts that open
        /// or close within the step, with the weight w / (1 - w).
        double contact_start_weight = 0;
      };

      OpenCloseSolver() = default;

      explicit OpenCloseSolver(const Settings &settings)
        : settings(settings)
      {}

      /**
       * Solve the attempt: the increment @p d of the system prepared in
       * @p system (LinearSystem::prepare_step()) with right-hand side
       * @p rhs, the prescribed increments @p prescribed of @p constraints,
       * and the springs of @p contacts (none if it is null: one solve).
       * With an integrator that averages contact forces,
       * @p inertia_correction receives the correction of the inertia force
       * of the contacts closed at both ends of the step
       * (ContactHandler::newmark_correction()); else it is zero.
       * Returns whether the states settled.
       */
      bool
      solve(LinearSystem         &system,
            ContactHandler       *contacts,
            const Vector<double> &rhs,
            const Vector<double> &prescribed,
            const Constraints    &constraints,
            Vector<double>       &d,
            Vector<double>       &inertia_correction);

      /** Iterations of the last solve() that the linear solver took. */
      unsigned int
      last_solver_iterations() const
      {
        return solver_iterations;
      }

      /** Write the statistics of the last solve to a checkpoint or read
       * them (Archive). */
      template <class Archive>
      void
      serialize(Archive &ar)
      {
        ar &solver_iterations;
      }

    private:
      Settings     settings;
      unsigned int solver_iterations = 0;
      /// An iteration's right-hand side (kept: a step allocates nothing).
      Vector<double> b;
    };
  } // namespace contact
} // namespace ndda

#endif
