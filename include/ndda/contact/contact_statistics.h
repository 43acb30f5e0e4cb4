// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_contact_contact_statistics_h
#define ndda_contact_contact_statistics_h

namespace ndda
{
  namespace contact
  {
    /** Figures of the last step, for the statistics file. */
    struct ContactStatistics
    {
      unsigned int n_candidates     = 0;
      unsigned int n_contacts       = 0;
      unsigned int n_closed         = 0;
      unsigned int n_sliding        = 0;
      unsigned int n_vertex_springs = 0;
      unsigned int n_vertex_vertex  = 0;
      unsigned int n_iterations     = 0;
      /// Bonded contacts (joint cohesion and tension intact) at the end of
      /// the step, and the contact length they carry (m).
      unsigned int n_bonded      = 0;
      double       bonded_length = 0;
      /// Largest penetration (m, positive) of a closed contact at the end
      /// of the step.
      double max_penetration = 0;
      /// Energy stored in the springs at the end of the step (J).
      double spring_energy = 0;
      /// Work done on the bodies by the contact forces the integrator
      /// applied, accumulated over the run (J).
      double contact_work = 0;
      /// Energy the contacts have taken out of the scene so far (J):
      /// -contact_work - spring_energy, i.e. friction and the losses of
      /// penalty springs that close within a step.
      double dissipation = 0;
      /// The part of the dissipation that friction took out so far (J): the
      /// friction force of each sliding contact times its slip, step by
      /// step (ContactLaw::friction_dissipation()). The rest of the
      /// dissipation is what the integrator's contact switching took.
      double friction_dissipation = 0;

      template <class Archive>
      void
      serialize(Archive &ar)
      {
        ar &n_candidates &n_contacts &n_closed &n_sliding &n_vertex_springs
          &n_vertex_vertex &n_iterations &n_bonded &bonded_length
            &max_penetration &spring_energy &contact_work &dissipation
              &friction_dissipation;
      }
    };
  } // namespace contact
} // namespace ndda

#endif
