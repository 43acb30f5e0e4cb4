// SPDX-License-Identifier: GPL-3.0-or-later
//
// The postprocessor registry, the defaults of the interface and
// subsection Postprocess.

#include <deal.II/base/utilities.h>

#include <deal.II/numerics/data_out.h>

#include <ndda/postprocess/postprocessor.h>

namespace ndda
{
  namespace postprocess
  {
    using namespace dealii;

    // The built-in postprocessors, see NDDA_REGISTER_PLUGIN.
    void
    link_plugin_DisplacementField();
    void
    link_plugin_VelocityField();
    void
    link_plugin_StressFields();
    void
    link_plugin_NodalStressFields();
    void
    link_plugin_BlockAndMaterial();
    void
    link_plugin_CrackFaces();
    void
    link_plugin_TimeStepStatistics();
    void
    link_plugin_EnergyStatistics();
    void
    link_plugin_FractureStatistics();
    void
    link_plugin_ContactColumns();
    void
    link_plugin_WallTime();
    void
    link_plugin_KinematicsOutput();
    void
    link_plugin_BlockForces();

    Frame::~Frame()
    {
      data_out.clear();
    }



    void
    Postprocessor::link_builtin_plugins()
    {
      link_plugin_DisplacementField();
      link_plugin_VelocityField();
      link_plugin_StressFields();
      link_plugin_NodalStressFields();
      link_plugin_BlockAndMaterial();
      link_plugin_CrackFaces();
      link_plugin_TimeStepStatistics();
      link_plugin_EnergyStatistics();
      link_plugin_FractureStatistics();
      link_plugin_ContactColumns();
      link_plugin_WallTime();
      link_plugin_KinematicsOutput();
      link_plugin_BlockForces();
    }



    void
    Postprocessor::declare_parameters(ParameterHandler &)
    {}



    void
    Postprocessor::parse_parameters(ParameterHandler &)
    {}



    void
    Postprocessor::add_fields(const Simulator<2> &, Frame &) const
    {}



    void
    Postprocessor::add_statistics(const Simulator<2> &, StatisticsTable &) const
    {}



    void
    add_scientific(StatisticsTable   &statistics,
                   const std::string &column,
                   const double       value)
    {
      statistics.add_value(column, value);
      statistics.set_scientific(column, true);
      statistics.set_precision(column, 6);
    }



    namespace
    {
      /// The default selection: everything ndda writes, in the order of
      /// the VTU fields and the statistics columns.
      const char *default_list =
        "displacement, velocity, stress, nodal stress, block and material, "
        "crack faces, "
        "kinematics, time step, energy, fracture, contact, block forces";
    } // namespace



  } // namespace postprocess



  namespace parameters
  {
    using namespace dealii;

    void
    Postprocess::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Postprocess");
      {
        prm.declare_entry(
          "List of postprocessors",
          postprocess::default_list,
          Patterns::MultipleSelection(
            postprocess::PostprocessorRegistry::joined_names()),
          postprocess::PostprocessorRegistry::documentation(
            "What a run writes: VTU fields (at every output time) and "
            "groups of columns of the statistics file (after every step), "
            "each a plugin (include/ndda/postprocess/postprocessor.h), in "
            "the order given. Each reads its own entries from the "
            "subsection of its name. The postprocessors:"));
        postprocess::PostprocessorRegistry::declare_parameters(prm);
      }
      prm.leave_subsection();
    }



    void
    Postprocess::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Postprocess");
      {
        names = Utilities::split_string_list(prm.get("List of postprocessors"));
        postprocessors.clear();
        for (const std::string &name : names)
          {
            AssertThrow(std::count(names.begin(), names.end(), name) == 1,
                        ExcMessage("Postprocess/List of postprocessors: '" +
                                   name +
                                   "' is listed twice. Give each "
                                   "postprocessor once."));
            postprocessors.push_back(
              postprocess::PostprocessorRegistry::create_and_parse(name, prm));
          }
      }
      prm.leave_subsection();
    }
  } // namespace parameters
} // namespace ndda
