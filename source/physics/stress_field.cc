// SPDX-License-Identifier: GPL-3.0-or-later

#include <ndda/physics/stress_field.h>

#include <cmath>

namespace ndda
{
  namespace
  {
    /** cos and sin of a small angle, by series where that is exact. */
    std::pair<double, double>
    cos_sin(const double omega)
    {
      if (std::abs(omega) > 1e-2)
        return {std::cos(omega), std::sin(omega)};
      // Truncation below 1e-15 for |omega| <= 1e-2.
      const double w2 = omega * omega;
      return {1. - w2 / 2. * (1. - w2 / 12. * (1. - w2 / 30.)),
              omega * (1. - w2 / 6. * (1. - w2 / 20.))};
    }

    /** Rotate the 2D vector stored at dofs (i, j) by the angle omega. */
    void
    rotate_pair(Vector<double>               &v,
                const types::global_dof_index i,
                const types::global_dof_index j,
                const double                  c,
                const double                  s)
    {
      const double x = v[i], y = v[j];
      v[i] = c * x - s * y;
      v[j] = s * x + c * y;
    }
  } // namespace



  void
  StressField::initialize(const ElementCache<2>           &element_cache,
                          const DofMap                    &dof_map,
                          const parameters::Materials     &materials,
                          const std::vector<unsigned int> &cell_material,
                          const bool                       rotate_with_spin)
  {
    this->element_cache    = &element_cache;
    this->dof_map          = &dof_map;
    this->materials        = &materials;
    this->cell_material    = &cell_material;
    this->rotate_with_spin = rotate_with_spin;
  }



  void
  StressField::reinit(const unsigned int n_cells, const unsigned int n_points)
  {
    stress.assign(n_cells, std::vector<Stress>(n_points));
  }



  std::pair<double, double>
  StressField::cell_rotation(const unsigned int    c,
                             const Vector<double> &d) const
  {
    const unsigned int n_dofs = dof_map->dofs_per_cell;
    const auto        &data   = (*element_cache)[c];
    const auto        *dofs   = dof_map->dofs_of_cell(c);
    double             omega = 0, area = 0;
    for (unsigned int q = 0; q < element_cache->n_quadrature_points(); ++q)
      {
        for (unsigned int i = 0; i < n_dofs; ++i)
          omega += d[dofs[i]] * data.spin[q * n_dofs + i] * data.weight[q];
        area += data.weight[q];
      }
    return {omega, area};
  }



  void
  StressField::advance(const unsigned int    c,
                       const Vector<double> &d,
                       std::vector<Stress>  &sigma) const
  {
    // The small-rotation update moves points along straight lines; turn
    // each cell's stress by the cell's rotation in the increment
    // (Jaumann-like, sigma <- R sigma R^T) before the law adds the
    // increment's stress. See doc/theory.md.
    if (rotate_with_spin)
      {
        const auto [rotation, area] = cell_rotation(c, d);
        const double omega          = rotation / area;
        if (omega != 0.)
          {
            const auto [cs, sn] = cos_sin(omega);
            for (auto &s : sigma)
              {
                const double xx = s[0][0], yy = s[1][1], xy = s[0][1];
                s[0][0] = cs * cs * xx - 2 * cs * sn * xy + sn * sn * yy;
                s[1][1] = sn * sn * xx + 2 * cs * sn * xy + cs * cs * yy;
                s[0][1] = cs * sn * (xx - yy) + (cs * cs - sn * sn) * xy;
              }
          }
      }
    const unsigned int n_dofs   = dof_map->dofs_per_cell;
    const auto        &data     = (*element_cache)[c];
    const auto        *dofs     = dof_map->dofs_of_cell(c);
    const unsigned int material = (*cell_material)[c];
    const auto        &law      = element_cache->get_constitutive_law();
    const auto        &C        = element_cache->get_tangents()[material];
    for (unsigned int q = 0; q < sigma.size(); ++q)
      {
        Stress eps;
        for (unsigned int i = 0; i < n_dofs; ++i)
          eps += d[dofs[i]] * data.strain[q * n_dofs + i];
        law.update_stress(materials->materials[material], C, eps, sigma[q]);
      }
  }



  void
  StressField::advance(const Vector<double> &d)
  {
    for (unsigned int c = 0; c < stress.size(); ++c)
      advance(c, d, stress[c]);
  }



