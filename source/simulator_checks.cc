// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Simulator's guard against values that are not finite (issue 17): a
// step whose forces or solved increment hold NaN or inf stops the run with
// a message that names the step, the time, the quantity, the node and its
// block.

#include <ndda/base/utilities.h>
#include <ndda/simulator.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ndda
{
  template <int dim>
  void
  Simulator<dim>::require_finite(const Vector<double> &v,
                                 const double          dt,
                                 const std::string    &quantity,
                                 const std::string    &hint) const
  {
    if (std::isfinite(v.l1_norm()))
      return;
    unsigned int bad = 0;
    while (bad < v.size() && std::isfinite(v[bad]))
      ++bad;
    std::ostringstream message;
    message << "Step " << step_number + 1 << " at t = " << time
            << " s (dt = " << dt << " s): " << quantity << " is not finite";
    if (bad < v.size())
      {
        const unsigned int node = fem.dof_map.dof_to_node[bad];
        message << " (" << (std::isnan(v[bad]) ? "nan" : "inf") << " in the "
                << (fem.dof_map.node_dofs[node][0] == bad ? "x" : "y")
                << " component";
        // The node: a vertex of the mesh where it is one, and its block.
        const auto  &vertex_dofs = fem.dof_map.vertex_dofs;
        unsigned int vertex      = numbers::invalid_unsigned_int;
        for (unsigned int i = 0; i < vertex_dofs.size(); ++i)
          if (vertex_dofs[i][0] == bad || vertex_dofs[i][1] == bad)
            vertex = i;
        if (vertex != numbers::invalid_unsigned_int)
          message << " at the vertex "
                  << to_string(mesh.get_block_mesh().vertices[vertex]);
        for (unsigned int c = 0; c < fem.dof_map.n_cells(); ++c)
          {
            const auto *dofs = fem.dof_map.dofs_of_cell(c);
            if (std::find(dofs, dofs + fem.dof_map.dofs_per_cell, bad) !=
                dofs + fem.dof_map.dofs_per_cell)
              {
                message << " of block '"
                        << mesh.get_block_names()[mesh.block_of_cell(c)] << "'";
                break;
              }
          }
        message << ")";
      }
    message << ". " << hint
            << " The output up to the last completed step is kept.";
    AssertThrow(false, ExcMessage(message.str()));
  }



  template void
  Simulator<2>::require_finite(const Vector<double> &,
                               const double,
                               const std::string &,
                               const std::string &) const;
} // namespace ndda
