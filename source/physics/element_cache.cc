// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/fe/fe_values.h>

#include <ndda/physics/element_cache.h>

namespace ndda
{
  template <int dim>
  SymmetricTensor<4, dim>
  elasticity_tensor(const double E, const double nu, const bool plane_strain)
  {
    const double mu     = E / (2. * (1. + nu));
    const double lambda = plane_strain ? E * nu / ((1. + nu) * (1. - 2. * nu)) :
                                         E * nu / (1. - nu * nu);
    SymmetricTensor<4, dim> C;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = 0; l < dim; ++l)
            C[i][j][k][l] = (i == j && k == l ? lambda : 0.) +
                            (i == k && j == l ? mu : 0.) +
                            (i == l && j == k ? mu : 0.);
    return C;
  }



  template <int dim>
  void
  ElementCache<dim>::set_quadratures(const Quadrature<dim> &cell_quadrature,
                                     const Quadrature<dim> &mass_quadrature)
  {
    quadrature            = cell_quadrature;
    this->mass_quadrature = mass_quadrature;
  }



  template <int dim>
  unsigned int
  ElementCache<dim>::update(const DoFHandler<dim>       &dof_handler,
                            const Mapping<dim>          &mapping,
                            const parameters::Materials &materials,
                            const bool                   only_moved_cells,
                            const double                 tolerance)
  {
    const auto        &fe     = dof_handler.get_fe();
    const unsigned int n_dofs = fe.n_dofs_per_cell();
    AssertThrow(quadrature.size() > 0 && mass_quadrature.size() > 0,
                ExcMessage("ElementCache::update(): call set_quadratures() "
                           "with the element's quadratures first."));
    n_q_points = quadrature.size();
    const unsigned int n_cells =
      dof_handler.get_triangulation().n_active_cells();
    if (data.size() != n_cells)
      {
        data.clear();
        data.resize(n_cells);
      }
    elasticity.clear();
    for (const auto &material : materials.materials)
      elasticity.push_back(elasticity_tensor<dim>(material.youngs_modulus,
                                                  material.poissons_ratio,
                                                  materials.plane_strain));

    FEValues<dim>                    fe_values(mapping,
                            fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    FEValues<dim>                    mass_values(mapping,
                              fe,
                              mass_quadrature,
                              update_values | update_JxW_values);
    const FEValuesExtractors::Vector u(0);
    const double                     t = materials.thickness;

    unsigned int n_computed = 0;
    computed_cells.clear();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        CellData &d = data[cell->active_cell_index()];
        if (only_moved_cells && !d.vertices.empty())
          {
            // A translation does not change the element matrices: measure
            // the motion relative to the cell's centroid.
            Tensor<1, dim> shift;
            for (unsigned int v = 0; v < cell->n_vertices(); ++v)
              shift += (cell->vertex(v) - d.vertices[v]) / cell->n_vertices();
            double moved = 0;
            for (unsigned int v = 0; v < cell->n_vertices(); ++v)
              moved =
                std::max(moved,
                         (cell->vertex(v) - d.vertices[v] - shift).norm());
            if (moved <= tolerance * d.diameter)
              continue;
          }
        ++n_computed;
        computed_cells.push_back(cell->active_cell_index());
        fe_values.reinit(cell);
        mass_values.reinit(cell);
        const auto &material = materials.materials[cell->material_id()];
        const auto &C        = elasticity[cell->material_id()];

        d.stiffness.reinit(n_dofs, n_dofs);
        d.mass.reinit(n_dofs, n_dofs);
        d.strain.resize(n_q_points * n_dofs);
        d.spin.resize(n_q_points * n_dofs);
        d.weight.resize(n_q_points);
        d.viscosity_over_density =
          material.density > 0 ? material.viscosity / material.density : 0.;
        double area = 0;
        for (unsigned int q = 0; q < n_q_points; ++q)
          area += fe_values.JxW(q);
        if (d.initial_area == 0)
          d.initial_area = area;
        // Mass is conserved: the current density is rho_0 A_0 / A.
        const double density = material.density * d.initial_area / area;

        for (unsigned int q = 0; q < n_q_points; ++q)
          {
            d.weight[q] = t * fe_values.JxW(q);
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                d.strain[q * n_dofs + i] =
                  fe_values[u].symmetric_gradient(i, q);
                const Tensor<2, dim> grad = fe_values[u].gradient(i, q);
                d.spin[q * n_dofs + i]    = 0.5 * (grad[1][0] - grad[0][1]);
              }
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                const SymmetricTensor<2, dim> Ceps_i =
                  C * d.strain[q * n_dofs + i];
                for (unsigned int j = 0; j < n_dofs; ++j)
                  d.stiffness(i, j) +=
                    (Ceps_i * d.strain[q * n_dofs + j]) * d.weight[q];
              }
          }
        for (unsigned int q = 0; q < mass_quadrature.size(); ++q)
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              const Tensor<1, dim> phi_i = mass_values[u].value(i, q);
              for (unsigned int j = 0; j < n_dofs; ++j)
                d.mass(i, j) += density * t * mass_values.JxW(q) *
                                (phi_i * mass_values[u].value(j, q));
            }
        d.vertices.resize(cell->n_vertices());
        for (unsigned int v = 0; v < cell->n_vertices(); ++v)
          d.vertices[v] = cell->vertex(v);
        d.diameter = cell->diameter();
      }
    return n_computed;
  }



  template SymmetricTensor<4, 2>
  elasticity_tensor<2>(const double, const double, const bool);
  template class ElementCache<2>;
} // namespace ndda
