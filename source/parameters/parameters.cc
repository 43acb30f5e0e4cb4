// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <ndda/contact/contact_law.h>
#include <ndda/kinematics/automatic_kinematics.h>
#include <ndda/kinematics/block_kinematics.h>
#include <ndda/parameters/parameters.h>
#include <ndda/physics/constitutive_law.h>
#include <ndda/physics/finite_element.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
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
      /**
       * The lines of @p input that enter a subsection or set an entry that
       * @p prm does not declare, or give a value with braces (which would
       * escape its pattern's check), as "line N: ..." texts, in file order.
       * Comments, continued lines and the entries inside an undeclared
       * subsection (not reported again) are taken care of.
       */
      std::vector<std::string>
      input_problems(const std::string &input, const ParameterHandler &prm)
      {
        // The declared subsections and entries, as paths joined by '\x1f':
        // from the handler's own listing (ParameterHandler has no query
        // for an entry that a Release build checks).
        const auto key_of = [](const std::vector<std::string> &path,
                               const std::string              &last) {
          std::string key;
          for (const auto &s : path)
            key += s + '\x1f';
          return key + last;
        };
        std::set<std::string> subsections, entries;
        {
          std::ostringstream listing;
          prm.print_parameters(listing, ParameterHandler::ShortPRM);
          std::istringstream       lines(listing.str());
          std::vector<std::string> path;
          std::string              l;
          while (std::getline(lines, l))
            {
              l = Utilities::trim(l);
              if (l.rfind("subsection ", 0) == 0)
                {
                  subsections.insert(
                    key_of(path, Utilities::trim(l.substr(11))));
                  path.push_back(Utilities::trim(l.substr(11)));
                }
              else if (l == "end" && !path.empty())
                path.pop_back();
              else if (l.rfind("set ", 0) == 0)
                entries.insert(
                  key_of(path, Utilities::trim(l.substr(4, l.find('=') - 4))));
            }
        }

        std::vector<std::string> found;
        std::vector<std::string> path;
        // Depth inside an undeclared subsection.
        unsigned int       skipped = 0;
        std::istringstream in(input);
        std::string        raw, line;
        unsigned int       number = 0, start = 0;
        const auto         where = [&]() {
          std::string text;
          for (const auto &s : path)
            text += (text.empty() ? "" : "/") + s;
          return text.empty() ? std::string("at the top level") :
                                        "in subsection '" + text + "'";
        };
        while (std::getline(in, raw))
          {
            ++number;
            if (line.empty())
              start = number;
            raw = Utilities::trim(raw.substr(0, raw.find('#')));
            if (!raw.empty() && raw.back() == '\\')
              {
                line += raw.substr(0, raw.size() - 1) + " ";
                continue;
              }
            const std::string text = Utilities::trim(line + raw);
            line.clear();
            std::istringstream words(text);
            std::string        keyword;
            words >> keyword;
            const std::string rest = Utilities::trim(
              text.substr(std::min(text.size(), keyword.size())));
            const std::string here = "line " + std::to_string(start) + ": ";
            if (keyword == "subsection")
              {
                if (skipped > 0 || subsections.count(key_of(path, rest)) == 0)
                  {
                    if (skipped == 0)
                      found.push_back(here + "no subsection '" + rest + "' " +
                                      where());
                    ++skipped;
                  }
                else
                  path.push_back(rest);
              }
            else if (keyword == "end")
              {
                if (skipped > 0)
                  --skipped;
                else if (!path.empty())
                  path.pop_back();
              }
            else if (keyword == "set" && skipped == 0)
              {
                const std::string name =
                  Utilities::trim(rest.substr(0, rest.find('=')));
                const auto equals = rest.find('=');
                if (entries.count(key_of(path, name)) == 0)
                  found.push_back(here + "no entry '" + name + "' " + where());
                else if (equals != std::string::npos &&
                         rest.find_first_of("{}", equals) != std::string::npos)
                  // ParameterHandler takes a value with braces for a set of
                  // variations and skips its pattern check.
                  found.push_back(here + "the value of '" + name +
                                  "' holds a brace '{' or '}', which is "
                                  "deal.II's syntax for parameter variations");
              }
          }
        return found;
      }



      /**
       * Pass 1 of Parameters::read(): only the name lists of @p input,
       * everything else skipped; checked to be unique across lists.
       */
      Parameters::NameLists
      read_name_lists(const std::string &input, const std::string &filename)
      {
        Parameters::NameLists names;
        ParameterHandler      lists;
        Parameters::declare_parameters(lists, Parameters::NameLists());
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
        return names;
      }



      /** The scene's name: Scene name, or the file's name without its
       * extension. */
      std::string
      scene_name_of(ParameterHandler &prm, const std::string &filename)
      {
        std::string scene_name = prm.get("Scene name");
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
        return scene_name;
      }



      /** Control: the analysis, the time integrator, step sizes and cuts. */
      void
      declare_time_entries(ParameterHandler &prm)
      {
        prm.declare_entry("Analysis type",
                          "dynamic",
                          Patterns::Selection("static|dynamic|quasi-static"),
                          "static: the velocity is set to zero at the start of "
                          "every step (DDA statics); dynamic: it is carried "
                          "over; quasi-static: no inertia, every step solves "
                          "equilibrium K d = f: every block must be "
                          "held, by boundary conditions, bolts or contacts "
                          "that touch when the run starts; a scene where a "
                          "block can still move as a rigid body is refused "
                          "before the run, with the block and its motion.");
        prm.declare_entry(
          "Time integrator",
          "generalized-alpha",
          Patterns::Selection(time::TimeIntegratorRegistry::joined_names()),
          time::TimeIntegratorRegistry::documentation(
            "The time integration scheme (a plugin, see "
            "include/ndda/time/time_integrator.h; each reads its own entries "
            "from the subsection of its name). The default, generalized-alpha, "
            "keeps the waves and bounces the step resolves and removes the "
            "modes it does not (stiff contact springs); DDA damps both, "
            "Newmark neither (doc/theory.md, 'The default'). With Analysis "
            "type = static "
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
      }



      /** Control: the finite element. */
      void
      declare_element_entries(ParameterHandler &prm)
      {
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
      }



      /** Control: linear solver, constraints, matrix updates, spin. */
      void
      declare_solver_entries(ParameterHandler &prm)
      {
        prm.declare_entry(
          "Linear solver",
          "direct",
          Patterns::Selection("UMFPACK|direct|KLU|CG-AMG|CG-Jacobi|MUMPS"),
          "direct: sparse Cholesky (CHOLMOD, supernodal) where the system "
          "matrix is symmetric positive definite (elasticity, inertia, "
          "contact springs, constraints), UMFPACK's LU where it is not "
          "(sliding friction): a third of the flops of the LU, "
          "back-substitutions 1.2-1.6 times faster, less memory "
          "(doc/performance.md); UMFPACK: sparse direct LU, "
          "multifrontal, for every system; KLU: sparse direct, "
          "SuiteSparse's KLU (little overhead per factorization, keeps "
          "the pivot order between contact iterations; best for many "
          "small blocks); CG-AMG: Trilinos CG with ML AMG; CG-Jacobi: CG "
          "(BiCGStab where sliding friction makes the matrix non-symmetric) "
          "preconditioned by the diagonal, on ndda's matrix itself: the "
          "least memory of all, for continua with a time step near the "
          "time a wave takes to cross an element (its iterations grow "
          "with that ratio); MUMPS: the "
          "parallel sparse direct solver MUMPS (through Trilinos' Amesos; "
          "its symmetric factorization where the matrix is symmetric, LU "
          "where it is not). On several MPI processes (mpirun -np N), "
          "MUMPS and CG-AMG solve with all of them; with direct, UMFPACK, "
          "KLU and CG-Jacobi the first process solves the whole system and sends the "
          "solution to the others, which repeats the run on one process to "
          "the bit.");
        prm.declare_entry("Solver tolerance",
                          "1e-10",
                          Patterns::Double(0.),
                          "Relative residual for CG-AMG and CG-Jacobi.");
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
          "Kinematics",
          "meshed",
          Patterns::Selection(
            kinematics::BlockKinematicsRegistry::joined_names() + "|" +
            kinematics::automatic_name),
          kinematics::BlockKinematicsRegistry::documentation(
            "How the blocks move, unless a block's or region's own "
            "Kinematics entry says otherwise (doc/design.md, \"Block "
            "kinematics\"). Every model keeps the block's nodes for "
            "contacts, loads, constraints, bolts and output, and turns "
            "blocks exactly. 'auto': a block starts with the Start model "
            "of subsection Automatic kinematics, is meshed when its "
            "stresses come near its strength and returns when it is "
            "unloaded (doc/theory.md, \"Automatic kinematics\")."));
        kinematics::AutomaticSettings::declare_parameters(prm);
        prm.declare_entry(
          "Matrix update tolerance",
          "1e-3",
          Patterns::Double(0.),
          "Element matrices are rebuilt when a vertex has moved by more than "
          "this fraction of its cell's diameter since the last build; 0 "
          "rebuilds every step.");
      }
    } // namespace



    void
    Control::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Control");
      declare_time_entries(prm);
      declare_element_entries(prm);
      declare_solver_entries(prm);
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
      linear_solver     = ls == "direct"    ? LinearSolverType::direct :
                          ls == "UMFPACK"   ? LinearSolverType::umfpack :
                          ls == "KLU"       ? LinearSolverType::klu :
                          ls == "MUMPS"     ? LinearSolverType::mumps :
                          ls == "CG-Jacobi" ? LinearSolverType::cg_jacobi :
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
      kinematics              = prm.get("Kinematics");
      automatic_kinematics.parse_parameters(prm);

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
      Fracture::declare_parameters(prm);
      Postprocess::declare_parameters(prm);
    }



    void
    Parameters::read(const std::string &input,
                     const std::string &filename,
                     ParameterHandler  &prm)
    {
      const NameLists names = read_name_lists(input, filename);

      // Pass 2: everything, strictly; every unknown entry and subsection
      // first, at once, each with its line (deal.II's own message names the
      // first problem only).
      declare_parameters(prm, names);
      const auto undeclared = input_problems(input, prm);
      try
        {
          AssertThrow(undeclared.empty(), ExcMessage(""));
          prm.parse_input_from_string(input, "", false);
        }
      catch (const ExceptionBase &exc)
        {
          std::string message = message_of(exc, filename);
          if (!undeclared.empty())
            {
              message = std::to_string(undeclared.size()) +
                        (undeclared.size() == 1 ? " problem" : " problems") +
                        ": ";
              for (unsigned int i = 0; i < undeclared.size() && i < 10; ++i)
                message += (i > 0 ? "; " : "") + undeclared[i];
              if (undeclared.size() > 10)
                message +=
                  "; and " + std::to_string(undeclared.size() - 10) + " more";
              message += ".";
            }
          AssertThrow(false,
                      ExcMessage("Error in '" + filename + "': " + message +
                                 " Run 'ndda --print-parameters' for all "
                                 "entries and their allowed values; names "
                                 "of blocks, materials, loads and "
                                 "constraints must be listed in their "
                                 "section's name list first."));
        }

      // Only now, after the strict pass has reported any unknown entry or
      // subsection with its line: a misspelled 'Materials' must be blamed
      // as such, not as a scene without materials.
      AssertThrow(!names.materials.empty(),
                  ExcMessage("Materials/Names: no material is declared in '" +
                             filename +
                             "'. Give 'set Names = rock' and a subsection "
                             "'rock' with its properties."));

      scene_name        = scene_name_of(prm, filename);
      const auto  slash = filename.find_last_of('/');
      std::string base_directory =
        slash == std::string::npos ? "" : filename.substr(0, slash + 1);

      try
        {
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
        }
      catch (const ExceptionBase &exc)
        {
          // ParameterHandler::get_double() and friends name neither the
          // file nor the line: "Can't convert the parameter value <1e-308>
          // for entry <Cohesion> to a double precision variable" (the
          // pattern accepted what strtod() calls out of range).
          const std::string message = message_of(exc, filename);
          const std::string tag     = "for entry <";
          const auto        at      = message.find(tag);
          if (message.find("Can't convert") == std::string::npos ||
              at == std::string::npos)
            throw;
          const auto        name_end = message.find('>', at);
          const std::string name =
            message.substr(at + tag.size(), name_end - at - tag.size());
          const auto        value_at = message.find("value <");
          const std::string value =
            value_at == std::string::npos ?
              std::string() :
              message.substr(value_at + 7,
                             message.find('>', value_at) - value_at - 7);
          std::istringstream lines(input);
          std::string        line, where;
          for (unsigned int number = 1; std::getline(lines, line); ++number)
            {
              line = Utilities::trim(line.substr(0, line.find('#')));
              const auto equals = line.find('=');
              if (line.rfind("set ", 0) == 0 && equals != std::string::npos &&
                  Utilities::trim(line.substr(4, equals - 4)) == name &&
                  Utilities::trim(line.substr(equals + 1)) == value)
                where +=
                  (where.empty() ? "line " : ", ") + std::to_string(number);
            }
          AssertThrow(false,
                      ExcMessage("Error in '" + filename + "'" +
                                 (where.empty() ? "" : ", " + where) + ": " +
                                 message +
                                 " Give a number between -1.7e308 and "
                                 "1.7e308, and 0 or at least 2.3e-308 in "
                                 "magnitude."));
        }
      check_consistency();
    }



    void
    Parameters::check_consistency() const
    {
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
      // Only splitting turns a zero strength into a block that falls
      // apart; 'Split edges = false' counts the failing edges.
      if (fracture.criterion && fracture.split_edges)
        {
          const auto strengths = material_strengths(materials);
          for (unsigned int m = 0; m < strengths.size(); ++m)
            if (strengths[m])
              {
                const std::string problem =
                  fracture.criterion->fails_under_any_load(*strengths[m]);
                AssertThrow(problem.empty(),
                            ExcMessage("Materials/" +
                                       materials.materials[m].name + ": " +
                                       problem +
                                       ". Give it a strength above zero, or "
                                       "'Fracture = false' if it must not "
                                       "crack."));
              }
        }
      AssertThrow(control.time_step <= control.end_time,
                  ExcMessage(
                    "Control/Time step: " + std::to_string(control.time_step) +
                    " is larger than Control/End time " +
                    std::to_string(control.end_time) +
                    ". Make the step smaller than the end time."));
    }



    std::vector<std::optional<fracture::Strength>>
    material_strengths(const Materials &materials)
    {
      std::vector<std::optional<fracture::Strength>> strengths;
      for (const auto &m : materials.materials)
        {
          strengths.emplace_back();
          if (!m.fracture)
            continue;
          fracture::Strength s;
          s.cohesion         = m.cohesion;
          s.friction_angle   = m.friction_angle * numbers::PI / 180.;
          s.tensile_strength = m.tensile_strength;
          strengths.back()   = s;
        }
      return strengths;
    }



    void
    Parameters::read_file(const std::string &filename, ParameterHandler &prm)
    {
      std::error_code error;
      AssertThrow(std::filesystem::exists(filename, error),
                  ExcMessage("The parameter file '" + filename +
                             "' does not exist. Check the path."));
      AssertThrow(!std::filesystem::is_directory(filename, error),
                  ExcMessage("'" + filename +
                             "' is a directory, not a parameter file. Give "
                             "the path of a .prm file."));
      std::ifstream in(filename);
      AssertThrow(in.good(),
                  ExcMessage("Cannot read the parameter file '" + filename +
                             "' (" + std::strerror(errno) +
                             "). Check its permissions."));
      std::stringstream buffer;
      buffer << in.rdbuf();
      AssertThrow(!in.bad(),
                  ExcMessage("Cannot read the parameter file '" + filename +
                             "' (" + std::strerror(errno) + ")."));
      read(buffer.str(), filename, prm);
    }

  } // namespace parameters
} // namespace ndda
