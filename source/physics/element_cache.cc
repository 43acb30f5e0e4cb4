// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/fe/fe_values.h>

#include <ndda/physics/element_cache.h>

namespace ndda
{
  namespace
  {
    /**
     * Whether @p cell moved by more than @p distance from @p vertices,
     * measured relative to its centroid: a translation does not change the
     * element matrices.
     */
    template <typename CellIterator, int dim>
    bool
    moved_beyond(const CellIterator            &cell,
                 const std::vector<Point<dim>> &vertices,
                 const double                   distance)
    {
      Tensor<1, dim> shift;
      for (unsigned int v = 0; v < cell->n_vertices(); ++v)
        shift += (cell->vertex(v) - vertices[v]) / cell->n_vertices();
      double moved = 0;
      for (unsigned int v = 0; v < cell->n_vertices(); ++v)
        moved = std::max(moved, (cell->vertex(v) - vertices[v] - shift).norm());
      return moved > distance;
    }



    /** Add rho t int N^T N (mass quadrature in @p values) to @p mass. */
    template <int dim>
    void
    add_mass_matrix(const FEValues<dim> &values,
                    const double         density_times_thickness,
                    FullMatrix<double>  &mass)
    {
      const FEValuesExtractors::Vector u(0);
      const unsigned int               n_dofs = mass.m();
      for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
        for (unsigned int i = 0; i < n_dofs; ++i)
          {
            const Tensor<1, dim> phi_i = values[u].value(i, q);
            for (unsigned int j = 0; j < n_dofs; ++j)
              mass(i, j) += density_times_thickness * values.JxW(q) *
                            (phi_i * values[u].value(j, q));
          }
    }


    /** The constitutive law of @p materials (linear elasticity if the
     * materials were built without the parameter file). */
    std::shared_ptr<const ConstitutiveLaw>
    law_of(const parameters::Materials &materials)
    {
      if (materials.constitutive_law != nullptr)
        return materials.constitutive_law;
      return ConstitutiveLawRegistry::create("linear elasticity");
    }


    /**
     * The strain and spin of every shape function, t JxW and the stiffness
     * t int B^T C B at the points of @p values (the cell quadrature), into
     * @p d (sized before).
     */
    template <int dim, typename CellData>
    void
    add_operators(const FEValues<dim>                        &values,
                  const std::vector<SymmetricTensor<4, dim>> &C,
                  const double                                t,
                  CellData                                   &d)
    {
      const FEValuesExtractors::Vector u(0);
      const unsigned int               n_dofs = d.stiffness.m();
      for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
        {
          d.weight[q] = t * values.JxW(q);
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              d.strain[q * n_dofs + i]  = values[u].symmetric_gradient(i, q);
              const Tensor<2, dim> grad = values[u].gradient(i, q);
              d.spin[q * n_dofs + i]    = 0.5 * (grad[1][0] - grad[0][1]);
            }
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              const SymmetricTensor<2, dim> Ceps_i =
                C[q] * d.strain[q * n_dofs + i];
              for (unsigned int j = 0; j < n_dofs; ++j)
                d.stiffness(i, j) +=
                  (Ceps_i * d.strain[q * n_dofs + j]) * d.weight[q];
            }
        }
    }
  } // namespace



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
  ElementCache<dim>::update(
    const DoFHandler<dim>                                   &dof_handler,
    const Mapping<dim>                                      &mapping,
    const parameters::Materials                             &materials,
    const bool                                               only_moved_cells,
    const double                                             tolerance,
    const std::vector<std::vector<SymmetricTensor<2, dim>>> *stresses)
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
    law = law_of(materials);
    tangents.clear();
    for (const auto &material : materials.materials)
      tangents.push_back(law->tangent(material, materials.plane_strain));
    // A tangent that depends on the stress changes wherever the stress
    // does: every cell is computed, with the tangent at each point.
    const bool point_tangents =
      law->tangent_depends_on_stress() && stresses != nullptr;
    std::vector<SymmetricTensor<4, dim>> C(n_q_points);

    FEValues<dim> fe_values(mapping,
                            fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    FEValues<dim> mass_values(mapping,
                              fe,
                              mass_quadrature,
                              update_values | update_JxW_values);
    const double  t = materials.thickness;

    unsigned int n_computed = 0;
    computed_cells.clear();
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        CellData &d = data[cell->active_cell_index()];
        if (only_moved_cells && !point_tangents && !d.vertices.empty() &&
            !moved_beyond(cell, d.vertices, tolerance * d.diameter))
          continue;
        ++n_computed;
        computed_cells.push_back(cell->active_cell_index());
        fe_values.reinit(cell);
        mass_values.reinit(cell);
        const auto        &material = materials.materials[cell->material_id()];
        const unsigned int c        = cell->active_cell_index();
        for (unsigned int q = 0; q < n_q_points; ++q)
          C[q] = point_tangents && !(*stresses)[c].empty() ?
                   law->point_tangent(material,
                                      materials.plane_strain,
                                      (*stresses)[c][q]) :
                   tangents[cell->material_id()];

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

        add_operators(fe_values, C, t, d);
        add_mass_matrix(mass_values, density * t, d.mass);
        d.vertices.resize(cell->n_vertices());
        for (unsigned int v = 0; v < cell->n_vertices(); ++v)
          d.vertices[v] = cell->vertex(v);
        d.diameter = cell->diameter();
      }
    return n_computed;
  }



  template <int dim>
  bool
  ElementCache<dim>::tangent_depends_on_stress(
    const parameters::Materials &materials)
  {
    return law_of(materials)->tangent_depends_on_stress();
  }



  template class ElementCache<2>;
} // namespace ndda
