// SPDX-License-Identifier: GPL-3.0-or-later
//
// The postprocessor 'block forces': the resultant contact force on chosen
// blocks after every step (a loading plate's load, the thrust on a
// retaining block), statistics columns.

#include <ndda/postprocess/block_forces.h>
#include <ndda/postprocess/postprocessor.h>
#include <ndda/simulator.h>

#include <algorithm>

namespace ndda
{
  namespace postprocess
  {
    using namespace dealii;

    Tensor<1, 2>
    contact_force_on_block(const Simulator<2> &simulator,
                           const unsigned int  block)
    {
      const Vector<double> &force = simulator.get_contacts().end_forces();
      Tensor<1, 2>          sum;
      if (force.size() == 0)
        return sum;
      const auto                          &mesh = simulator.get_mesh();
      const auto                          &dofs = simulator.get_dof_handler();
      std::vector<bool>                    counted(force.size(), false);
      std::vector<types::global_dof_index> cell_dofs(
        dofs.get_fe().n_dofs_per_cell());
      for (const auto &cell : dofs.active_cell_iterators())
        {
          if (mesh.block_of_cell(cell->active_cell_index()) != block)
            continue;
          cell->get_dof_indices(cell_dofs);
          for (unsigned int i = 0; i < cell_dofs.size(); ++i)
            if (!counted[cell_dofs[i]])
              {
                counted[cell_dofs[i]] = true;
                sum[dofs.get_fe().system_to_component_index(i).first] +=
                  force[cell_dofs[i]];
              }
        }
      return sum;
    }



    /**
     * The statistics columns '<block> contact force x (N)' and '... y (N)'
     * for every block of `Blocks`: the sum of the contact forces on the
     * block's nodes at the end of the step (the springs of its contacts on
     * the step's end geometry), times the thickness as every force of
     * ndda. For a plate pressed on a specimen it is the load the specimen
     * carries, whatever the plate's kinematics (a rigid plate has no
     * stress to read it from).
     */
    class BlockForces : public Postprocessor
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry(
          "Blocks",
          "",
          Patterns::List(Patterns::Anything()),
          "The blocks (Geometry/Blocks names, or '<region>.<n>') whose "
          "resultant contact force is written, two statistics columns "
          "each: '<block> contact force x (N)' and '... y (N)'. Empty: "
          "none.");
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        blocks = Utilities::split_string_list(prm.get("Blocks"));
      }

      void
      add_statistics(const Simulator<2> &simulator,
                     StatisticsTable    &statistics) const override
      {
        const auto &names = simulator.get_mesh().get_block_names();
        for (const std::string &name : blocks)
          {
            const auto b = std::find(names.begin(), names.end(), name);
            AssertThrow(b != names.end(),
                        ExcMessage("Postprocess/block forces/Blocks: the "
                                   "scene has no block '" +
                                   name + "'."));
            const Tensor<1, 2> f =
              simulator.get_parameters().contact.enabled ?
                contact_force_on_block(simulator, b - names.begin()) :
                Tensor<1, 2>();
            add_scientific(statistics, name + " contact force x (N)", f[0]);
            add_scientific(statistics, name + " contact force y (N)", f[1]);
          }
      }

    private:
      std::vector<std::string> blocks;
    };



    NDDA_REGISTER_PLUGIN(
      Postprocessor,
      BlockForces,
      "block forces",
      "The resultant contact force on each block of 'Blocks' at the end "
      "of every step: statistics columns '<block> contact force x (N)' "
      "and '... y (N)' (the load on a loading plate, rigid or not).")
  } // namespace postprocess
} // namespace ndda
