// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/base/parallel.h>

#include <ndda/physics/rotation.h>
#include <ndda/physics/stress_field.h>

namespace ndda
{



  void
  StressField::initialize(const ElementCache<2>           &element_cache,
                          const DofMap                    &dof_map,
                          const parameters::Materials     &materials,
                          const std::vector<unsigned int> &cell_material,
                          const Triangulation<2>          &triangulation,
                          const OwnedCells                *owned_cells)
  {
    this->element_cache = &element_cache;
    this->dof_map       = &dof_map;
    this->materials     = &materials;
    this->cell_material = &cell_material;
    this->triangulation = &triangulation;
    this->owned_cells   = owned_cells;
  }



  std::pair<unsigned int, unsigned int>
  StressField::owned_range() const
  {
    if (owned_cells == nullptr || !owned_cells->is_split())
      return {0u, n_active_cells};
    owned_cells->check_size(n_active_cells, "StressField");
    return {owned_cells->begin(), owned_cells->end()};
  }



  void
  StressField::reinit(const unsigned int n_cells, const unsigned int n_points)
  {
    n_active_cells = n_cells;
    this->n_points = n_points;
    stress.assign(std::size_t(n_cells) * n_points, Stress());
  }



  std::vector<std::vector<StressField::Stress>>
  StressField::by_cell() const
  {
    std::vector<std::vector<Stress>> cells(n_active_cells);
    for (unsigned int c = 0; c < n_active_cells; ++c)
      cells[c].assign((*this)[c].begin(), (*this)[c].end());
    return cells;
  }



  void
  StressField::set_by_cell(const std::vector<std::vector<Stress>> &cells)
  {
    reinit(cells.size(), cells.empty() ? 0 : cells[0].size());
    for (unsigned int c = 0; c < n_active_cells; ++c)
      {
        AssertThrow(cells[c].size() == n_points,
                    ExcMessage("StressField::set_by_cell(): cell " +
                               std::to_string(c) + " has " +
                               std::to_string(cells[c].size()) +
                               " stresses, cell 0 has " +
                               std::to_string(n_points) + "."));
        std::copy(cells[c].begin(), cells[c].end(), (*this)[c].begin());
      }
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
    const double      *weights   = element_cache->weights_of(c);
    const auto        *dofs      = dof_map->dofs_of_cell(c);
    const Tensor<2, 2> F         = deformation_gradient(c);
    const Tensor<2, 2> F_inverse = invert(F);
    const double       J         = determinant(F);
    const bool         moves     = moves_in(c, d);
    double             rotation = 0, area = 0;
    for (unsigned int q = 0; q < element_cache->n_quadrature_points(); ++q)
      {
        area += J * weights[q];
        if (!moves)
          continue;
        const Tensor<2, 2> G =
          element_cache->field_gradient(c, q, d, dofs) * F_inverse;
        rotation += 0.5 * (G[1][0] - G[0][1]) * J * weights[q];
      }
    return {rotation, area};
  }



