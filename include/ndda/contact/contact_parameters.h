// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef ndda_contact_contact_parameters_h
#define ndda_contact_contact_parameters_h

#include <deal.II/base/parameter_handler.h>

#include <ndda/contact/detection_distance.h>

#include <memory>
#include <string>

namespace ndda
{
  namespace contact
  {
    class ContactLaw;
  }

  /**
   * The parameters that contact/ reads: subsection Contact.
   *
   * @ingroup parameters
   */
  namespace parameters
  {
    using dealii::ParameterHandler;

    /** How the contact penalty is chosen. */
    enum class PenaltyMethod
    {
      /// A fixed multiple of the largest Young's modulus.
      fixed,
      /// Starts as the fixed value and doubles whenever a step ends with a
      /// penetration beyond the tolerance (the step is then solved again).
      automatic
    };

    /** Resolution of vertex-vertex contacts, thesis chapter 6. */
    enum class VertexVertexMethod
    {
      /// The thesis's revised method: entrance edge from the vertex's
      /// trajectory (6.3), temporary vertex-vertex spring for genuine
      /// indeterminacy (6.2).
      revised,
      /// The original rule: the potential reference edge with the smallest
      /// penetration at the end of the step.
      shortest_path
    };

    /** subsection Contact */
    struct Contact
    {
      bool               enabled;
      PenaltyMethod      penalty_method;
      double             penalty_factor;
      double             shear_stiffness_ratio;
      unsigned int       max_open_close_iterations;
      unsigned int       max_one_way_iterations;
      unsigned int       reuse_iterations;
      VertexVertexMethod vertex_vertex_method;
      double             max_penetration_ratio;
      /// Contact/Detection distance.
      contact::DetectionDistance::Rule detection_rule;
      /// The contact law's name, `set Contact law = ...`, and the law with
      /// its parameters read (contact/contact_law.h); stateless, shared.
      std::string                                law_name;
      std::shared_ptr<const contact::ContactLaw> law;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

  } // namespace parameters
} // namespace ndda

#endif
