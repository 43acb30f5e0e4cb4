// SPDX-License-Identifier: GPL-3.0-or-later
//
// The postprocessor 'kinematics': which model moves each block (VTU cell
// field) and how many blocks each model has, with the switches of
// Kinematics = auto (statistics columns).

#include <deal.II/numerics/data_out.h>

#include <ndda/postprocess/postprocessor.h>
#include <ndda/simulator.h>

namespace ndda
{
  namespace postprocess
  {
    using namespace dealii;

    /**
     * For scenes with rigid, affine or auto blocks (nothing for a scene
     * whose blocks are all meshed): the VTU cell field 'kinematics' (the
     * number of unknowns of the cell's block model: 0 meshed, 3 rigid, 6
     * affine) and the statistics columns 'Blocks <model>' for every model
     * in use and, with auto blocks, 'Promotions' and 'Demotions' (so far).
     */
    class KinematicsOutput : public Postprocessor
    {
    public:
      void
      add_fields(const Simulator<2> &simulator, Frame &frame) const override
      {
        const auto &fem = simulator.get_discretization();
        if (fem.all_meshed())
          return;
        const unsigned int n_cells = fem.cell_model.size();
        Vector<double>    &values  = frame.new_cell_vector(n_cells);
        for (unsigned int c = 0; c < n_cells; ++c)
          values[c] = fem.cell_model[c]->n_unknowns();
        frame.data_out.add_data_vector(values,
                                       "kinematics",
                                       DataOut<2>::type_cell_data);
      }

      void
      add_statistics(const Simulator<2> &simulator,
                     StatisticsTable    &statistics) const override
      {
        const auto &fem = simulator.get_discretization();
        if (fem.all_meshed())
          return;
        const auto count = fem.blocks_per_model();
        for (unsigned int m = 0; m < fem.models.size(); ++m)
          statistics.add_value("Blocks " + fem.models[m].first, count[m]);
        const auto &automatic = simulator.get_automatic_kinematics();
        if (!automatic.enabled())
          return;
        statistics.add_value("Promotions", automatic.n_promotions());
        statistics.add_value("Demotions", automatic.n_demotions());
      }
    };



    NDDA_REGISTER_PLUGIN(
      Postprocessor,
      KinematicsOutput,
      "kinematics",
      "For scenes with rigid, affine or auto blocks: the VTU cell field "
      "'kinematics' (unknowns of the cell's block model: 0 meshed, 3 "
      "rigid, 6 affine) and the statistics columns 'Blocks <model>' for "
      "every model in use and, with Kinematics = auto, 'Promotions' and "
      "'Demotions' (so far).")
  } // namespace postprocess
} // namespace ndda
