// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/physics/rotation.h>
#include <ndda/physics/stress_field.h>

namespace ndda
{
  namespace
  {
    /**
     * Each cell's stresses are a heap block of their own, wherever the
     * allocator put it: a loop over all cells would wait for one cache
     * miss per cell. It asks for the block of the cell this many cells
     * ahead of the one it works on.
     */
    constexpr unsigned int prefetch_distance = 8;

    void
    prefetch(const std::vector<std::vector<StressField::Stress>> &stress,
             const unsigned int                                   cell)
    {
      if (cell < stress.size())
        __builtin_prefetch(stress[cell].data());
    }
  } // namespace



  void
  StressField::initialize(const ElementCache<2>           &element_cache,
                          const DofMap                    &dof_map,
                          const parameters::Materials     &materials,
                          const std::vector<unsigned int> &cell_material,
                          const Triangulation<2>          &triangulation)
  {
    this->element_cache = &element_cache;
    this->dof_map       = &dof_map;
    this->materials     = &materials;
    this->cell_material = &cell_material;
    this->triangulation = &triangulation;
  }



  void
  StressField::reinit(const unsigned int n_cells, const unsigned int n_points)
  {
    stress.assign(n_cells, std::vector<Stress>(n_points));
  }



  Tensor<2, 2>
  StressField::deformation_gradient(const unsigned int cell) const
  {
    return element_cache->deformation_gradient(cell,
                                               dof_map->vertices_of_cell(cell),
                                               triangulation->get_vertices());
  }



  bool
  StressField::moves_in(const unsigned int c, const Vector<double> &d) const
  {
    const auto *dofs = dof_map->dofs_of_cell(c);
    for (unsigned int i = 0; i < dof_map->dofs_per_cell; ++i)
      if (d[dofs[i]] != 0.)
        return true;
    return false;
  }



  std::pair<double, double>
  StressField::cell_rotation(const unsigned int    c,
                             const Vector<double> &d) const
  {
    const unsigned int  n_dofs    = dof_map->dofs_per_cell;
    const Tensor<2, 2> *gradients = element_cache->gradients_of(c);
    const double       *weights   = element_cache->weights_of(c);
    const auto         *dofs      = dof_map->dofs_of_cell(c);
    const Tensor<2, 2>  F         = deformation_gradient(c);
    const Tensor<2, 2>  F_inverse = invert(F);
    const double        J         = determinant(F);
    const bool          moves     = moves_in(c, d);
    double              rotation = 0, area = 0;
    for (unsigned int q = 0; q < element_cache->n_quadrature_points(); ++q)
      {
        area += J * weights[q];
        if (!moves)
          continue;
        Tensor<2, 2> gradient;
        for (unsigned int i = 0; i < n_dofs; ++i)
          gradient += d[dofs[i]] * gradients[q * n_dofs + i];
        const Tensor<2, 2> G = gradient * F_inverse;
        rotation += 0.5 * (G[1][0] - G[0][1]) * J * weights[q];
      }
    return {rotation, area};
  }



  void
  StressField::advance(const unsigned int    c,
                       const Vector<double> &d,
                       std::vector<Stress>  &sigma) const
  {
    // The element data hold shape gradients on the geometry X they were
    // computed on; F maps it to the step's start geometry x, so the
    // increment's gradient there is (dd/dX) F^-1. Its polar split turns
    // the stress exactly and strains the cell by its stretch only: rigid
    // motion of any size leaves the stress as it was, turned. A cell
    // that does not move keeps its stresses (the law is not asked).
    if (!moves_in(c, d))
      return;
    const unsigned int  n_dofs    = dof_map->dofs_per_cell;
    const Tensor<2, 2> *gradients = element_cache->gradients_of(c);
    const auto         *dofs      = dof_map->dofs_of_cell(c);
    const unsigned int  material  = (*cell_material)[c];
    const auto         &law       = element_cache->get_constitutive_law();
    const auto         &C         = element_cache->get_tangents()[material];
    const Tensor<2, 2>  F_inverse = invert(deformation_gradient(c));
    for (unsigned int q = 0; q < sigma.size(); ++q)
      {
        Tensor<2, 2> gradient;
        for (unsigned int i = 0; i < n_dofs; ++i)
          gradient += d[dofs[i]] * gradients[q * n_dofs + i];
        const rotation::StepStrain step =
          rotation::step_strain(gradient * F_inverse);
        if (step.sin != 0. || step.cos_minus_one != 0.)
          sigma[q] =
            rotation::turn(sigma[q], 1. + step.cos_minus_one, step.sin);
        law.update_stress(materials->materials[material],
                          C,
                          step.strain,
                          sigma[q]);
      }
  }



