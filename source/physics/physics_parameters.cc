// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/parameters/entries.h>
#include <ndda/physics/constitutive_law.h>
#include <ndda/physics/physics_parameters.h>

namespace ndda
{
  namespace parameters
  {
    using namespace dealii;

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
  } // namespace parameters
} // namespace ndda
