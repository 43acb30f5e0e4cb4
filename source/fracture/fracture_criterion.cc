// SPDX-License-Identifier: GPL-3.0-or-later
//
// The fracture criterion registry (ASPECT-style plugins), the linear
// crossing time shared by the criteria, and subsection Fracture.

#include <deal.II/base/exceptions.h>

#include <ndda/fracture/fracture_criterion.h>


namespace ndda
{
  namespace fracture
  {
    using namespace dealii;

    // The built-in criteria, see NDDA_REGISTER_FRACTURE_CRITERION.
    void
    link_plugin_MohrCoulomb();
    void
    link_plugin_MaximumPrincipalStress();

    void
    FractureCriterion::link_builtin_plugins()
    {
      link_plugin_MohrCoulomb();
      link_plugin_MaximumPrincipalStress();
    }



    std::optional<double>
    limit_crossing_time(const double excess_start, const double excess_end)
    {
      if (excess_start > 0.)
        return 0.;
      if (excess_end > 0.)
        // excess_start <= 0 < excess_end: the ratio lies in [0, 1).
        return excess_start / (excess_start - excess_end);
      return std::nullopt;
    }



    EdgeFailure
    earlier_failure(const std::optional<double> &tension_time,
                    const std::optional<double> &shear_time)
    {
      EdgeFailure failure;
      if (tension_time && (!shear_time || *tension_time <= *shear_time))
        failure = {FailureMode::tension, *tension_time};
      else if (shear_time)
        failure = {FailureMode::shear, *shear_time};
      return failure;
    }



    void
    FractureCriterion::parse_parameters(ParameterHandler &)
    {}



    std::string
    FractureCriterion::fails_under_any_load(const Strength &) const
    {
      return "";
    }



    void
    register_fracture_criterion(const std::string &name,
                                const std::string &description,
                                void (*declare_parameters)(ParameterHandler &),
                                std::unique_ptr<FractureCriterion> (*create)())
    {
      FractureCriterionRegistry::add(name,
                                     description,
                                     declare_parameters,
                                     create);
    }



    std::vector<std::string>
    fracture_criterion_names()
    {
      return FractureCriterionRegistry::names();
    }



    std::string
    fracture_criterion_selection()
    {
      return FractureCriterionRegistry::joined_names();
    }



    std::unique_ptr<FractureCriterion>
    create_fracture_criterion(const std::string &name)
    {
      return FractureCriterionRegistry::create(name);
    }



  } // namespace fracture



  namespace parameters
  {
    using namespace dealii;

