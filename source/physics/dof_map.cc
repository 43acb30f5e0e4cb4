// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/numbers.h>

#include <ndda/physics/dof_map.h>

#include <algorithm>
#include <cmath>

namespace ndda
{
  void
  DofMap::reinit(const dealii::DoFHandler<2> &dof_handler)
  {
    const auto &fe = dof_handler.get_fe();
    this->fe       = &fe;
    n_dofs         = dof_handler.n_dofs();
    dofs_per_cell  = fe.n_dofs_per_cell();
    cell_dofs.resize(dof_handler.get_triangulation().n_active_cells() *
                     dofs_per_cell);
    vertices_per_cell = dof_handler.get_triangulation().n_active_cells() > 0 ?
                          dof_handler.begin_active()->n_vertices() :
                          0;
    cell_vertices.resize(dof_handler.get_triangulation().n_active_cells() *
                         vertices_per_cell);
    local_component.resize(dofs_per_cell);
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      local_component[i] = fe.system_to_component_index(i).first;
    vertex_dofs.resize(dof_handler.get_triangulation().n_vertices());
    dof_to_node.assign(n_dofs, dealii::numbers::invalid_unsigned_int);
    node_dofs.clear();
    std::vector<index> dofs(dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        std::copy(dofs.begin(),
                  dofs.end(),
                  cell_dofs.begin() +
                    cell->active_cell_index() * dofs_per_cell);
        for (unsigned int v = 0; v < cell->n_vertices(); ++v)
          cell_vertices[cell->active_cell_index() * vertices_per_cell + v] =
            cell->vertex_index(v);
        for (unsigned int v = 0; v < cell->n_vertices(); ++v)
          for (unsigned int c = 0; c < 2; ++c)
            vertex_dofs[cell->vertex_index(v)][c] =
              cell->vertex_dof_index(v, c);
        // A node is numbered when its x dof is first met; its y dof is the
        // dof of component 1 at the same support point.
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            const auto [component, base] = fe.system_to_component_index(i);
            if (component == 0 &&
                dof_to_node[dofs[i]] == dealii::numbers::invalid_unsigned_int)
              {
                const auto j = dofs[fe.component_to_system_index(1, base)];
                dof_to_node[dofs[i]] = dof_to_node[j] = node_dofs.size();
                node_dofs.push_back({{dofs[i], j}});
              }
          }
      }
  }



  std::vector<dealii::Tensor<1, 2>>
  DofMap::vertex_values(const dealii::Vector<double> &v) const
  {
    std::vector<dealii::Tensor<1, 2>> values(vertex_dofs.size());
    for (unsigned int i = 0; i < vertex_dofs.size(); ++i)
      for (unsigned int c = 0; c < 2; ++c)
        values[i][c] = v[vertex_dofs[i][c]];
    return values;
  }



  double
  DofMap::max_vertex_norm(const dealii::Vector<double> &v) const
  {
    double max_square = 0;
    for (const auto &dofs : vertex_dofs)
      max_square =
        std::max(max_square, v[dofs[0]] * v[dofs[0]] + v[dofs[1]] * v[dofs[1]]);
    return std::sqrt(max_square);
  }
} // namespace ndda