  StressField::Stress
  StressField::mean(const unsigned int         cell,
                    const std::vector<Stress> &sigma) const
  {
    const auto &data = (*element_cache)[cell];
    Stress      mean;
    double      area = 0;
    for (unsigned int q = 0; q < sigma.size(); ++q)
      {
        mean += data.weight[q] * sigma[q];
        area += data.weight[q];
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
      for (const double w : (*element_cache)[c].weight)
        area[c] += w;
    return area;
  }



  double
  StressField::internal_force(Vector<double> &force) const
  {
    // Computed from the stresses every step (not updated by K d and
    // turned with the spin), so that it is self-equilibrated in every
    // cell: turning nodal forces by nodal spins that differ from node to
    // node would leave a net force on a free, vibrating block.
    //
    // The energy is the state function sum t int w(sigma) (w the law's
    // energy density); unlike the accumulated work d . f_int, it does not
    // drift when stresses are turned with the spin.
    force                     = 0;
    const unsigned int n_dofs = dof_map->dofs_per_cell;
    const unsigned int n_q    = element_cache->n_quadrature_points();
    const auto        &law    = element_cache->get_constitutive_law();
    double             energy = 0;
    for (unsigned int c = 0; c < dof_map->n_cells(); ++c)
      {
        const auto        &data     = (*element_cache)[c];
        const auto        *dofs     = dof_map->dofs_of_cell(c);
        const unsigned int material = (*cell_material)[c];
        const auto        &C        = element_cache->get_tangents()[material];
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const auto &sigma = stress[c][q];
            for (unsigned int i = 0; i < n_dofs; ++i)
              force[dofs[i]] +=
                (data.strain[q * n_dofs + i] * sigma) * data.weight[q];
            energy +=
              law.energy_density(materials->materials[material], C, sigma) *
              data.weight[q];
          }
      }
    return energy;
  }



  void
  rotate_block_motion(const CrackableMesh        &mesh,
                      const DofMap               &dof_map,
                      const StressField          &stresses,
                      const SparseMatrix<double> &mass,
                      const Vector<double>       &d,
                      Vector<double>             &velocity,
                      Vector<double>             &inertia_force)
  {
    // As DDA does with its block rotation, turn the velocity (and inertia
    // force) of each block relative to its centre of mass by the block's
    // rotation in the increment. Only the part relative to the centre of
    // mass turns: a block that falls while it vibrates (its spin
    // oscillating) keeps its momentum, where turning whole nodal
    // velocities by nodal spins made it drift sideways by metres.
    const unsigned int        n_dofs   = dof_map.dofs_per_cell;
    const unsigned int        n_blocks = mesh.n_blocks();
    const unsigned int        n_nodes  = dof_map.node_dofs.size();
    std::vector<double>       block_spin(n_blocks), block_area(n_blocks);
    std::vector<unsigned int> node_block(n_nodes,
                                         numbers::invalid_unsigned_int);
    for (unsigned int c = 0; c < dof_map.n_cells(); ++c)
      {
        const auto [omega, area] = stresses.cell_rotation(c, d);
        const unsigned int b     = mesh.block_of_cell(c);
        block_spin[b] += omega;
        block_area[b] += area;
        const auto *dofs = dof_map.dofs_of_cell(c);
        for (unsigned int i = 0; i < n_dofs; ++i)
          node_block[dof_map.dof_to_node[dofs[i]]] = b;
      }

    // Centre-of-mass velocity and acceleration of each block, with the
    // row sums of the mass matrix as nodal masses (1^T M v is the momentum
    // for the consistent mass too).
    std::vector<double>       block_mass(n_blocks);
    std::vector<Tensor<1, 2>> block_velocity(n_blocks), block_force(n_blocks);
    std::vector<double>       node_mass(n_nodes);
    for (unsigned int n = 0; n < n_nodes; ++n)
      {
        const unsigned int b = node_block[n];
        if (b == numbers::invalid_unsigned_int)
          continue;
        double m = 0;
        for (auto entry = mass.begin(dof_map.node_dofs[n][0]);
             entry != mass.end(dof_map.node_dofs[n][0]);
             ++entry)
          m += entry->value();
        node_mass[n] = m;
        block_mass[b] += m;
        for (unsigned int k = 0; k < 2; ++k)
          {
            block_velocity[b][k] += m * velocity[dof_map.node_dofs[n][k]];
            block_force[b][k] += inertia_force[dof_map.node_dofs[n][k]];
          }
      }
    for (unsigned int b = 0; b < n_blocks; ++b)
      if (block_mass[b] > 0.)
        {
          block_velocity[b] /= block_mass[b];
          block_force[b] /= block_mass[b]; // per unit mass
          block_spin[b] /= block_area[b];
        }

    for (unsigned int n = 0; n < n_nodes; ++n)
      {
        const unsigned int b = node_block[n];
        if (b == numbers::invalid_unsigned_int || block_spin[b] == 0. ||
            block_mass[b] <= 0.)
          continue;
        const auto [cs, sn] = cos_sin(block_spin[b]);
        const auto [i, j]   = dof_map.node_dofs[n];
        for (unsigned int k = 0; k < 2; ++k)
          {
            velocity[dof_map.node_dofs[n][k]] -= block_velocity[b][k];
            inertia_force[dof_map.node_dofs[n][k]] -=
              node_mass[n] * block_force[b][k];
          }
        rotate_pair(velocity, i, j, cs, sn);
        rotate_pair(inertia_force, i, j, cs, sn);
        for (unsigned int k = 0; k < 2; ++k)
          {
            velocity[dof_map.node_dofs[n][k]] += block_velocity[b][k];
            inertia_force[dof_map.node_dofs[n][k]] +=
              node_mass[n] * block_force[b][k];
          }
      }
  }
} // namespace ndda
