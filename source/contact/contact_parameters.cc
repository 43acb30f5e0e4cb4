// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/contact/contact_law.h>
#include <ndda/contact/contact_parameters.h>
#include <ndda/parameters/entries.h>

namespace ndda
{
  namespace parameters
  {
    using namespace dealii;

    void
    Contact::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      prm.declare_entry(
        "Contact law",
        contact::default_contact_law,
        Patterns::Selection(contact::ContactLawRegistry::joined_names()),
        contact::ContactLawRegistry::documentation(
          "What happens in a contact once it is found: its springs, the "
          "open-close and friction criteria, bonds and stored energy (a "
          "plugin, see include/ndda/contact/contact_law.h; each reads its "
          "own entries from the subsection of its name). The laws:"));
      contact::ContactLawRegistry::declare_parameters(prm);
      prm.declare_entry("Enable",
                        "true",
                        Patterns::Bool(),
                        "Contact between blocks (and between the faces of "
                        "cracks and notches). false: blocks pass through "
                        "each other.");
      prm.declare_entry("Penalty",
                        "fixed",
                        Patterns::Selection("fixed|automatic"),
                        "fixed: normal spring stiffness = Penalty factor "
                        "times the largest Young's modulus times the "
                        "thickness (N/m); automatic: starts there and "
                        "doubles whenever a step ends with a penetration "
                        "beyond the tolerance, re-solving that step.");
      prm.declare_entry("Penalty factor",
                        "100",
                        Patterns::Double(0.),
                        "Normal contact spring stiffness as a multiple of "
                        "the largest Young's modulus times the thickness "
                        "(DDA's g0 / E); greater than zero.");
      prm.declare_entry("Shear stiffness ratio",
                        "0.4",
                        Patterns::Double(0.),
                        "Stiffness of the shear spring of a locked contact "
                        "as a fraction of the normal one.");
      prm.declare_entry("Open-close iterations",
                        "10",
                        Patterns::Integer(1, 100),
                        "Largest number of solves in one step's open-close "
                        "iteration; a step whose contact states still "
                        "change is cut in half and retried, unless the "
                        "changes are one-way (see 'One-way open-close "
                        "iterations').");
      prm.declare_entry(
        "One-way open-close iterations",
        "100",
        Patterns::Integer(1, 10000),
        "Largest number of solves in one step's open-close iteration when "
        "every state change past 'Open-close iterations' is one-way: each "
        "contact that changes goes to a state (open, locked, sliding in "
        "either direction) it has not had in this step, so the iteration "
        "cannot cycle and ends. In tall stacks such a change passes from "
        "course to course, one course a solve, and cutting the step does "
        "not shorten it. Below 'Open-close iterations' it changes nothing.");
      prm.declare_entry(
        "Reused factorization iterations",
        "10",
        Patterns::Integer(0, 100),
        "With a direct solver: a system whose contact springs changed is "
        "first solved by GMRES preconditioned with the last factorization, "
        "and factorized anew if GMRES would need more than this many "
        "solves with the factors, or more than a factorization costs in "
        "them where that is more (at most 100; it gives up as soon as its "
        "rate shows it; the result is the same to a relative residual of "
        "1e-12). 0: factorize every changed system.");
      prm.declare_entry("Vertex-vertex method",
                        "revised",
                        Patterns::Selection("revised|shortest path"),
                        "revised: entrance edge from the vertex trajectory, "
                        "temporary vertex-vertex spring for genuine "
                        "indeterminacy (thesis 6.2, 6.3); shortest path: "
                        "the original DDA rule, the potential reference "
                        "edge with the smaller penetration.");
      prm.declare_entry(
        "Detection distance",
        "motion",
        Patterns::Selection("motion|scene"),
        "How far from an edge a vertex is a candidate contact of a step "
        "(doc/contact.md, 'Detection'). motion: four times the last step's "
        "largest increment plus twice the deepest contact, between 1 % of "
        "Shi's distance and Shi's; a step that moves further than its "
        "distance covers is detected again, and solved again at the same "
        "size if that finds more candidates. scene: Shi's distance, twice "
        "the largest increment the step control allows (2 x Control/Maximum "
        "displacement ratio x half the scene's height), in every step; it "
        "grows with the scene, and in a large scene each block has "
        "candidates (couplings in the system) blocks away. Both find every "
        "contact a step can close, and the contacts a step makes of the "
        "candidates do not depend on the distance; the results differ by "
        "round-off.");
      prm.declare_entry("Maximum penetration ratio",
                        "1e-3",
                        Patterns::Double(0.),
                        "Penetration tolerance as a fraction of half the "
                        "scene's height: reported in the statistics, and "
                        "with 'Penalty = automatic' the limit above which "
                        "the penalty is raised.");
      prm.leave_subsection();
    }



    void
    Contact::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      law_name = prm.get("Contact law");
      law      = contact::ContactLawRegistry::create_and_parse(law_name, prm);
      enabled  = prm.get_bool("Enable");
      penalty_method = prm.get("Penalty") == "fixed" ? PenaltyMethod::fixed :
                                                       PenaltyMethod::automatic;
      penalty_factor = prm.get_double("Penalty factor");
      AssertThrow(penalty_factor > 0.,
                  ExcMessage(
                    "Contact/Penalty factor: " + prm.get("Penalty factor") +
                    " is not positive. Give a multiple of the "
                    "largest Young's modulus, e.g. 100."));
      shear_stiffness_ratio     = prm.get_double("Shear stiffness ratio");
      max_open_close_iterations = prm.get_integer("Open-close iterations");
      max_one_way_iterations = prm.get_integer("One-way open-close iterations");
      reuse_iterations     = prm.get_integer("Reused factorization iterations");
      vertex_vertex_method = prm.get("Vertex-vertex method") == "revised" ?
                               VertexVertexMethod::revised :
                               VertexVertexMethod::shortest_path;
      max_penetration_ratio = prm.get_double("Maximum penetration ratio");
      detection_rule        = prm.get("Detection distance") == "motion" ?
                                contact::DetectionDistance::Rule::motion :
                                contact::DetectionDistance::Rule::scene;
      AssertThrow(max_penetration_ratio > 0. ||
                    penalty_method == PenaltyMethod::fixed,
                  ExcMessage("Contact/Maximum penetration ratio: must be "
                             "greater than zero with 'Penalty = "
                             "automatic'."));
      prm.leave_subsection();
    }
  } // namespace parameters
} // namespace ndda