  void
  StressField::advance_cell(const unsigned int    c,
                            const Vector<double> &d,
                            const Tensor<2, 2>   &F_inverse,
                            Stress               *sigma) const
  {
    // The element data hold shape gradients on the geometry X they were
    // computed on; F maps it to the step's start geometry x, so the
    // increment's gradient there is (dd/dX) F^-1. Its polar split turns
    // the stress exactly and strains the cell by its stretch only: rigid
    // motion of any size leaves the stress as it was, turned.
    const auto        *dofs     = dof_map->dofs_of_cell(c);
    const unsigned int material = (*cell_material)[c];
    const auto        &law      = element_cache->get_constitutive_law();
    const auto        &C        = element_cache->get_tangents()[material];
    for (unsigned int q = 0; q < n_points; ++q)
      {
        const rotation::StepStrain step = rotation::step_strain(
          element_cache->field_gradient(c, q, d, dofs) * F_inverse);
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
  StressField::advance(const unsigned int    c,
                       const Vector<double> &d,
                       ArrayView<Stress>     sigma) const
  {
    // A cell that does not move keeps its stresses (the law is not
    // asked).
    AssertDimension(sigma.size(), n_points);
    if (moves_in(c, d))
      advance_cell(c, d, invert(deformation_gradient(c)), sigma.data());
  }



  void
  StressField::advance(const Vector<double> &d)
  {
    for (unsigned int c = 0; c < n_active_cells; ++c)
      advance(c, d, (*this)[c]);
  }



  StressField::Stress
  StressField::mean(const unsigned int             cell,
                    const ArrayView<const Stress> &sigma) const
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
    std::vector<Stress> means(n_active_cells);
    for (unsigned int c = 0; c < n_active_cells; ++c)
      means[c] = mean(c);
    return means;
  }



  std::vector<StressField::Stress>
  StressField::trial_cell_means(const Vector<double> &d) const
  {
    std::vector<Stress> means(n_active_cells);
    std::vector<Stress> sigma(n_points);
    for (unsigned int c = 0; c < n_active_cells; ++c)
      {
        std::copy((*this)[c].begin(), (*this)[c].end(), sigma.begin());
        advance(c, d, make_array_view(sigma));
        means[c] = mean(c, make_array_view(std::as_const(sigma)));
      }
    return means;
  }



  std::vector<double>
  StressField::cell_areas() const
  {
    std::vector<double> area(n_active_cells);
    for (unsigned int c = 0; c < n_active_cells; ++c)
      {
        const double *weights = element_cache->weights_of(c);
        for (unsigned int q = 0; q < element_cache->n_quadrature_points(); ++q)
          area[c] += weights[q];
        area[c] *= determinant(deformation_gradient(c));
      }
    return area;
  }



  std::vector<SymmetricTensor<4, 2>>
  StressField::compliances() const
  {
    std::vector<SymmetricTensor<4, 2>> compliance;
    for (const auto &C : element_cache->get_tangents())
      compliance.push_back(invert(C));
    return compliance;
  }



  double
  StressField::cell_force(const unsigned int           c,
                          const Tensor<2, 2>          &F,
                          const Stress                *sigma,
                          const SymmetricTensor<4, 2> &compliance,
                          double                      *local_force) const
  {
    // With the element data's gradients on X and F = dx/dX,
    // int_x (dphi/dx) : sigma = int_X dphi/dX : P, P = det(F) sigma F^-T
    // (the first Piola-Kirchhoff stress), exact however far the cell has
    // turned or moved since its data were computed.
    const unsigned int  n_dofs    = dof_map->dofs_per_cell;
    const unsigned int  n_nodes   = element_cache->n_nodes_per_cell();
    const Tensor<1, 2> *gradients = element_cache->gradients_of(c);
    const auto         &component = element_cache->dof_components();
    const auto         &node      = element_cache->dof_nodes();
    const double       *weights   = element_cache->weights_of(c);
    const auto         &law       = element_cache->get_constitutive_law();
    const auto         &material  = materials->materials[(*cell_material)[c]];
    const double        J         = determinant(F);
    const Tensor<2, 2>  F_inverse_transpose = transpose(invert(F));
    double              energy              = 0;
    for (unsigned int q = 0; q < n_points; ++q)
      {
        const Tensor<2, 2> P =
          (J * weights[q]) * (Tensor<2, 2>(sigma[q]) * F_inverse_transpose);
        // dphi_i/dX : P, with dphi_i/dX the node's gradient in row
        // component[i]: that row of P times it.
        for (unsigned int i = 0; i < n_dofs; ++i)
          local_force[q * n_dofs + i] =
            P[component[i]] * gradients[q * n_nodes + node[i]];
        energy +=
          law.energy_density(material, compliance, sigma[q]) * J * weights[q];
      }
    return energy;
  }



  template <typename CellForce>
  double
  StressField::sum_cell_forces(const CellForce &cell_force_of,
                               Vector<double>  &force) const
  {
    // Each cell's force and energy on deal.II's threads, into arrays of
    // their own (this process's cells, then shared with the others);
    // summed in cell order on one thread: the same sums, in the same
    // order, however many threads and processes there are.
    const unsigned int n_local = n_points * dof_map->dofs_per_cell;
    local_forces.resize(std::size_t(n_active_cells) * n_local);
    local_energies.resize(n_active_cells);
    const auto [first, last] = owned_range();
    parallel::apply_to_subranges(
      first,
      last,
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int c = begin; c < end; ++c)
          local_energies[c] =
            cell_force_of(c, local_forces.data() + std::size_t(c) * n_local);
      },
      cell_grain_size);
    if (owned_cells != nullptr)
      {
        owned_cells->share(local_forces, n_local);
        owned_cells->share(local_energies, 1);
      }
    force         = 0;
    double energy = 0;
    for (unsigned int c = 0; c < n_active_cells; ++c)
      {
        const auto   *dofs  = dof_map->dofs_of_cell(c);
        const double *local = local_forces.data() + std::size_t(c) * n_local;
        for (unsigned int q = 0; q < n_points; ++q)
          for (unsigned int i = 0; i < dof_map->dofs_per_cell; ++i)
            force[dofs[i]] += local[q * dof_map->dofs_per_cell + i];
        energy += local_energies[c];
      }
    return energy;
  }



  double
  StressField::internal_force(Vector<double> &force) const
  {
    // Computed from the stresses every step (not updated by K d), so that
    // it is self-equilibrated in every cell, on the present geometry.
    //
    // The energy is the state function sum t int w(sigma) (w the law's
    // energy density); unlike the accumulated work d . f_int, it does not
    // drift when stresses turn.
    const std::vector<SymmetricTensor<4, 2>> compliance = compliances();
    return sum_cell_forces(
      [&](const unsigned int c, double *local_force) {
        return cell_force(c,
                          deformation_gradient(c),
                          (*this)[c].data(),
                          compliance[(*cell_material)[c]],
                          local_force);
      },
      force);
  }



  double
  StressField::advance_with_internal_force(const Vector<double> &d,
                                           Vector<double>       &force)
  {
    // One pass: each cell's start geometry (the present vertices) for
    // the stress update, its end geometry (the vertices moved by d, in
    // the arithmetic of CrackableMesh::move_vertices()) for the force.
    // A cell writes only its own stresses.
    const std::vector<SymmetricTensor<4, 2>> compliance = compliances();
    const auto  &vertices   = triangulation->get_vertices();
    const auto  &vertex_dof = dof_map->vertex_dofs;
    const double energy     = sum_cell_forces(
      [&](const unsigned int c, double *local_force) {
        const unsigned int *cell_vertices = dof_map->vertices_of_cell(c);
        Stress             *sigma = stress.data() + std::size_t(c) * n_points;
        Tensor<2, 2>        F_end;
        if (moves_in(c, d))
          {
            advance_cell(c, d, invert(deformation_gradient(c)), sigma);
            std::array<Point<2>, 3> x;
            for (unsigned int v = 0; v < 3; ++v)
              {
                const auto &dofs = vertex_dof[cell_vertices[v]];
                x[v]             = vertices[cell_vertices[v]];
                x[v] += Tensor<1, 2>({d[dofs[0]], d[dofs[1]]});
              }
            F_end = element_cache->deformation_gradient(c, x);
          }
        else
          F_end = deformation_gradient(c);
        return cell_force(
          c, F_end, sigma, compliance[(*cell_material)[c]], local_force);
      },
      force);
    if (owned_cells != nullptr)
      owned_cells->share(stress, n_points);
    return energy;
  }
} // namespace ndda
