// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <ndda/contact/contact_law.h>
#include <ndda/parameters/parameters.h>
#include <ndda/physics/constitutive_law.h>
#include <ndda/physics/finite_element.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace ndda
{
  namespace parameters
  {
    namespace
    {
      /** Split at @p delimiter and trim; empty pieces are dropped. */
      std::vector<std::string>
      split(const std::string &text, const std::string &delimiter)
      {
        std::vector<std::string> pieces;
        for (const auto &piece : Utilities::split_string_list(text, delimiter))
          if (!piece.empty())
            pieces.push_back(piece);
        return pieces;
      }

      double
      to_double(const std::string &text, const std::string &entry)
      {
        std::istringstream in(text);
        double             value;
        in >> value;
        AssertThrow(in && (in >> std::ws).eof() && std::isfinite(value),
                    ExcMessage(entry + ": '" + text +
                               "' is not a number. Give plain numbers such as "
                               "0.5 or 1e-3."));
        return value;
      }

      std::vector<double>
      parse_numbers(const std::string &text,
                    const std::string &entry,
                    const unsigned int n)
      {
        std::vector<double> numbers;
        for (const auto &piece : split(text, ","))
          numbers.push_back(to_double(piece, entry));
        AssertThrow(numbers.size() == n,
                    ExcMessage(entry + ": '" + text + "' has " +
                               std::to_string(numbers.size()) +
                               " numbers, but " + std::to_string(n) +
                               " separated by commas are needed."));
        return numbers;
      }

      /** Names in a comma separated list, checked to be unique. */
      std::vector<std::string>
      parse_names(const std::string &text, const std::string &entry)
      {
        const auto            names = split(text, ",");
        std::set<std::string> seen;
        for (const auto &name : names)
          AssertThrow(seen.insert(name).second,
                      ExcMessage(entry + ": the name '" + name +
                                 "' appears twice. Names must be unique."));
        return names;
      }

      std::string
      angle_description(const std::string &what)
      {
        return what + " (degrees).";
      }

      void
      declare_initial_state(ParameterHandler &prm)
      {
        prm.declare_entry("Initial stress",
                          "0, 0, 0",
                          Patterns::Anything(),
                          "Initial stress sigma_xx, sigma_yy, sigma_xy of all "
                          "cells of the block (Pa, tension positive).");
        prm.declare_entry(
          "Initial velocity",
          "0; 0",
          Patterns::Anything(),
          "Initial velocity v_x; v_y (m/s) as functions of x and y, e.g. "
          "'-2*y; 2*x' for a rotation about the origin at 2 rad/s.");
      }

      InitialState
      parse_initial_state(ParameterHandler &prm, const std::string &where)
      {
        InitialState state;
        const auto   stress = parse_numbers(prm.get("Initial stress"),
                                          where + "/Initial stress",
                                          3);
        state.stress        = {{stress[0], stress[1], stress[2]}};
        state.velocity      = prm.get("Initial velocity");
        check_function(state.velocity, 2, "x,y", where + "/Initial velocity");
        return state;
      }

      void
      declare_mesh_size(ParameterHandler &prm)
      {
        prm.declare_entry("Material",
                          "",
                          Patterns::Anything(),
                          "Name of the material of this block, one of "
                          "Materials/Names.");
        prm.declare_entry("Mesh size",
                          "0",
                          Patterns::Double(0.),
                          "Longest triangle edge (m). Zero: use 'Target "
                          "number of elements'.");
        prm.declare_entry("Target number of elements",
                          "0",
                          Patterns::Integer(0),
                          "Approximate number of triangles, used only if "
                          "'Mesh size' is zero.");
      }

      template <typename Description>
      void
      parse_mesh_size(ParameterHandler  &prm,
                      const std::string &where,
                      const Materials   &materials,
                      Description       &description)
      {
        description.material_id =
          materials.id(prm.get("Material"), where + "/Material");
        description.mesh_size = prm.get_double("Mesh size");
        description.target_n_cells =
          prm.get_integer("Target number of elements");
        AssertThrow(description.mesh_size > 0. ||
                      description.target_n_cells > 0,
                    ExcMessage(where +
                               ": neither 'Mesh size' nor 'Target number of "
                               "elements' is set. Set one of them, e.g. "
                               "'set Mesh size = 0.01'."));
      }

      std::vector<std::vector<Point<2>>>
      parse_rings(const std::string &text, const std::string &entry)
      {
        std::vector<std::vector<Point<2>>> rings;
        for (const auto &ring : split(text, "|"))
          rings.push_back(parse_points(ring, entry));
        return rings;
      }

      /** The text of ParameterHandler's exception, without the stack. */
      std::string
      message_of(const ExceptionBase &exc, const std::string &filename = "")
      {
        std::ostringstream out;
        exc.print_info(out);
        std::string text = out.str();
        // ParameterHandler reads from a string here: "Line <3> of file
        // <input string>: ..." becomes "line 3: ...".
        if (!filename.empty())
          for (const auto &[from, to] :
               std::vector<std::pair<std::string, std::string>>{
                 {"> of file <input string>", ""},
                 {"> of file <input string", ":"},
                 {"Line <", "line "}})
            for (auto pos = text.find(from); pos != std::string::npos;
                 pos      = text.find(from))
              text.replace(pos, from.size(), to);
        // Collapse deal.II's line breaks and indentation.
        std::string result;
        bool        space = false;
        for (const char c : text)
          if (c == '\n' || c == ' ' || c == '\t')
            space = true;
          else
            {
              if (space && !result.empty())
                result += ' ';
              result += c;
              space = false;
            }
        return result;
      }
    } // namespace



    std::vector<Point<2>>
    parse_points(const std::string &text, const std::string &entry)
    {
      std::vector<Point<2>> points;
      for (const auto &piece : split(text, ";"))
        {
          const auto xy = parse_numbers(piece, entry, 2);
          points.emplace_back(xy[0], xy[1]);
        }
      return points;
    }



    std::vector<geometry::Segment>
    parse_segments(const std::string &text, const std::string &entry)
    {
      std::vector<geometry::Segment> segments;
      for (const auto &piece : split(text, ";"))
        {
          const auto c = parse_numbers(piece, entry, 4);
          segments.push_back({Point<2>(c[0], c[1]), Point<2>(c[2], c[3])});
          AssertThrow(segments.back().a.distance(segments.back().b) > 0.,
                      ExcMessage(entry + ": the segment '" + piece +
                                 "' has zero length. Give two different end "
                                 "points x1, y1, x2, y2."));
        }
      return segments;
    }



    void
    check_function(const std::string &expression,
                   const unsigned int n_components,
                   const std::string &variables,
                   const std::string &entry)
    {
      const auto components = Utilities::split_string_list(expression, ";");
      AssertThrow(components.size() == n_components,
                  ExcMessage(entry + ": '" + expression + "' has " +
                             std::to_string(components.size()) +
                             " components separated by ';', but " +
                             std::to_string(n_components) +
                             " are needed (variables: " + variables + ")."));
      try
        {
          FunctionParser<2> function(n_components);
          function.initialize(variables,
                              expression,
                              {{"pi", numbers::PI}},
                              variables.find('t') != std::string::npos);
          // muparser reports unknown variables only on evaluation.
          function.value(Point<2>(), 0);
        }
      catch (const ExceptionBase &exc)
        {
          AssertThrow(false,
                      ExcMessage(entry + ": '" + expression +
                                 "' is not a valid function of (" + variables +
                                 "): " + message_of(exc)));
        }
      catch (const std::exception &exc)
        {
          AssertThrow(false,
                      ExcMessage(entry + ": '" + expression +
                                 "' is not a valid function of (" + variables +
                                 "): " + exc.what()));
        }
    }



    void
    Control::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Control");
      prm.declare_entry("Analysis type",
                        "dynamic",
                        Patterns::Selection("static|dynamic|quasi-static"),
                        "static: the velocity is set to zero at the start of "
                        "every step (DDA statics); dynamic: it is carried "
                        "over; quasi-static: no inertia, every step solves "
                        "equilibrium K d = f (every block must be "
                        "constrained).");
      prm.declare_entry(
        "Time integrator",
        "Newmark",
        Patterns::Selection(time::TimeIntegratorRegistry::joined_names()),
        time::TimeIntegratorRegistry::documentation(
          "The time integration scheme (a plugin, see "
          "include/ndda/time/time_integrator.h; each reads its own entries "
          "from the subsection of its name). With Analysis type = static "
          "every step of the scheme starts at rest; quasi-static uses no "
          "scheme. See doc/theory.md. The schemes:"));
      time::TimeIntegratorRegistry::declare_parameters(prm);
      prm.declare_entry("Time step",
                        "1e-3",
                        Patterns::Double(),
                        "Nominal time step (s), greater than zero.");
      prm.declare_entry("End time",
                        "1",
                        Patterns::Double(),
                        "Time at which the run ends (s), greater than zero.");
      prm.declare_entry(
        "Maximum displacement ratio",
        "0.01",
        Patterns::Double(0., 1.),
        "DDA step control: the largest displacement in a step, as a "
        "fraction of half the scene's height, above which the step is cut "
        "and retried with half the step size.");
      prm.declare_entry("Maximum step cuts",
                        "10",
                        Patterns::Integer(0, 50),
                        "How often one step may be halved before the run "
                        "stops with an error. A step starts at twice the "
                        "last one (at most Time step). The run also stops "
                        "when the step falls below 1e-6 of Time step, or "
                        "when 1000 steps in a row were cut below 1e-3 of "
                        "it (a run that crawls).");
      // has_to_be_set = true only so that ParameterHandler records whether
      // a scene set the entry (get_entries_wrongly_not_set()): a scene
      // that gives both entries must mean the same element.
      prm.declare_entry("Element degree",
                        "1",
                        Patterns::Integer(1, 2),
                        "Polynomial degree of FE_SimplexP: 1 (three-node "
                        "triangles, as in the thesis) or 2. Short for "
                        "'Finite element = FE_SimplexP(degree)'.",
                        true);
      prm.declare_entry(
        "Finite element",
        "",
        Patterns::Anything(),
        "The scalar deal.II element on the triangle, by name; ndda builds "
        "the displacement element FESystem(element, 2) and the element's "
        "quadratures, mapping and output subdivisions from it. "
        "FE_SimplexP(k) or FE_SimplexP_Bubbles(k), k = 1 or 2, or any "
        "name FETools::get_fe_by_name() knows, including elements a "
        "program registered with FETools::add_fe_name(). The element "
        "needs one dof on each vertex (no discontinuous elements). Empty: "
        "FE_SimplexP(Element degree). Given, it overrides Element degree; "
        "a scene that gives both must mean the same element.");
      prm.declare_entry("Linear solver",
                        "UMFPACK",
                        Patterns::Selection("UMFPACK|KLU|CG-AMG"),
                        "UMFPACK: sparse direct, multifrontal (serial; best "
                        "for large blocks); KLU: sparse direct, SuiteSparse's "
                        "KLU (little overhead per factorization, keeps the "
                        "pivot order between contact iterations; best for "
                        "many small blocks); CG-AMG: Trilinos CG with ML "
                        "AMG.");
      prm.declare_entry("Solver tolerance",
                        "1e-10",
                        Patterns::Double(0.),
                        "Relative residual for CG-AMG.");
      prm.declare_entry("Constraint method",
                        "exact",
                        Patterns::Selection("exact|penalty"),
                        "exact: constraints through AffineConstraints; "
                        "penalty: the thesis's stiff springs (3.9).");
      prm.declare_entry("Penalty factor",
                        "100",
                        Patterns::Double(0.),
                        "Spring stiffness of penalty constraints as a "
                        "multiple of the largest Young's modulus times the "
                        "thickness (N/m).");
      prm.declare_entry(
        "Matrix update tolerance",
        "1e-3",
        Patterns::Double(0.),
        "Element matrices are rebuilt when a vertex has moved by more than "
        "this fraction of its cell's diameter since the last build; 0 "
        "rebuilds every step.");
      prm.declare_entry(
        "Rotate with spin",
        "true",
        Patterns::Bool(),
        "Rotate nodal velocities and cell stresses by the local rotation of "
        "each step's increment, so that a spinning block keeps spinning "
        "(DDA carries its rotation the same way). See doc/theory.md.");
      prm.leave_subsection();
    }



    void
    Control::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Control");
      const auto analysis = prm.get("Analysis type");
      analysis_type =
        analysis == "static"  ? time::AnalysisType::static_analysis :
        analysis == "dynamic" ? time::AnalysisType::dynamic_analysis :
                                time::AnalysisType::quasi_static;
      time_integrator_name = prm.get("Time integrator");
      time_integrator      = time::create_time_integrator(
        time::TimeIntegratorRegistry::create_and_parse(time_integrator_name,
                                                       prm),
        analysis_type);
      time_step = prm.get_double("Time step");
      AssertThrow(time_step > 0.,
                  ExcMessage("Control/Time step: " + prm.get("Time step") +
                             " is not positive. Give a time step greater "
                             "than zero in seconds, e.g. 1e-3."));
      end_time = prm.get_double("End time");
      AssertThrow(end_time > 0.,
                  ExcMessage("Control/End time: " + prm.get("End time") +
                             " is not positive. Give the end time in "
                             "seconds."));
      max_displacement_ratio = prm.get_double("Maximum displacement ratio");
      AssertThrow(max_displacement_ratio > 0.,
                  ExcMessage("Control/Maximum displacement ratio: must be "
                             "greater than zero, e.g. 0.01."));
      max_step_cuts     = prm.get_integer("Maximum step cuts");
      const auto ls     = prm.get("Linear solver");
      linear_solver     = ls == "UMFPACK" ? LinearSolverType::umfpack :
                          ls == "KLU"     ? LinearSolverType::klu :
                                            LinearSolverType::cg_amg;
      solver_tolerance  = prm.get_double("Solver tolerance");
      constraint_method = prm.get("Constraint method") == "exact" ?
                            ConstraintMethod::exact :
                            ConstraintMethod::penalty;
      penalty_factor    = prm.get_double("Penalty factor");
      AssertThrow(constraint_method == ConstraintMethod::exact ||
                    penalty_factor > 0.,
                  ExcMessage("Control/Penalty factor: must be greater than "
                             "zero with 'Constraint method = penalty'."));
      matrix_update_tolerance = prm.get_double("Matrix update tolerance");
      rotate_with_spin        = prm.get_bool("Rotate with spin");

      // The element: Finite element, or else FE_SimplexP(Element degree).
      const std::string by_degree =
        "FE_SimplexP(" + prm.get("Element degree") + ")";
      finite_element      = Utilities::trim(prm.get("Finite element"));
      element_from_degree = finite_element.empty();
      if (element_from_degree)
        finite_element = by_degree;
      const Element element = make_element(finite_element);
      // The entry's path as ParameterHandler mangles it.
      const bool degree_given = prm.get_entries_wrongly_not_set().count(
                                  "Control.Element_20degree") == 0;
      AssertThrow(element_from_degree || !degree_given ||
                    element.scalar->get_name() ==
                      make_element(by_degree).scalar->get_name(),
                  ExcMessage("Control/Finite element: '" + finite_element +
                             "' and Control/Element degree = " +
                             prm.get("Element degree") + " (" + by_degree +
                             ") name different elements. Give only one of "
                             "the two entries."));
      prm.leave_subsection();
    }



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
                        "change is cut in half and retried.");
      prm.declare_entry(
        "Reused factorization iterations",
        "10",
        Patterns::Integer(0, 100),
        "With UMFPACK or KLU: a system whose contact springs changed is first "
        "solved by GMRES preconditioned with the last factorization, and "
        "factorized anew only if GMRES needs more than this many "
        "iterations (the result is the same to a relative residual of "
        "1e-12). 0: factorize every changed system.");
      prm.declare_entry("Vertex-vertex method",
                        "revised",
                        Patterns::Selection("revised|shortest path"),
                        "revised: entrance edge from the vertex trajectory, "
                        "temporary vertex-vertex spring for genuine "
                        "indeterminacy (thesis 6.2, 6.3); shortest path: "
                        "the original DDA rule, the potential reference "
                        "edge with the smaller penetration.");
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
      reuse_iterations     = prm.get_integer("Reused factorization iterations");
      vertex_vertex_method = prm.get("Vertex-vertex method") == "revised" ?
                               VertexVertexMethod::revised :
                               VertexVertexMethod::shortest_path;
      max_penetration_ratio = prm.get_double("Maximum penetration ratio");
      AssertThrow(max_penetration_ratio > 0. ||
                    penalty_method == PenaltyMethod::fixed,
                  ExcMessage("Contact/Maximum penetration ratio: must be "
                             "greater than zero with 'Penalty = "
                             "automatic'."));
      prm.leave_subsection();
    }



    void
    Material::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Density",
                        "2600",
                        Patterns::Double(0.),
                        "Mass density (kg/m^3).");
      prm.declare_entry("Young's modulus",
                        "50e9",
                        Patterns::Double(0.),
                        "Young's modulus (Pa), greater than zero.");
      prm.declare_entry("Poisson's ratio",
                        "0.25",
                        Patterns::Double(-1., 0.5),
                        "Poisson's ratio, in (-1, 0.5).");
      prm.declare_entry("Friction angle",
                        "30",
                        Patterns::Double(0., 90.),
                        angle_description("Internal friction angle"));
      prm.declare_entry("Joint friction angle",
                        "-1",
                        Patterns::Double(-1., 90.),
                        "Friction angle of contacts on this material's "
                        "faces (degrees, in [0, 90)); -1: "
                        "Materials/Joint/Friction angle. A contact uses the "
                        "smaller angle of its two sides.");
      prm.declare_entry("Cohesion",
                        "0",
                        Patterns::Double(0.),
                        "Cohesion (Pa), used by fracture.");
      prm.declare_entry("Fracture",
                        "false",
                        Patterns::Bool(),
                        "Whether cells of this material may crack: their "
                        "interior edges are checked against "
                        "Fracture/Criterion with this material's "
                        "cohesion, friction angle and tensile strength.");
      prm.declare_entry("Tensile strength",
                        "0",
                        Patterns::Double(0.),
                        "Tensile strength (Pa), used by fracture.");
      prm.declare_entry("Viscosity",
                        "0",
                        Patterns::Double(0.),
                        "Viscous resistance per unit volume, force = "
                        "-viscosity * velocity (kg/(m^3 s)), thesis 3.8.");
    }



    void
    Material::parse_parameters(ParameterHandler &prm, const std::string &n)
    {
      name           = n;
      density        = prm.get_double("Density");
      youngs_modulus = prm.get_double("Young's modulus");
      AssertThrow(youngs_modulus > 0.,
                  ExcMessage("Materials/" + n +
                             "/Young's modulus: must be greater than zero."));
      poissons_ratio = prm.get_double("Poisson's ratio");
      AssertThrow(poissons_ratio < 0.5 && poissons_ratio > -1.,
                  ExcMessage("Materials/" + n +
                             "/Poisson's ratio: " + prm.get("Poisson's ratio") +
                             " gives an incompressible or unstable material; "
                             "give a value in (-1, 0.5)."));
      friction_angle       = prm.get_double("Friction angle");
      joint_friction_angle = prm.get_double("Joint friction angle");
      AssertThrow(joint_friction_angle < 90.,
                  ExcMessage("Materials/" + n +
                             "/Joint friction angle: must be below 90 "
                             "degrees."));
      cohesion         = prm.get_double("Cohesion");
      tensile_strength = prm.get_double("Tensile strength");
      viscosity        = prm.get_double("Viscosity");
      fracture         = prm.get_bool("Fracture");
    }



    unsigned int
    Materials::id(const std::string &name, const std::string &entry) const
    {
      std::string known;
      for (unsigned int i = 0; i < materials.size(); ++i)
        {
          if (materials[i].name == name)
            return i;
          known += (i > 0 ? ", " : "") + materials[i].name;
        }
      AssertThrow(false,
                  ExcMessage(entry + ": '" + name +
                             "' is not a material. Known materials "
                             "(Materials/Names): " +
                             (known.empty() ? "none" : known) + "."));
      return 0;
    }



    void
    Materials::declare_parameters(ParameterHandler               &prm,
                                  const std::vector<std::string> &names)
    {
      prm.enter_subsection("Materials");
      prm.declare_entry("Names",
                        "",
                        Patterns::Anything(),
                        "Comma separated material names; each has a "
                        "subsection of that name.");
      prm.declare_entry("Plane condition",
                        "plane stress",
                        Patterns::Selection("plane stress|plane strain"),
                        "Plane stress (thin plate) or plane strain.");
      prm.declare_entry(
        "Constitutive law",
        "linear elasticity",
        Patterns::Selection(ConstitutiveLawRegistry::joined_names()),
        ConstitutiveLawRegistry::documentation(
          "The stress-strain law of every material (a plugin, see "
          "include/ndda/physics/constitutive_law.h; each reads its own "
          "entries from the subsection of its name). The laws:"));
      ConstitutiveLawRegistry::declare_parameters(prm);
      prm.declare_entry("Thickness",
                        "1",
                        Patterns::Double(0.),
                        "Out-of-plane thickness (m); masses, loads and "
                        "stiffnesses scale with it.");
      for (const auto &name : names)
        {
          prm.enter_subsection(name);
          Material::declare_parameters(prm);
          prm.leave_subsection();
        }
      prm.enter_subsection("Joint");
      prm.declare_entry("Friction angle",
                        "25",
                        Patterns::Double(0., 90.),
                        angle_description("Friction angle of joints and "
                                          "cracks"));
      prm.declare_entry("Cohesion",
                        "0",
                        Patterns::Double(0.),
                        "Cohesion of joints (Pa): contacts that touch when "
                        "the run starts are bonded; a bond holds a shear "
                        "force up to cohesion times contact length plus "
                        "friction, and breaks for good when it is "
                        "exceeded.");
      prm.declare_entry("Tensile strength",
                        "0",
                        Patterns::Double(0.),
                        "Tensile strength of joints (Pa): a bonded contact "
                        "holds tension up to this times its contact length "
                        "and breaks for good beyond it.");
      prm.leave_subsection();
      prm.leave_subsection();
    }



    void
    Materials::parse_parameters(ParameterHandler               &prm,
                                const std::vector<std::string> &names)
    {
      prm.enter_subsection("Materials");
      constitutive_law_name = prm.get("Constitutive law");
      constitutive_law =
        ConstitutiveLawRegistry::create_and_parse(constitutive_law_name, prm);
      plane_strain = prm.get("Plane condition") == "plane strain";
      thickness    = prm.get_double("Thickness");
      AssertThrow(thickness > 0.,
                  ExcMessage("Materials/Thickness: must be greater than "
                             "zero."));
      materials.clear();
      for (const auto &name : names)
        {
          prm.enter_subsection(name);
          materials.emplace_back();
          materials.back().parse_parameters(prm, name);
          prm.leave_subsection();
        }
      prm.enter_subsection("Joint");
      joint.friction_angle   = prm.get_double("Friction angle");
      joint.cohesion         = prm.get_double("Cohesion");
      joint.tensile_strength = prm.get_double("Tensile strength");
      prm.leave_subsection();
      prm.leave_subsection();
    }



    void
    Geometry::declare_parameters(ParameterHandler               &prm,
                                 const std::vector<std::string> &block_names,
                                 const std::vector<std::string> &region_names)
    {
      prm.enter_subsection("Geometry");
      prm.declare_entry("Blocks",
                        "",
                        Patterns::Anything(),
                        "Comma separated names of polygon blocks; each has "
                        "a subsection of that name.");
      prm.declare_entry("Regions",
                        "",
                        Patterns::Anything(),
                        "Comma separated names of rock regions cut into "
                        "blocks by joints; each has a subsection of that "
                        "name.");
      prm.declare_entry("Mesh file",
                        "",
                        Patterns::Anything(),
                        "A gmsh .msh file (relative to the .prm file) whose "
                        "physical surfaces are blocks. Used instead of "
                        "Blocks and Regions.");
      prm.declare_entry("Mesh file materials",
                        "",
                        Patterns::Anything(),
                        "Material of each physical surface of the mesh "
                        "file, 'tag: material, tag: material'. Empty: the "
                        "physical tag is the material id, an index into "
                        "Materials/Names (0 is the first).");
      prm.declare_entry("Minimum angle",
                        "30",
                        Patterns::Double(10., 33.),
                        "Minimum triangle angle of the Delaunay "
                        "refinement (degrees).");
      for (const auto &name : block_names)
        {
          prm.enter_subsection(name);
          prm.declare_entry("Outer boundary",
                            "",
                            Patterns::Anything(),
                            "Polygon 'x, y; x, y; ...' (m), either "
                            "orientation.");
          prm.declare_entry("Holes",
                            "",
                            Patterns::Anything(),
                            "Hole polygons inside the block, separated by "
                            "'|'.");
          prm.declare_entry("Cracks",
                            "",
                            Patterns::Anything(),
                            "Pre-existing crack segments 'x1, y1, x2, y2; "
                            "...' inside the block.");
          declare_mesh_size(prm);
          declare_initial_state(prm);
          prm.leave_subsection();
        }
      for (const auto &name : region_names)
        {
          prm.enter_subsection(name);
          prm.declare_entry("Outer boundary",
                            "",
                            Patterns::Anything(),
                            "Polygon of the rock region 'x, y; ...' (m).");
          prm.declare_entry("Holes",
                            "",
                            Patterns::Anything(),
                            "Hole polygons, separated by '|'.");
          prm.declare_entry("Joints",
                            "",
                            Patterns::Anything(),
                            "Joint segments 'x1, y1, x2, y2; ...' that cut "
                            "the region into blocks.");
          prm.declare_entry("Keep dangling joints as cracks",
                            "true",
                            Patterns::Bool(),
                            "Joint parts that end inside a block become "
                            "cracks of it (true) or are dropped (false).");
          declare_mesh_size(prm);
          declare_initial_state(prm);
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }



    void
    Geometry::parse_parameters(ParameterHandler               &prm,
                               const std::vector<std::string> &block_names,
                               const std::vector<std::string> &region_names,
                               const Materials                &materials,
                               const std::string              &base_directory)
    {
      prm.enter_subsection("Geometry");
      min_angle = prm.get_double("Minimum angle");
      mesh_file = prm.get("Mesh file");
      if (!mesh_file.empty())
        {
          if (mesh_file.front() != '/')
            mesh_file = base_directory + mesh_file;
          std::ifstream in(mesh_file);
          AssertThrow(in.good(),
                      ExcMessage("Geometry/Mesh file: cannot open '" +
                                 mesh_file +
                                 "'. Check the path; a relative path is "
                                 "taken relative to the .prm file."));
          AssertThrow(block_names.empty() && region_names.empty(),
                      ExcMessage("Geometry/Mesh file: a mesh file is given "
                                 "together with Blocks or Regions. Use "
                                 "either the mesh file or the polygons."));
          for (const auto &item : split(prm.get("Mesh file materials"), ","))
            {
              const auto pair = Utilities::split_string_list(item, ":");
              AssertThrow(pair.size() == 2,
                          ExcMessage("Geometry/Mesh file materials: '" + item +
                                     "' is not 'tag: material'."));
              const double tag =
                to_double(pair[0], "Geometry/Mesh file materials");
              AssertThrow(tag >= 0 && tag == std::floor(tag),
                          ExcMessage("Geometry/Mesh file materials: '" +
                                     pair[0] + "' is not a physical tag."));
              materials.id(pair[1], "Geometry/Mesh file materials");
              mesh_file_materials.emplace_back(static_cast<unsigned int>(tag),
                                               pair[1]);
            }
        }
      blocks.clear();
      block_states.clear();
      for (const auto &name : block_names)
        {
          const std::string where = "Geometry/" + name;
          prm.enter_subsection(name);
          geometry::BlockDescription block;
          block.name = name;
          block.outer =
            parse_points(prm.get("Outer boundary"), where + "/Outer boundary");
          block.holes  = parse_rings(prm.get("Holes"), where + "/Holes");
          block.cracks = parse_segments(prm.get("Cracks"), where + "/Cracks");
          parse_mesh_size(prm, where, materials, block);
          blocks.push_back(block);
          block_states.push_back(parse_initial_state(prm, where));
          prm.leave_subsection();
        }
      regions.clear();
      region_states.clear();
      for (const auto &name : region_names)
        {
          const std::string where = "Geometry/" + name;
          prm.enter_subsection(name);
          geometry::RegionDescription region;
          region.name = name;
          region.outer =
            parse_points(prm.get("Outer boundary"), where + "/Outer boundary");
          region.holes  = parse_rings(prm.get("Holes"), where + "/Holes");
          region.joints = parse_segments(prm.get("Joints"), where + "/Joints");
          region.keep_dangling_as_cracks =
            prm.get_bool("Keep dangling joints as cracks");
          parse_mesh_size(prm, where, materials, region);
          regions.push_back(region);
          region_states.push_back(parse_initial_state(prm, where));
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }



    void
    Loads::declare_parameters(ParameterHandler               &prm,
                              const std::vector<std::string> &point_names,
                              const std::vector<std::string> &line_names)
    {
      prm.enter_subsection("Loads");
      prm.declare_entry(
        "Gravity",
        "0; 0",
        Patterns::Anything(),
        "Gravitational acceleration g_x; g_y (m/s^2) as "
        "functions of t (x and y may be used too), e.g. '0; -9.81'.");
      prm.declare_entry("Point loads",
                        "",
                        Patterns::Anything(),
                        "Comma separated names of point loads; each has a "
                        "subsection of that name.");
      prm.declare_entry("Line loads",
                        "",
                        Patterns::Anything(),
                        "Comma separated names of loads on boundary "
                        "segments; each has a subsection of that name.");
      for (const auto &name : point_names)
        {
          prm.enter_subsection(name);
          prm.declare_entry("Point",
                            "0, 0",
                            Patterns::Anything(),
                            "Point of application 'x, y' (m), inside or on "
                            "a block.");
          prm.declare_entry(
            "Force",
            "0; 0",
            Patterns::Anything(),
            "Force f_x; f_y (N) as functions of t (and of the initial position x, y).");
          prm.leave_subsection();
        }
      for (const auto &name : line_names)
        {
          prm.enter_subsection(name);
          prm.declare_entry("Segment",
                            "",
                            Patterns::Anything(),
                            "Boundary segment 'x1, y1, x2, y2' (m); the load "
                            "acts on every boundary edge on it.");
          prm.declare_entry("Type",
                            "pressure",
                            Patterns::Selection("pressure|traction"),
                            "pressure: scalar, normal to the boundary, "
                            "positive pushes into the block; traction: "
                            "vector t_x; t_y.");
          prm.declare_entry("Value",
                            "0",
                            Patterns::Anything(),
                            "Pressure p (Pa) or traction t_x; t_y (Pa) as "
                            "functions of x, y and t.");
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }



    void
    Loads::parse_parameters(ParameterHandler               &prm,
                            const std::vector<std::string> &point_names,
                            const std::vector<std::string> &line_names)
    {
      prm.enter_subsection("Loads");
      gravity = prm.get("Gravity");
      check_function(gravity, 2, "x,y,t", "Loads/Gravity");
      point_loads.clear();
      for (const auto &name : point_names)
        {
          prm.enter_subsection(name);
          const std::string where = "Loads/" + name;
          PointLoad         load;
          load.name        = name;
          const auto point = parse_points(prm.get("Point"), where + "/Point");
          AssertThrow(point.size() == 1,
                      ExcMessage(where + "/Point: give exactly one point "
                                         "'x, y'."));
          load.point = point[0];
          load.force = prm.get("Force");
          check_function(load.force, 2, "x,y,t", where + "/Force");
          point_loads.push_back(load);
          prm.leave_subsection();
        }
      line_loads.clear();
      for (const auto &name : line_names)
        {
          prm.enter_subsection(name);
          const std::string where = "Loads/" + name;
          LineLoad          load;
          load.name = name;
          const auto segment =
            parse_segments(prm.get("Segment"), where + "/Segment");
          AssertThrow(segment.size() == 1,
                      ExcMessage(where + "/Segment: give exactly one "
                                         "segment 'x1, y1, x2, y2'."));
          load.segment     = segment[0];
          load.is_pressure = prm.get("Type") == "pressure";
          load.value       = prm.get("Value");
          check_function(load.value,
                         load.is_pressure ? 1 : 2,
                         "x,y,t",
                         where + "/Value");
          line_loads.push_back(load);
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }



    void
    BoundaryConditions::declare_parameters(
      ParameterHandler               &prm,
      const std::vector<std::string> &names)
    {
      prm.enter_subsection("Boundary conditions");
      prm.declare_entry("Names",
                        "",
                        Patterns::Anything(),
                        "Comma separated names of displacement constraints; "
                        "each has a subsection of that name.");
      for (const auto &name : names)
        {
          prm.enter_subsection(name);
          prm.declare_entry(
            "Type",
            "fixed",
            Patterns::Selection("fixed|roller|displacement|velocity"),
            "fixed: no displacement; roller: free along 'Roller angle', "
            "displacement 'Value' normal to it; displacement / velocity: "
            "both components prescribed by 'Value'.");
          prm.declare_entry("Points",
                            "",
                            Patterns::Anything(),
                            "Constrained points 'x, y; x, y' (m); each must "
                            "be inside or on a block.");
          prm.declare_entry("Segments",
                            "",
                            Patterns::Anything(),
                            "Boundary segments 'x1, y1, x2, y2; ...' (m); "
                            "every boundary vertex on them is constrained.");
          prm.declare_entry("Roller angle",
                            "0",
                            Patterns::Double(-360., 360.),
                            angle_description("Direction along which a "
                                              "roller moves freely, from "
                                              "the x axis"));
          prm.declare_entry("Value",
                            "0; 0",
                            Patterns::Anything(),
                            "displacement: u_x; u_y (m); velocity: v_x; v_y "
                            "(m/s); roller: normal displacement d (m); as "
                            "functions of t and of the initial position x, "
                            "y of each node. Not used for fixed.");
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }



    void
    BoundaryConditions::parse_parameters(ParameterHandler               &prm,
                                         const std::vector<std::string> &names)
    {
      prm.enter_subsection("Boundary conditions");
      conditions.clear();
      for (const auto &name : names)
        {
          prm.enter_subsection(name);
          const std::string where = "Boundary conditions/" + name;
          BoundaryCondition bc;
          bc.name         = name;
          const auto type = prm.get("Type");
          bc.type         = type == "fixed"        ? ConstraintType::fixed :
                            type == "roller"       ? ConstraintType::roller :
                            type == "displacement" ? ConstraintType::displacement :
                                                     ConstraintType::velocity;
          bc.points       = parse_points(prm.get("Points"), where + "/Points");
          bc.segments =
            parse_segments(prm.get("Segments"), where + "/Segments");
          AssertThrow(!bc.points.empty() || !bc.segments.empty(),
                      ExcMessage(where + ": neither Points nor Segments is "
                                         "given. Say where the constraint "
                                         "acts."));
          bc.roller_angle = prm.get_double("Roller angle");
          bc.value        = prm.get("Value");
          if (bc.type == ConstraintType::roller)
            {
              if (bc.value == "0; 0")
                bc.value = "0";
              check_function(bc.value, 1, "x,y,t", where + "/Value");
            }
          else if (bc.type != ConstraintType::fixed)
            check_function(bc.value, 2, "x,y,t", where + "/Value");
          conditions.push_back(bc);
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }



    void
    Bolts::declare_parameters(ParameterHandler               &prm,
                              const std::vector<std::string> &names)
    {
      prm.enter_subsection("Bolts");
      prm.declare_entry("Names",
                        "",
                        Patterns::Anything(),
                        "Comma separated bolt names; each has a subsection "
                        "of that name.");
      for (const auto &name : names)
        {
          prm.enter_subsection(name);
          prm.declare_entry("End points",
                            "",
                            Patterns::Anything(),
                            "The two anchor points 'x1, y1, x2, y2' (m).");
          prm.declare_entry("Stiffness",
                            "1e9",
                            Patterns::Double(0.),
                            "Axial stiffness (N/m).");
          prm.declare_entry("Pretension",
                            "0",
                            Patterns::Double(),
                            "Axial pre-tension (N), pulling the ends "
                            "together.");
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }



    void
    Bolts::parse_parameters(ParameterHandler               &prm,
                            const std::vector<std::string> &names)
    {
      prm.enter_subsection("Bolts");
      bolts.clear();
      for (const auto &name : names)
        {
          prm.enter_subsection(name);
          const std::string where = "Bolts/" + name;
          const auto        ends =
            parse_segments(prm.get("End points"), where + "/End points");
          AssertThrow(ends.size() == 1,
                      ExcMessage(where + "/End points: give exactly two "
                                         "points 'x1, y1, x2, y2'."));
          bolts.push_back({name,
                           ends[0].a,
                           ends[0].b,
                           prm.get_double("Stiffness"),
                           prm.get_double("Pretension")});
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }



    void
    Output::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Directory",
                        "",
                        Patterns::Anything(),
                        "Output directory; empty: output/<Scene name>/.");
      prm.declare_entry("Interval",
                        "0",
                        Patterns::Double(0.),
                        "Simulated time between graphical outputs (s); 0: "
                        "every step.");
      prm.declare_entry("Write vtu",
                        "true",
                        Patterns::Bool(),
                        "Write solution-NNNNN.vtu files and solution.pvd.");
      prm.declare_entry("Write hdf5",
                        "false",
                        Patterns::Bool(),
                        "Also write solution.h5 and solution.xdmf "
                        "(element degree 1 only).");
      prm.declare_entry("Measure points",
                        "",
                        Patterns::Anything(),
                        "Points 'x, y; x, y' (m) whose displacement, "
                        "velocity and stress histories are written to "
                        "measure_points.txt.");
      prm.declare_entry("Progress interval",
                        "2",
                        Patterns::Double(0.),
                        "Wall-clock seconds between progress lines.");
      prm.leave_subsection();
    }



    void
    Output::parse_parameters(ParameterHandler  &prm,
                             const std::string &scene_name)
    {
      prm.enter_subsection("Output");
      directory = prm.get("Directory");
      if (directory.empty())
        directory = "output/" + scene_name;
      if (directory.back() != '/')
        directory += '/';
      interval   = prm.get_double("Interval");
      write_vtu  = prm.get_bool("Write vtu");
      write_hdf5 = prm.get_bool("Write hdf5");
      measure_points =
        parse_points(prm.get("Measure points"), "Output/Measure points");
      progress_interval = prm.get_double("Progress interval");
      prm.leave_subsection();
    }



    void
    Parameters::declare_parameters(ParameterHandler &prm,
                                   const NameLists  &names)
    {
      prm.declare_entry("Scene name",
                        "",
                        Patterns::Anything(),
                        "Name of the scene, used for the output directory; "
                        "empty: the .prm file's name without extension.");
      Control::declare_parameters(prm);
      Contact::declare_parameters(prm);
      Materials::declare_parameters(prm, names.materials);
      Geometry::declare_parameters(prm, names.blocks, names.regions);
      Loads::declare_parameters(prm, names.point_loads, names.line_loads);
      BoundaryConditions::declare_parameters(prm, names.boundary_conditions);
      Bolts::declare_parameters(prm, names.bolts);
      Output::declare_parameters(prm);
      fracture::Parameters::declare_parameters(prm);
      postprocess::Parameters::declare_parameters(prm);
    }



    void
    Parameters::read(const std::string &input,
                     const std::string &filename,
                     ParameterHandler  &prm)
    {
      // Pass 1: only the name lists, everything else skipped.
      NameLists names;
      {
        ParameterHandler lists;
        declare_parameters(lists, NameLists());
        try
          {
            lists.parse_input_from_string(input, "", true);
          }
        catch (const ExceptionBase &exc)
          {
            AssertThrow(false,
                        ExcMessage("Error in '" + filename +
                                   "': " + message_of(exc, filename)));
          }
        const auto get = [&](const std::string &section,
                             const std::string &entry) {
          lists.enter_subsection(section);
          const auto names =
            parse_names(lists.get(entry), section + "/" + entry);
          lists.leave_subsection();
          return names;
        };
        names.blocks              = get("Geometry", "Blocks");
        names.regions             = get("Geometry", "Regions");
        names.materials           = get("Materials", "Names");
        names.point_loads         = get("Loads", "Point loads");
        names.line_loads          = get("Loads", "Line loads");
        names.boundary_conditions = get("Boundary conditions", "Names");
        names.bolts               = get("Bolts", "Names");
      }
      std::set<std::string> geometry_names(names.blocks.begin(),
                                           names.blocks.end());
      for (const auto &name : names.regions)
        AssertThrow(geometry_names.insert(name).second,
                    ExcMessage("Geometry: '" + name +
                               "' is both a block and a region name. Names "
                               "must be unique."));
      std::set<std::string> load_names(names.point_loads.begin(),
                                       names.point_loads.end());
      for (const auto &name : names.line_loads)
        AssertThrow(load_names.insert(name).second,
                    ExcMessage("Loads: '" + name +
                               "' is both a point load and a line load "
                               "name. Names must be unique."));
      AssertThrow(!names.materials.empty(),
                  ExcMessage("Materials/Names: no material is declared. "
                             "Give 'set Names = rock' and a subsection "
                             "'rock' with its properties."));

      // Pass 2: everything, strictly.
      declare_parameters(prm, names);
      try
        {
          prm.parse_input_from_string(input, "", false);
        }
      catch (const ExceptionBase &exc)
        {
          AssertThrow(false,
                      ExcMessage("Error in '" + filename +
                                 "': " + message_of(exc, filename) +
                                 " Run 'ndda --print-parameters' for all "
                                 "entries and their allowed values; names "
                                 "of blocks, materials, loads and "
                                 "constraints must be listed in their "
                                 "section's name list first."));
        }

      scene_name = prm.get("Scene name");
      if (scene_name.empty())
        {
          const auto slash = filename.find_last_of('/');
          scene_name =
            filename.substr(slash == std::string::npos ? 0 : slash + 1);
          const auto dot = scene_name.find_last_of('.');
          if (dot != std::string::npos)
            scene_name = scene_name.substr(0, dot);
          if (scene_name.empty())
            scene_name = "scene";
        }
      const auto  slash = filename.find_last_of('/');
      std::string base_directory =
        slash == std::string::npos ? "" : filename.substr(0, slash + 1);

      control.parse_parameters(prm);
      contact.parse_parameters(prm);
      materials.parse_parameters(prm, names.materials);
      geometry.parse_parameters(
        prm, names.blocks, names.regions, materials, base_directory);
      loads.parse_parameters(prm, names.point_loads, names.line_loads);
      boundary_conditions.parse_parameters(prm, names.boundary_conditions);
      bolts.parse_parameters(prm, names.bolts);
      fracture.parse_parameters(prm);
      output.parse_parameters(prm, scene_name);
      postprocess.parse_parameters(prm);

      if (output.write_hdf5)
        {
          const Element      element = make_element(control.finite_element);
          const unsigned int n_subdivisions = element.n_output_subdivisions;
          AssertThrow(
            n_subdivisions == 1,
            ExcMessage(
              "Output/Write hdf5: HDF5/XDMF output in deal.II 9.4 supports "
              "only linear cells, but " +
              (control.element_from_degree ?
                 "Control/Element degree is " +
                   std::to_string(element.scalar->degree) :
                 "Control/Finite element is " + control.finite_element +
                   " (written with " + std::to_string(n_subdivisions) +
                   " subdivisions per cell)") +
              ". Set 'Write hdf5 = false' or use degree 1."));
        }
      AssertThrow(control.time_step <= control.end_time,
                  ExcMessage(
                    "Control/Time step: " + std::to_string(control.time_step) +
                    " is larger than Control/End time " +
                    std::to_string(control.end_time) +
                    ". Make the step smaller than the end time."));
    }



    void
    Parameters::read_file(const std::string &filename, ParameterHandler &prm)
    {
      std::ifstream in(filename);
      AssertThrow(in.good(),
                  ExcMessage("Cannot open the parameter file '" + filename +
                             "'. Check the path."));
      std::stringstream buffer;
      buffer << in.rdbuf();
      read(buffer.str(), filename, prm);
    }
  } // namespace parameters
} // namespace ndda
