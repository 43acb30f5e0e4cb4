// SPDX-License-Identifier: GPL-3.0-or-later

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <ndda/postprocess/stress_recovery.h>
#include <ndda/simulator.h>

#include <cmath>

namespace ndda
{
  namespace postprocess
  {
    namespace
    {
      /**
       * The least-squares fit of values at the points of @p from by the
       * complete polynomials of the highest degree m with (m + 1)(m + 2)/2
       * <= its number of points, evaluated at the points of @p to: row r
       * gives the fitted value at point r of @p to from the values at the
       * points of @p from.
       */
      FullMatrix<double>
      fit_to_points(const Quadrature<2> &from, const Quadrature<2> &to)
      {
        unsigned int degree = 0;
        while ((degree + 2) * (degree + 3) / 2 <= from.size())
          ++degree;
        const auto monomials = [degree](const Point<2> &p) {
          std::vector<double> m;
          for (unsigned int total = 0; total <= degree; ++total)
            for (unsigned int i = 0; i <= total; ++i)
              m.push_back(std::pow(p[0], total - i) * std::pow(p[1], i));
          return m;
        };
        const unsigned int n_basis = (degree + 1) * (degree + 2) / 2;
        FullMatrix<double> at_from(from.size(), n_basis);
        for (unsigned int q = 0; q < from.size(); ++q)
          {
            const auto m = monomials(from.point(q));
            for (unsigned int b = 0; b < n_basis; ++b)
              at_from(q, b) = m[b];
          }
        // (A^T A)^-1 A^T: the coefficients from the values.
        FullMatrix<double> normal(n_basis, n_basis);
        at_from.Tmmult(normal, at_from);
        normal.gauss_jordan();
        FullMatrix<double> coefficients(n_basis, from.size());
        normal.mTmult(coefficients, at_from);
        FullMatrix<double> at_to(to.size(), n_basis);
        for (unsigned int r = 0; r < to.size(); ++r)
          {
            const auto m = monomials(to.point(r));
            for (unsigned int b = 0; b < n_basis; ++b)
              at_to(r, b) = m[b];
          }
        FullMatrix<double> result(to.size(), from.size());
        at_to.mmult(result, coefficients);
        return result;
      }
    } // namespace



    void
    StressRecovery::recover(const DoFHandler<2>                    &dofs,
                            const Mapping<2>                       &mapping,
                            const Quadrature<2>                    &quadrature,
                            const Quadrature<2>                    &mass_rule,
                            const std::vector<std::vector<Stress>> &stresses)
    {
      const auto &fe = dofs.get_fe().base_element(0);
      dof_handler.reinit(dofs.get_triangulation());
      dof_handler.distribute_dofs(fe);
      const unsigned int n = dof_handler.n_dofs();
      AssertThrow(stresses.size() == dofs.get_triangulation().n_active_cells(),
                  ExcMessage("StressRecovery: the stresses are not those of "
                             "the mesh's cells."));

      DynamicSparsityPattern pattern(n, n);
      DoFTools::make_sparsity_pattern(dof_handler, pattern);
      SparsityPattern sparsity;
      sparsity.copy_from(pattern);
      SparseMatrix<double> mass(sparsity);
      for (auto &c : components)
        c.reinit(n);
      std::array<Vector<double>, 3> rhs;
      for (auto &r : rhs)
        r.reinit(n);

      // The stress of a cell is known at the points of the cell
      // quadrature only; between them it is the polynomial of the highest
      // complete degree those points determine (a constant for P1's one
      // point, the linear stress of P2 from its three), fitted by least
      // squares in the unit cell (the mapping is affine), and integrated
      // with the mass quadrature: a stress of that degree is then
      // projected exactly. to_mass_points(r, q) gives the fitted value at
      // mass point r from the value at stress point q.
      const FullMatrix<double> to_mass_points =
        fit_to_points(quadrature, mass_rule);

      FEValues<2>                          values(mapping,
                         fe,
                         mass_rule,
                         update_values | update_JxW_values);
      const unsigned int                   n_local = fe.n_dofs_per_cell();
      const unsigned int                   n_mass  = mass_rule.size();
      FullMatrix<double>                   cell_mass(n_local, n_local);
      std::vector<types::global_dof_index> local(n_local);
      std::vector<Stress>                  sigma_r(n_mass);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          const auto &sigma = stresses[cell->active_cell_index()];
          AssertThrow(sigma.size() == quadrature.size(),
                      ExcMessage("StressRecovery: a cell's stresses are not "
                                 "at the points of the cell quadrature."));
          for (unsigned int r = 0; r < n_mass; ++r)
            {
              sigma_r[r] = Stress();
              for (unsigned int q = 0; q < sigma.size(); ++q)
                sigma_r[r] += to_mass_points(r, q) * sigma[q];
            }
          values.reinit(cell);
          cell->get_dof_indices(local);
          cell_mass = 0;
          for (unsigned int r = 0; r < n_mass; ++r)
            for (unsigned int i = 0; i < n_local; ++i)
              {
                const double w = values.shape_value(i, r) * values.JxW(r);
                for (unsigned int j = 0; j < n_local; ++j)
                  cell_mass(i, j) += w * values.shape_value(j, r);
                rhs[0](local[i]) += w * sigma_r[r][0][0];
                rhs[1](local[i]) += w * sigma_r[r][1][1];
                rhs[2](local[i]) += w * sigma_r[r][0][1];
              }
          mass.add(local, cell_mass);
        }

      PreconditionJacobi<SparseMatrix<double>> jacobi;
      jacobi.initialize(mass);
      iterations = 0;
      for (unsigned int k = 0; k < 3; ++k)
        {
          const double norm = rhs[k].l2_norm();
          if (norm == 0.)
            continue;
          SolverControl            control(1000, 1e-13 * norm);
          SolverCG<Vector<double>> cg(control);
          cg.solve(mass, components[k], rhs[k], jacobi);
          iterations = std::max(iterations, control.last_step());
        }
    }



    void
    StressRecovery::recover(const Simulator<2> &simulator)
    {
      const auto &cache = simulator.get_discretization().element_cache;
      recover(simulator.get_dof_handler(),
              simulator.get_mapping(),
              cache.get_quadrature(),
              cache.get_mass_quadrature(),
              simulator.get_stresses().cells());
    }



    StressRecovery::Stress
    StressRecovery::at_dof(const types::global_dof_index i) const
    {
      Stress s;
      s[0][0] = components[0](i);
      s[1][1] = components[1](i);
      s[0][1] = components[2](i);
      return s;
    }



    StressRecovery::Stress
    StressRecovery::at_vertex(const DoFHandler<2>::active_cell_iterator &cell,
                              const unsigned int v) const
    {
      const typename DoFHandler<2>::active_cell_iterator own(
        &dof_handler.get_triangulation(),
        cell->level(),
        cell->index(),
        &dof_handler);
      return at_dof(own->vertex_dof_index(v, 0));
    }
  } // namespace postprocess
} // namespace ndda