  void
  StressField::advance(const Vector<double> &d)
  {
    for (unsigned int c = 0; c < stress.size(); ++c)
      {
        prefetch(stress, c + prefetch_distance);
        advance(c, d, stress[c]);
      }
  }



  StressField::Stress
  StressField::mean(const unsigned int         cell,
                    const std::vector<Stress> &sigma) const
  {
    const double *weights = element_cache->weights_of(cell);
    Stress        mean;
    double        area = 0;
    for (unsigned int q = 0; q < sigma.size(); ++q)
      {
        mean += weights[q] * sigma[q];
        area += weights[q];
      }
    return mean / area;
  }



  std::vector<StressField::Stress>
  StressField::cell_means() const
  {
    std::vector<Stress> means(stress.size());
    for (unsigned int c = 0; c < stress.size(); ++c)
      means[c] = mean(c);
    return means;
  }



  std::vector<StressField::Stress>
  StressField::trial_cell_means(const Vector<double> &d) const
  {
    std::vector<Stress> means(stress.size());
    std::vector<Stress> sigma;
    for (unsigned int c = 0; c < stress.size(); ++c)
      {
        sigma = stress[c];
        advance(c, d, sigma);
        means[c] = mean(c, sigma);
      }
    return means;
  }



  std::vector<double>
  StressField::cell_areas() const
  {
    std::vector<double> area(stress.size());
    for (unsigned int c = 0; c < stress.size(); ++c)
      {
        const double *weights = element_cache->weights_of(c);
        for (unsigned int q = 0; q < element_cache->n_quadrature_points(); ++q)
          area[c] += weights[q];
        area[c] *= determinant(deformation_gradient(c));
      }
    return area;
  }



  double
  StressField::internal_force(Vector<double> &force) const
  {
    // Computed from the stresses every step (not updated by K d), so that
    // it is self-equilibrated in every cell, on the present geometry x:
    // with the element data's gradients on X and F = dx/dX,
    // int_x (dphi/dx) : sigma = int_X dphi/dX : P, P = det(F) sigma F^-T
    // (the first Piola-Kirchhoff stress), exact however far the cell has
    // turned or moved since its data were computed.
    //
    // The energy is the state function sum t int w(sigma) (w the law's
    // energy density); unlike the accumulated work d . f_int, it does not
    // drift when stresses turn.
    force                     = 0;
    const unsigned int n_dofs = dof_map->dofs_per_cell;
    const unsigned int n_q    = element_cache->n_quadrature_points();
    const auto        &law    = element_cache->get_constitutive_law();
    double             energy = 0;
    for (unsigned int c = 0; c < dof_map->n_cells(); ++c)
      {
        prefetch(stress, c + prefetch_distance);
        const Tensor<2, 2> *gradients = element_cache->gradients_of(c);
        const double       *weights   = element_cache->weights_of(c);
        const auto         *dofs      = dof_map->dofs_of_cell(c);
        const unsigned int  material  = (*cell_material)[c];
        const auto         &C         = element_cache->get_tangents()[material];
        const Tensor<2, 2>  F         = deformation_gradient(c);
        const double        J         = determinant(F);
        const Tensor<2, 2>  F_inverse_transpose = transpose(invert(F));
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const auto        &sigma = stress[c][q];
            const Tensor<2, 2> P =
              (J * weights[q]) * (Tensor<2, 2>(sigma) * F_inverse_transpose);
            for (unsigned int i = 0; i < n_dofs; ++i)
              force[dofs[i]] += scalar_product(gradients[q * n_dofs + i], P);
            energy +=
              law.energy_density(materials->materials[material], C, sigma) * J *
              weights[q];
          }
      }
    return energy;
  }
} // namespace ndda