    void
    Fracture::declare_parameters(ParameterHandler &prm)
    {
      const std::string documentation =
        fracture::FractureCriterionRegistry::documentation(
          "Which criterion decides when, within a step, an interior edge of "
          "a block cracks (thesis chapter 5, doc/fracture.md). Each "
          "criterion reads its own entries from the subsection of its "
          "name. The criteria:");
      prm.enter_subsection("Fracture");
      {
        prm.declare_entry("Criterion",
                          "Mohr-Coulomb",
                          Patterns::Selection(
                            fracture::fracture_criterion_selection()),
                          documentation);
        prm.declare_entry(
          "Edge stress",
          "cell average",
          Patterns::Selection("cell average|nodal average|nonlocal average"),
          "The stress tensor of an edge. cell average: the mean of the "
          "stresses of the two cells beside it (thesis 5.21); nodal "
          "average: the mean of the nodal stresses of its two vertices, a "
          "nodal stress being the area-weighted mean of the stresses of the "
          "cells around the vertex (smoother crack paths, thesis 8.2); "
          "nonlocal average: the mean of the cell stresses within 'Nonlocal "
          "radius' of the edge's midpoint, weighted by area (1 - r^2/R^2)^2 "
          "and never across a crack: a material length that makes crack "
          "initiation converge as the mesh is refined (doc/fracture.md). "
          "Every criterion reads the stress this entry forms.");
        prm.declare_entry(
          "Nonlocal radius",
          "0",
          Patterns::Double(0.),
          "The radius R (m) of the nonlocal average (Edge stress = "
          "nonlocal average; required there, unused otherwise): a property "
          "of the material, not of the mesh. The average converges when "
          "the cells near a crack tip are a few times smaller than R "
          "(doc/fracture.md gives the measured convergence).");
        prm.declare_entry(
          "Split edges",
          "true",
          Patterns::Bool(),
          "true: edges that fail are split (node splitting, the crack "
          "sequence of thesis 5.3); false: failing edges are only counted "
          "in the statistics (detection).");
        prm.declare_entry(
          "Crack window",
          "0",
          Patterns::Double(0., 1.),
          "Edges whose failure time lies within this fraction of the step "
          "after the earliest one crack together with it; 0: one crack "
          "event per failure time (edges failing at the same instant still "
          "crack together).");
        prm.declare_entry(
          "Maximum crack events per step",
          "50",
          Patterns::Integer(1),
          "Limit on crack events (split, rebuild, re-solve) within one "
          "step; when it is reached the step is accepted with the edges "
          "that still fail, and the statistics file says so ('Crack limit "
          "hit').");
        prm.declare_entry(
          "Crack path",
          "mesh edges",
          Patterns::Selection("mesh edges|maximum tangential stress"),
          "How a crack grows from a tip inside a block. mesh edges: the "
          "edges that fail crack, whatever their direction (thesis 5.3). "
          "maximum tangential stress: an edge that fails near a crack tip "
          "(within the nonlocal radius or two edge lengths of it) makes "
          "the tip advance instead, in the direction of the maximum "
          "tangential stress (thesis 7.11) for the ratio K_II/K_I that the "
          "opening and sliding of the crack's last faces give; a vertex "
          "ahead of the tip is moved onto that direction and the edge to it "
          "cracks, so the path does not follow the mesh "
          "(doc/fracture.md, 'Crack paths free of the mesh'). Edges that "
          "fail away from tips crack as with mesh edges.");
        prm.declare_entry(
          "Tip mesh size",
          "0",
          Patterns::Double(0.),
          "Longest triangle edge (m) around every crack tip while cracks "
          "grow: after every crack event the cells near each tip are split "
          "by longest-edge bisection until their longest edge is at most "
          "h + (g - 1) d at distance d from the tip, g being Geometry/Mesh "
          "grading/Growth rate. The two faces of a crack are split "
          "together; the state goes to the new cells (exactly for P1 and "
          "P2: doc/fracture.md, 'Refinement ahead of a running crack'). "
          "The mesh at the start is graded by Geometry/Mesh grading "
          "instead (Crack tip mesh size for pre-existing cracks). 0: the "
          "mesh is not refined.");
        fracture::FractureCriterionRegistry::declare_parameters(prm);
      }
      prm.leave_subsection();
    }



    void
    Fracture::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Fracture");
      {
        const std::string method = prm.get("Edge stress");
        edge_stress_method       = method == "nodal average" ?
                                     fracture::EdgeStressMethod::nodal_average :
                                   method == "nonlocal average" ?
                                     fracture::EdgeStressMethod::nonlocal_average :
                                     fracture::EdgeStressMethod::cell_average;
        nonlocal_radius          = 0;
        if (edge_stress_method == fracture::EdgeStressMethod::nonlocal_average)
          {
            nonlocal_radius = prm.get_double("Nonlocal radius");
            AssertThrow(nonlocal_radius > 0.,
                        ExcMessage(
                          "Fracture/Nonlocal radius is 0, but Fracture/Edge "
                          "stress = nonlocal average needs a positive "
                          "radius: the material length (m) over which "
                          "stresses are averaged."));
          }
        criterion_name   = prm.get("Criterion");
        split_edges      = prm.get_bool("Split edges");
        crack_window     = prm.get_double("Crack window");
        max_crack_events = prm.get_integer("Maximum crack events per step");
        align_crack_paths =
          prm.get("Crack path") == "maximum tangential stress";
        tip_mesh_size = prm.get_double("Tip mesh size");
        criterion =
          fracture::FractureCriterionRegistry::create_and_parse(criterion_name,
                                                                prm);
      }
      prm.leave_subsection();
    }
  } // namespace parameters
} // namespace ndda
